// Both languages are complete: every message of the interface (lupdate's .ts files, kept up
// to date from the sources) has a translation, finished, with the same placeholders (%1, %n
// ...) and HTML tags as its source, and shortcuts translated to themselves; Portuguese
// plurals have both forms.
#include <QtTest>

#include <QFile>
#include <QRegularExpression>
#include <QXmlStreamReader>

#include <set>

#include "tests/test_support.h"

namespace {

struct Message {
    QString context, source;
    QStringList translations;  // one, or the plural forms
    bool unfinished = false;
    bool obsolete = false;
    bool numerus = false;
};

std::vector<Message> readTs(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    QXmlStreamReader xml(&file);
    std::vector<Message> out;
    QString context;
    Message m;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement()) continue;
        const auto name = xml.name();
        if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            m = Message{};
            m.context = context;
            m.numerus = xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
        } else if (name == QLatin1String("source")) {
            m.source = xml.readElementText();
        } else if (name == QLatin1String("translation")) {
            const auto type = xml.attributes().value(QLatin1String("type"));
            m.unfinished = type == QLatin1String("unfinished");
            m.obsolete = type == QLatin1String("vanished") || type == QLatin1String("obsolete");
            if (m.numerus) {
                while (xml.readNextStartElement())
                    if (xml.name() == QLatin1String("numerusform"))
                        m.translations << xml.readElementText();
            } else {
                m.translations << xml.readElementText();
            }
            out.push_back(m);
        }
    }
    return out;
}

std::multiset<QString> tokens(const QString& text) {
    static const QRegularExpression re(
        QStringLiteral("%L?\\d|%n|</?[a-zA-Z][a-zA-Z0-9]*|&[a-z]+;"));
    std::multiset<QString> out;
    for (auto it = re.globalMatch(text); it.hasNext();) out.insert(it.next().captured());
    return out;
}

}  // namespace

class TestTranslations : public QObject {
    Q_OBJECT
private slots:
    void complete_data() {
        QTest::addColumn<QString>("language");
        QTest::newRow("pt_BR") << QStringLiteral("pt_BR");
        QTest::newRow("en") << QStringLiteral("en");
    }

    void complete() {
        QFETCH(QString, language);
        const auto messages = readTs(testing::sourceDir() + QStringLiteral("/translations/rasterlab_") +
                                     language + QStringLiteral(".ts"));
        QVERIFY(messages.size() > 600);
        int live = 0;
        for (const Message& m : messages) {
            if (m.obsolete) continue;
            ++live;
            const QString where = m.context + QStringLiteral(": ") + m.source;
            QVERIFY2(!m.unfinished, qPrintable(QStringLiteral("unfinished: ") + where));
            QVERIFY2(!m.translations.isEmpty(), qPrintable(where));
            if (m.numerus && language == QLatin1String("pt_BR"))
                QVERIFY2(m.translations.size() == 2, qPrintable(QStringLiteral("plural forms: ") + where));
            for (const QString& t : m.translations) {
                QVERIFY2(!t.isEmpty(), qPrintable(QStringLiteral("empty: ") + where));
                QVERIFY2(tokens(t) == tokens(m.source),
                         qPrintable(QStringLiteral("placeholders or tags differ: ") + where +
                                    QStringLiteral(" -> ") + t));
                static const QRegularExpression shortcut(
                    QStringLiteral("^(Ctrl|Alt|Shift|F\\d+)(\\+[A-Za-z0-9+-]+)?$"));
                if (shortcut.match(m.source).hasMatch())
                    QCOMPARE(t, m.source);
            }
        }
        QVERIFY(live > 600);
    }
};

QTEST_GUILESS_MAIN(TestTranslations)
#include "tst_translations.moc"
