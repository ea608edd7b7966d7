// The interface in one language: our strings (the installed .qm files, or else the copies
// embedded in the window's library under ":/i18n": install_paths.h) and Qt's own (its dialogs
// and buttons), for "" (the system's language), "en" or "pt_BR". Installed again when the user
// picks another language.
#pragma once

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

#include "app/install_paths.h"

namespace rasterlab {

class Translators {
public:
    void install(const QString& language) {
        QCoreApplication::removeTranslator(&m_qt);
        QCoreApplication::removeTranslator(&m_ours);
        const QLocale locale = language.isEmpty() ? QLocale() : QLocale(language);
        QLocale::setDefault(locale);
        if (m_qt.load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                      QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
            QCoreApplication::installTranslator(&m_qt);
        if (m_ours.load(locale, QStringLiteral("rasterlab"), QStringLiteral("_"),
                        translationsDir()))
            QCoreApplication::installTranslator(&m_ours);
    }

private:
    QTranslator m_qt;
    QTranslator m_ours;
};

}  // namespace rasterlab
