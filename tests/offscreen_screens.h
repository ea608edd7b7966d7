// Screens of chosen sizes for Qt's offscreen platform, whose own screen is 800x800: a
// window fits itself to its screen, and presentation mode sizes its text and places its
// docks by it. Call before the QApplication is made; `dir` keeps the configuration file.
#pragma once

#include <QFile>
#include <QSize>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <initializer_list>

// Side by side, from x = 0; only when the platform asked for is "offscreen". False when the
// configuration cannot be written.
inline bool useOffscreenScreens(const QTemporaryDir& dir, std::initializer_list<QSize> sizes) {
    if (qgetenv("QT_QPA_PLATFORM") != "offscreen") return true;
    QStringList screens;
    int x = 0;
    for (const QSize& size : sizes) {
        screens << QStringLiteral(
                       R"({"name": "%1x%2", "x": %3, "y": 0, "width": %1, "height": %2})")
                       .arg(size.width())
                       .arg(size.height())
                       .arg(x);
        x += size.width();
    }
    const QString config = dir.filePath(QStringLiteral("screens.json"));
    QFile file(config);
    if (!file.open(QIODevice::WriteOnly)) return false;
    file.write(
        QStringLiteral(R"({"screens": [%1]})").arg(screens.join(QStringLiteral(", "))).toUtf8());
    file.close();
    qputenv("QT_QPA_PLATFORM", "offscreen:configfile=" + config.toLocal8Bit());
    return true;
}
