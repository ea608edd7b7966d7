// What an installed RasterLab relies on: the lookup of its own files relative to its
// executable (install_paths.h), `--version` in both programs, the window opening a file given
// on its command line (as the desktop entry's `Exec=rasterlab %f` does), and the About box.
#include <QAction>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "app/install_paths.h"
#include "app/window/main_window.h"
#include "tests/test_support.h"

using rasterlab::MainWindow;

namespace {

void touch(const QString& path) {
    QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("# RasterLab\n");
}

struct GuiRun {
    int exitCode = -1;
    QString out;
    QString err;
};

// Runs the window program offscreen, with settings of its own in `home`, and waits for it
// (at most 120 s).
GuiRun runGui(const QStringList& arguments, const QString& home,
              const QString& platform = QStringLiteral("offscreen")) {
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), platform);
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), home);
    process.setProcessEnvironment(env);
    process.start(QStringLiteral(RASTERLAB_GUI_PATH), arguments);
    GuiRun run;
    if (!process.waitForFinished(120000) || process.exitStatus() != QProcess::NormalExit) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.exitCode = process.exitCode();
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

}  // namespace

class TestInstall : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        QFile bad(m_dir.filePath(QStringLiteral("bad.rasterlab")));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{ \"rasterlab_lesson\": 1, \"scene\": ");
    }

    // An installed layout under any prefix: bin/, share/rasterlab/, share/doc/rasterlab/.
    void findsFilesRelativeToItsPrefix() {
        QTemporaryDir prefix;
        QVERIFY(prefix.isValid());
        const QString bin = prefix.filePath(QStringLiteral("usr/bin"));
        QVERIFY(QDir().mkpath(bin));
        QCOMPARE(rasterlab::dataDir(bin), QString());
        QCOMPARE(rasterlab::docDir(bin), QString());
        QCOMPARE(rasterlab::userGuide(QStringLiteral("en"), bin), QString());
        QCOMPARE(rasterlab::translationsDir(bin), QStringLiteral(":/i18n"));

        const QString doc = prefix.filePath(QStringLiteral("usr/share/doc/rasterlab"));
        touch(doc + QStringLiteral("/guide.en.md"));
        QVERIFY(QDir().mkpath(prefix.filePath(QStringLiteral("usr/share/rasterlab/lessons"))));
        QCOMPARE(rasterlab::dataDir(bin), prefix.filePath(QStringLiteral("usr/share/rasterlab")));
        QCOMPARE(rasterlab::docDir(bin), doc);
        // No Portuguese guide yet: English for every language.
        QCOMPARE(rasterlab::userGuide(QStringLiteral("pt_BR"), bin),
                 doc + QStringLiteral("/guide.en.md"));
        touch(doc + QStringLiteral("/guide.pt_BR.md"));
        QCOMPARE(rasterlab::userGuide(QStringLiteral("pt_BR"), bin),
                 doc + QStringLiteral("/guide.pt_BR.md"));
        QCOMPARE(rasterlab::userGuide(QStringLiteral("pt_BR.UTF-8"), bin),
                 doc + QStringLiteral("/guide.pt_BR.md"));
        QCOMPARE(rasterlab::userGuide(QStringLiteral("pt-PT"), bin),
                 doc + QStringLiteral("/guide.pt_BR.md"));
        QCOMPARE(rasterlab::userGuide(QStringLiteral("de_DE"), bin),
                 doc + QStringLiteral("/guide.en.md"));
        QCOMPARE(rasterlab::userGuide(QStringLiteral("en_GB"), bin),
                 doc + QStringLiteral("/guide.en.md"));

        // Installed translations are preferred to the embedded ones.
        QVERIFY(QDir().mkpath(prefix.filePath(QStringLiteral("usr/share/rasterlab/translations"))));
        QCOMPARE(rasterlab::translationsDir(bin),
                 prefix.filePath(QStringLiteral("usr/share/rasterlab/translations")));
    }

    // The build folder mirrors the installed layout: the tests (build/tests) and the programs
    // (build/bin) find the guides and the lessons of the source tree.
    void buildTreeMirrorsTheLayout() {
        const QString data = rasterlab::dataDir();
        QVERIFY2(!data.isEmpty(), "no share/rasterlab beside the build's programs");
        QVERIFY(QFileInfo::exists(data + QStringLiteral("/lessons/goblet/goblet.rasterlab")));
        const QString guide = rasterlab::userGuide(QStringLiteral("pt_BR"));
        QVERIFY2(guide.endsWith(QStringLiteral("/guide.pt_BR.md")), qPrintable(guide));
        QCOMPARE(QFile(guide).size(),
                 QFile(testing::sourceDir() + QStringLiteral("/docs/guide.pt_BR.md")).size());
        QVERIFY(QFileInfo::exists(rasterlab::docDir() + QStringLiteral("/copyright")));
    }

    void cliPrintsItsVersion() {
        testing::CliRun run;
        QVERIFY2(testing::runCli({QStringLiteral("--version")}, QDir::tempPath(), run),
                 qPrintable(run.problem));
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(run.out, QStringLiteral("rasterlab-cli " RASTERLAB_VERSION "\n"));
    }

    // Also without a display (a terminal over ssh): xcb with no DISPLAY would abort a window.
    void windowPrintsItsVersion_data() {
        QTest::addColumn<QString>("platform");
        QTest::addColumn<QString>("option");
        QTest::newRow("offscreen") << QStringLiteral("offscreen") << QStringLiteral("--version");
        QTest::newRow("no display") << QStringLiteral("xcb") << QStringLiteral("--version");
        QTest::newRow("-v") << QStringLiteral("xcb") << QStringLiteral("-v");
    }
    void windowPrintsItsVersion() {
        QFETCH(QString, platform);
        QFETCH(QString, option);
        const GuiRun run = runGui({option}, m_dir.path(), platform);
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(run.out, QStringLiteral("RasterLab " RASTERLAB_VERSION "\n"));
    }

    // `rasterlab FILE` as the desktop entry runs it: a lesson file and a Movie.BYU object open;
    // a file that cannot be read fails --quit-after's status.
    void windowOpensFileArguments_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("exitCode");
        const QString lessons = testing::sourceDir() + QStringLiteral("/resources/lessons/");
        QTest::newRow("lesson") << lessons + QStringLiteral("goblet/goblet.rasterlab") << 0;
        QTest::newRow("byu") << lessons + QStringLiteral("triangle/triangle.byu") << 0;
        QTest::newRow("missing") << QStringLiteral("/nonexistent/none.byu") << 1;
        QTest::newRow("bad lesson") << m_dir.filePath(QStringLiteral("bad.rasterlab")) << 1;
    }
    void windowOpensFileArguments() {
        QFETCH(QString, file);
        QFETCH(int, exitCode);
        const GuiRun run =
            runGui({QStringLiteral("--quit-after"), QStringLiteral("300"), file}, m_dir.path());
        QVERIFY2(run.exitCode == exitCode,
                 qPrintable(QStringLiteral("exit %1, stderr: %2").arg(run.exitCode).arg(run.err)));
    }

    void windowRejectsABadQuitAfter() {
        QCOMPARE(
            runGui({QStringLiteral("--quit-after"), QStringLiteral("soon")}, m_dir.path()).exitCode,
            2);
    }

    // --language: en or pt_BR for the session; anything else is a wrong command line.
    void windowTakesALanguage() {
        const GuiRun wrong =
            runGui({QStringLiteral("--language"), QStringLiteral("fr")}, m_dir.path());
        QCOMPARE(wrong.exitCode, 2);
        QVERIFY2(wrong.err.contains(QStringLiteral("--language expects en or pt_BR, found 'fr'")),
                 qPrintable(wrong.err));
        for (const char* language : {"en", "pt_BR"})
            QCOMPARE(runGui({QStringLiteral("--language"), QLatin1String(language),
                             QStringLiteral("--quit-after"), QStringLiteral("200")},
                            m_dir.path())
                         .exitCode,
                     0);
    }

    void aboutNamesVersionLicenceAndCourses() {
        const QString text = MainWindow::aboutText();
        QVERIFY(text.contains(QStringLiteral(RASTERLAB_VERSION)));
        QVERIFY(text.contains(QStringLiteral("MIT License")));
        QVERIFY(text.contains(QStringLiteral("UFPE")));
        QVERIFY(text.contains(QStringLiteral("HW2: 3D Rasterizer")));
        QVERIFY(text.contains(QStringLiteral("Jonh Edson R. de Carvalho")));
        // The build folder has the copyright file the package installs: the box names it.
        QVERIFY(text.contains(QStringLiteral("/copyright")));
    }

    void helpOpensTheUserGuide() {
        MainWindow window;
        auto* guide = window.findChild<QAction*>(QStringLiteral("userGuideAction"));
        QVERIFY(guide);
        QVERIFY(guide->isEnabled());
        QVERIFY2(guide->data().toString().endsWith(QStringLiteral(".md")),
                 qPrintable(guide->data().toString()));
        QVERIFY(QFileInfo(guide->data().toString()).isFile());
    }
};

QTEST_MAIN(TestInstall)
#include "tst_install.moc"
