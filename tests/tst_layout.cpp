// The source tree shows the architecture: every include of a project header names its path
// from the source root (a .cpp's own header aside), no include goes up a layer
// (pipeline <- views <- app; inside the pipeline, base <- stages <- fast <- render and
// analysis), the two programs in app/ include nothing of each other, and app/ keeps at most
// four sources at its top.
#include <QtTest>

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include "tests/test_support.h"

namespace {

struct Include {
    QString file;  // from the source root
    int line = 0;
    QString target;  // as written between the quotes
};

QList<Include> scanIncludes() {
    const QDir root(testing::sourceDir());
    static const QRegularExpression quoted(QStringLiteral("^\\s*#\\s*include\\s+\"([^\"]+)\""));
    QList<Include> includes;
    for (const QString& top : {QStringLiteral("app"), QStringLiteral("views"),
                              QStringLiteral("pipeline"), QStringLiteral("tests")}) {
        QDirIterator it(root.filePath(top), {QStringLiteral("*.cpp"), QStringLiteral("*.h")},
                        QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            QFile file(path);
            if (!file.open(QIODevice::ReadOnly)) continue;
            int number = 0;
            while (!file.atEnd()) {
                ++number;
                const auto match = quoted.match(QString::fromUtf8(file.readLine()));
                if (match.hasMatch())
                    includes.append({root.relativeFilePath(path), number, match.captured(1)});
            }
        }
    }
    return includes;
}

// The tree is read once for all the tests.
const QList<Include>& projectIncludes() {
    static const QList<Include> includes = scanIncludes();
    return includes;
}

// The layer a file or an include belongs to: pipeline/<folder>, views/messages, views,
// app/cli, app/window, app (what both programs share) or tests.
QString layerOf(const QString& path) {
    const QStringList parts = path.split(QLatin1Char('/'));
    const QString& top = parts.first();
    if (top == QLatin1String("pipeline")) return top + QLatin1Char('/') + parts.value(1);
    if (top == QLatin1String("views"))
        return parts.value(1) == QLatin1String("messages") ? QStringLiteral("views/messages")
                                                             : top;
    if (top == QLatin1String("app")) {
        const QString second = parts.value(1);
        if (second == QLatin1String("cli") || second == QLatin1String("window"))
            return top + QLatin1Char('/') + second;
        return top;
    }
    return top;
}

// Which layers each layer may include; a layer may always include itself.
bool mayInclude(const QString& from, const QString& to) {
    if (from == to) return true;
    const QStringList base = {QStringLiteral("pipeline/core"), QStringLiteral("pipeline/scene"),
                              QStringLiteral("pipeline/io")};
    const QStringList pipeline = base + QStringList{QStringLiteral("pipeline/stages"),
                                                    QStringLiteral("pipeline/fast"),
                                                    QStringLiteral("pipeline/render"),
                                                    QStringLiteral("pipeline/analysis")};
    if (from == QLatin1String("pipeline/core")) return false;
    if (from == QLatin1String("pipeline/scene")) return to == QLatin1String("pipeline/core");
    if (from == QLatin1String("pipeline/io"))
        return to == QLatin1String("pipeline/core") || to == QLatin1String("pipeline/scene");
    if (from == QLatin1String("pipeline/stages")) return base.contains(to);
    if (from == QLatin1String("pipeline/fast"))
        return base.contains(to) || to == QLatin1String("pipeline/stages");
    if (from == QLatin1String("pipeline/render") || from == QLatin1String("pipeline/analysis"))
        return pipeline.contains(to);
    if (from == QLatin1String("views/messages")) return pipeline.contains(to);
    if (from == QLatin1String("views"))
        return pipeline.contains(to) || to == QLatin1String("views/messages");
    const bool belowApp = pipeline.contains(to) || to.startsWith(QLatin1String("views"));
    if (from == QLatin1String("app")) return belowApp;
    if (from == QLatin1String("app/cli") || from == QLatin1String("app/window"))
        return belowApp || to == QLatin1String("app");
    return from == QLatin1String("tests");
}

}  // namespace

