// The documents stay true to the source: the README is at most 200 lines and names the package
// of the project's version, every function the reading guide names with a file
// and a line is defined on that line, every link and image of the README and of docs/ points
// at a file that exists, every picture in docs/images is shown by some document, and the
// user guides need no file outside the repository (the course's own files are named only in
// a paragraph marked as being about them).
#include <QtTest>

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>

#include "tests/test_support.h"

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
    // The README is for users and stays short: detail goes to docs/.
    void readmeIsShort() {
        const QString text = read(QDir(testing::sourceDir()).filePath(QStringLiteral("README.md")));
        const qsizetype lines = text.count(QLatin1Char('\n'));
        QVERIFY2(lines > 50 && lines <= 200, qPrintable(QString::number(lines)));
    }

    // The package the README says to install is the one scripts/package.sh builds: named with
    // the project's version (CMakeLists.txt).
    void readmeNamesThePackageOfThisVersion() {
        const QDir root(testing::sourceDir());
        static const QRegularExpression version(
            QStringLiteral("project\\(RasterLab\\s+VERSION\\s+(\\S+)"));
        const auto project = version.match(read(root.filePath(QStringLiteral("CMakeLists.txt"))));
        QVERIFY(project.hasMatch());
        static const QRegularExpression deb(QStringLiteral("rasterlab_([^_\\s]+)_amd64\\.deb"));
        const QString readme = read(root.filePath(QStringLiteral("README.md")));
        int named = 0;
        for (auto it = deb.globalMatch(readme); it.hasNext(); ++named)
            QCOMPARE(it.next().captured(1), project.captured(1));
        QVERIFY(named >= 1);
    }

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

    void everyPictureIsShown() {
        // A picture in docs/images that no document shows is a leftover of an older build.
        QString all;
        for (const QString& file : markdownFiles()) all += read(file);
        const QDir images(QDir(testing::sourceDir()).filePath(QStringLiteral("docs/images")));
        int checked = 0;
        QDirIterator it(images.path(), {QStringLiteral("*.png")}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString relative = images.relativeFilePath(it.next());
            QVERIFY2(all.contains(QStringLiteral("images/") + relative),
                     qPrintable(QStringLiteral("docs/images/%1 is shown by no document")
                                    .arg(relative)));
            ++checked;
        }
        QVERIFY(checked > 20);
    }

    void guidesNeedNoCourseFiles_data() {
        QTest::addColumn<QString>("guide");
        QTest::addColumn<QString>("marker");
        QTest::newRow("en") << QStringLiteral("docs/guide.en.md")
                            << QStringLiteral("> **Course files.**");
        QTest::newRow("pt_BR") << QStringLiteral("docs/guide.pt_BR.md")
                               << QStringLiteral("> **Arquivos do curso.**");
    }

    void guidesNeedNoCourseFiles() {
        // The guides' examples use the shipped lessons and docs/examples, so a fresh clone can
        // follow them. The course's files (calice2, iluminacao.txt, the HW2 samples in
        // ../shared/samples) may be named only in a paragraph that starts with the marker,
        // which says they are not in the repository.
        QFETCH(QString, guide);
        QFETCH(QString, marker);
        const QString text = read(QDir(testing::sourceDir()).filePath(guide));
        QVERIFY2(!text.isEmpty(), qPrintable(guide));
        static const QRegularExpression course(
            QStringLiteral("\\.\\./shared|/samples/|calice2|iluminacao|hw2[a-z0-9]+\\.txt"),
            QRegularExpression::CaseInsensitiveOption);
        static const QRegularExpression blank(QStringLiteral("\\n\\s*\\n"));
        int marked = 0;
        for (const QString& paragraph : text.split(blank)) {
            const QRegularExpressionMatch m = course.match(paragraph);
            if (!m.hasMatch()) continue;
            QVERIFY2(paragraph.trimmed().startsWith(marker),
                     qPrintable(QStringLiteral("%1 names the course's file '%2' outside a "
                                               "paragraph starting with '%3': %4")
                                    .arg(guide, m.captured(0), marker,
                                         paragraph.trimmed().left(160))));
            ++marked;
        }
        QVERIFY2(marked <= 1, qPrintable(QStringLiteral("%1: %2 marked paragraphs; one says it")
                                             .arg(guide)
                                             .arg(marked)));
    }
};

QTEST_GUILESS_MAIN(TestDocs)
#include "tst_docs.moc"
