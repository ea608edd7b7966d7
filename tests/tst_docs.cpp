// The documents stay true to the source: every function the reading guide names with a file
// and a line is defined on that line, and every link and image of the README and of docs/
// points at a file that exists.
#include <QtTest>

#include <QDir>
#include <QFile>
#include <QRegularExpression>

#include "test_support.h"

namespace {

QString read(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(file.readAll());
}

QStringList markdownFiles() {
    const QDir root(testing::sourceDir());
    QStringList files = {root.filePath(QStringLiteral("README.md")),
                         root.filePath(QStringLiteral("CONTRIBUTING.md"))};
    for (const QString& name :
         QDir(root.filePath(QStringLiteral("docs"))).entryList({QStringLiteral("*.md")}))
        files << root.filePath(QStringLiteral("docs/") + name);
    return files;
}

}  // namespace

class TestDocs : public QObject {
    Q_OBJECT

private slots:
    void readingGuideNamesTheRightLines_data() {
        QTest::addColumn<QString>("guide");
        QTest::newRow("en") << QStringLiteral("docs/reading-order.md");
        QTest::newRow("pt_BR") << QStringLiteral("docs/reading-order.pt_BR.md");
    }

    void readingGuideNamesTheRightLines() {
        // "`FrameLighting::flatSample` (pipeline/stages/shading.cpp:172)": that line of that
        // file defines flatSample.
        QFETCH(QString, guide);
        const QDir root(testing::sourceDir());
        const QString text = read(root.filePath(guide));
        QVERIFY2(!text.isEmpty(), qPrintable(guide));
        static const QRegularExpression reference(
            QStringLiteral("`([A-Za-z_:~]+)` \\(([\\w/.]+):(\\d+)\\)"));
        int checked = 0;
        for (auto it = reference.globalMatch(text); it.hasNext();) {
            const auto m = it.next();
            const QString name = m.captured(1).section(QStringLiteral("::"), -1);
            const QStringList lines = read(root.filePath(m.captured(2))).split(QLatin1Char('\n'));
            const int line = m.captured(3).toInt();
            QVERIFY2(line >= 1 && line <= lines.size(), qPrintable(m.captured(0)));
            const QString at = lines[line - 1];
            QVERIFY2(at.contains(name + QLatin1Char('(')),
                     qPrintable(QStringLiteral("%1: line %2 reads '%3'")
                                    .arg(m.captured(0))
                                    .arg(line)
                                    .arg(at.trimmed())));
            ++checked;
        }
        QVERIFY2(checked >= 20, qPrintable(QString::number(checked)));
    }

    void linksPointAtFiles() {
        // Relative links and images, [text](path) and ![text](path), of every document.
        static const QRegularExpression link(QStringLiteral("!?\\[[^\\]]*\\]\\(([^)\\s#]+)"));
        int checked = 0;
        for (const QString& file : markdownFiles()) {
            const QString text = read(file);
            QVERIFY2(!text.isEmpty(), qPrintable(file));
            const QDir here = QFileInfo(file).dir();
            for (auto it = link.globalMatch(text); it.hasNext();) {
                const QString target = it.next().captured(1);
                if (target.contains(QLatin1String("://")) ||
                    target.startsWith(QLatin1String("mailto:")))
                    continue;
                QVERIFY2(QFileInfo::exists(here.filePath(target)),
                         qPrintable(
                             QStringLiteral("%1 links to %2, which does not exist")
                                 .arg(QDir(testing::sourceDir()).relativeFilePath(file), target)));
                ++checked;
            }
        }
        QVERIFY(checked > 50);
    }
};

QTEST_GUILESS_MAIN(TestDocs)
#include "tst_docs.moc"