class TestLayout : public QObject {
    Q_OBJECT

private slots:
    void everyIncludeNamesItsPath() {
        const QDir root(testing::sourceDir());
        QStringList bare;
        int named = 0;
        for (const Include& include : projectIncludes()) {
            if (include.target.endsWith(QLatin1String(".moc"))) continue;  // generated
            if (include.target.contains(QLatin1Char('/'))) {
                ++named;
                if (!QFileInfo::exists(root.filePath(include.target)))
                    bare << QStringLiteral("%1:%2: no such file %3")
                                .arg(include.file)
                                .arg(include.line)
                                .arg(include.target);
                continue;
            }
            // A .cpp includes its own header by its bare name.
            const QFileInfo info(include.file);
            const bool ownHeader = info.suffix() == QLatin1String("cpp") &&
                                   include.target == info.completeBaseName() + QStringLiteral(".h");
            if (!ownHeader)
                bare << QStringLiteral("%1:%2: bare include \"%3\"")
                            .arg(include.file)
                            .arg(include.line)
                            .arg(include.target);
        }
        QVERIFY2(bare.isEmpty(), qPrintable(bare.join(QLatin1Char('\n'))));
        QVERIFY2(named > 500, qPrintable(QStringLiteral("only %1 includes found").arg(named)));
    }

    void noIncludeGoesUpALayer() {
        QStringList wrong;
        for (const Include& include : projectIncludes()) {
            if (!include.target.contains(QLatin1Char('/'))) continue;
            const QString from = layerOf(include.file);
            const QString to = layerOf(include.target);
            if (!mayInclude(from, to))
                wrong << QStringLiteral("%1:%2: %3 includes %4 (%5)")
                             .arg(include.file)
                             .arg(include.line)
                             .arg(from, to, include.target);
        }
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(QLatin1Char('\n'))));
    }

    // The rule itself, on cases written by hand.
    void theLayersAreOrdered() {
        QVERIFY(mayInclude(QStringLiteral("pipeline/fast"), QStringLiteral("pipeline/stages")));
        QVERIFY(!mayInclude(QStringLiteral("pipeline/stages"), QStringLiteral("pipeline/fast")));
        QVERIFY(!mayInclude(QStringLiteral("pipeline/stages"), QStringLiteral("pipeline/render")));
        QVERIFY(!mayInclude(QStringLiteral("pipeline/core"), QStringLiteral("pipeline/scene")));
        QVERIFY(!mayInclude(QStringLiteral("pipeline/render"), QStringLiteral("views")));
        QVERIFY(!mayInclude(QStringLiteral("views"), QStringLiteral("app")));
        QVERIFY(!mayInclude(QStringLiteral("views/messages"), QStringLiteral("views")));
        QVERIFY(!mayInclude(QStringLiteral("app/cli"), QStringLiteral("app/window")));
        QVERIFY(!mayInclude(QStringLiteral("app/window"), QStringLiteral("app/cli")));
        QVERIFY(!mayInclude(QStringLiteral("app"), QStringLiteral("app/window")));
        QVERIFY(mayInclude(QStringLiteral("app/window"), QStringLiteral("views/messages")));
        QCOMPARE(layerOf(QStringLiteral("app/documents/lesson_file.h")), QStringLiteral("app"));
        QCOMPARE(layerOf(QStringLiteral("views/messages/pipeline_messages.h")),
                 QStringLiteral("views/messages"));
    }

    void appKeepsAtMostFourSourcesAtItsTop() {
        const QDir app(QDir(testing::sourceDir()).filePath(QStringLiteral("app")));
        const QStringList sources =
            app.entryList({QStringLiteral("*.cpp"), QStringLiteral("*.h")}, QDir::Files);
        QVERIFY2(sources.size() <= 4, qPrintable(sources.join(QStringLiteral(", "))));
    }
};

QTEST_GUILESS_MAIN(TestLayout)
#include "tst_layout.moc"
