// The pipeline's messages in the user's language: every template written in the sources
// ("..."_msg, pipeline/core/message.h) is in the app's catalogue for lupdate and translated
// into both languages, the pipeline writes no text that escapes translation, a translated
// message keeps the English one's arguments and its file:line:col, the window shows it so, and
// the command line stays English.
#include <QtTest>

#include <QDirIterator>
#include <QFile>
#include <QListWidget>
#include <QRegularExpression>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTranslator>

#include <set>

#include "app/window/main_window.h"
#include "app/window/translators.h"
#include "pipeline/io/course_readers.h"
#include "tests/test_support.h"
#include "views/messages/pipeline_messages.h"

using rasterlab::translated;

namespace {

// Adjacent string literals ("a" "b"), joined as the compiler joins them, with the suffix of
// the last one ("_msg") and the identifier just before the first ("operator").
struct Literal {
    QString text;
    QString suffix;
    QString before;
    int line = 0;
};

struct SourceScan {
    std::vector<Literal> literals;
    std::vector<int> untranslatedLiterals;  // lines where untranslated( ... ) holds a literal
};

bool isIdentifierChar(QChar c) {
    return c.isLetterOrNumber() || c == u'_';
}

// The literal that starts at text[i], its escapes resolved; i is left on its closing quote.
QString readLiteral(const QString& text, qsizetype& i) {
    QString s;
    for (++i; text[i] != u'"'; ++i) {
        if (text[i] != u'\\') {
            s += text[i];
            continue;
        }
        const QChar e = text[++i];
        s += e == u'n' ? QChar(u'\n') : e == u't' ? QChar(u'\t') : e;
    }
    return s;
}

// A small C++ lexer: skips comments and character literals, joins adjacent string literals,
// and notes the literals inside the parentheses of untranslated( ... ).
SourceScan scan(const QString& text) {
    SourceScan out;
    QString identifier;         // the identifier just read
    bool afterLiteral = false;  // only spaces and comments since the last literal
    int depth = 0;              // parentheses open in an untranslated( call
    int line = 1;
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (c == u'\n') ++line;
        if (c.isSpace()) continue;
        if (text.mid(i, 2) == u"//") {
            while (i + 1 < text.size() && text[i + 1] != u'\n') ++i;
            continue;
        }
        if (text.mid(i, 2) == u"/*") {
            const qsizetype end = text.indexOf(u"*/", i + 2);
            line += int(text.mid(i, end - i).count(u'\n'));
            i = end + 1;
            continue;
        }
        if (c == u'"') {
            const QString s = readLiteral(text, i);
            QString suffix;
            while (i + 1 < text.size() && isIdentifierChar(text[i + 1])) suffix += text[++i];
            if (afterLiteral && out.literals.back().suffix.isEmpty()) {
                out.literals.back().text += s;
                out.literals.back().suffix = suffix;
            } else {
                out.literals.push_back({s, suffix, identifier, line});
            }
            if (depth > 0) out.untranslatedLiterals.push_back(line);
            afterLiteral = true;
            identifier.clear();
            continue;
        }
        afterLiteral = false;
        const bool digitSeparator = i > 0 && text[i - 1].isDigit() && i + 1 < text.size() &&
                                    text[i + 1].isLetterOrNumber();  // 1'000
        if (c == u'\'' && !digitSeparator) {
            for (++i; text[i] != u'\''; ++i)
                if (text[i] == u'\\') ++i;
        } else if (isIdentifierChar(c)) {
            if (i == 0 || !isIdentifierChar(text[i - 1])) identifier.clear();
            identifier += c;
            continue;
        } else if (c == u'(') {
            if (depth > 0 || identifier == u"untranslated") ++depth;
        } else if (c == u')') {
            if (depth > 0) --depth;
        }
        identifier.clear();
    }
    return out;
}

// The C++ sources under a folder of the repository, by path relative to the repository.
std::vector<QString> sourcesIn(const QString& folder) {
    std::vector<QString> out;
    const QString root = testing::sourceDir() + u'/';
    QDirIterator it(root + folder, {QStringLiteral("*.cpp"), QStringLiteral("*.h")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext()) out.push_back(it.next().mid(root.size()));
    std::sort(out.begin(), out.end());
    return out;
}

SourceScan scanFile(const QString& path) {
    return scan(QString::fromUtf8(testing::readFile(testing::sourceDir() + u'/' + path)));
}

// Every template written in pipeline/ and app/, with where.
std::map<QString, QString> templatesInSources() {
    std::map<QString, QString> out;
    std::vector<QString> files = sourcesIn(QStringLiteral("pipeline"));
    for (const QString& f : sourcesIn(QStringLiteral("app"))) files.push_back(f);
    for (const QString& path : files)
        for (const Literal& l : scanFile(path).literals)
            if (l.suffix == u"_msg" && l.before != u"operator")
                out.emplace(l.text, path + u':' + QString::number(l.line));
    return out;
}

std::set<QString> catalogue() {
    std::set<QString> out;
    for (const char* t : rasterlab::messageCatalogue()) out.insert(QString::fromUtf8(t));
    return out;
}

// The line to paste into views/messages/pipeline_messages.cpp for a template.
QString catalogueLine(QString text) {
    text.replace(u'\\', QStringLiteral("\\\\")).replace(u'"', QStringLiteral("\\\""));
    return QStringLiteral("    QT_TRANSLATE_NOOP(\"Messages\", \"%1\"),").arg(text);
}

// Writes `content` to `name` in `dir`; returns the absolute path, or "" on failure.
QString writeFixture(const QTemporaryDir& dir, const QString& name, const QByteArray& content) {
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size()) return {};
    return path;
}

// A command file with a letter where a number goes: "xyz 1 b 3", the b at column 7.
const QByteArray kBadCommandFile = "png 8 8 out.png\nxyz 1 b 3\n";

// The placeholders of a text: "%1", "%2" ...
std::multiset<QString> placeholders(const QString& text) {
    static const QRegularExpression re(QStringLiteral("%\\d"));
    std::multiset<QString> out;
    for (auto it = re.globalMatch(text); it.hasNext();) out.insert(it.next().captured());
    return out;
}

}  // namespace

class TestPipelineMessages : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void catalogueListsEveryTemplate();
    void pipelineWritesOnlyTemplates();
    void everyTemplateIsTranslated_data();
    void everyTemplateIsTranslated();
    void untranslatedIsEnglish();
    void portugueseReaderMessages();
    void windowShowsPortuguese();
    void commandLineStaysEnglish();

private:
    QTemporaryDir m_settings;
};

void TestPipelineMessages::initTestCase() {
    // Settings of our own, in a folder that goes away (the window keeps its recent files).
    QCoreApplication::setOrganizationName(QStringLiteral("RasterLabTest"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_pipeline_messages"));
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
}

// A template written in the sources and missing from the catalogue would stay English in the
// window (lupdate never sees it); one the sources no longer write is dead weight in the .ts.
void TestPipelineMessages::catalogueListsEveryTemplate() {
    const std::map<QString, QString> sources = templatesInSources();
    const std::set<QString> listed = catalogue();
    QVERIFY(sources.size() > 250);
    QStringList missing, stale;
    for (const auto& [text, where] : sources)
        if (!listed.count(text)) missing << where + u'\n' + catalogueLine(text);
    for (const QString& text : listed)
        if (!sources.count(text)) stale << catalogueLine(text);
    QVERIFY2(missing.isEmpty(),
             qPrintable(QStringLiteral("templates missing from views/messages/pipeline_messages.cpp:\n") +
                        missing.join(u'\n')));
    QVERIFY2(stale.isEmpty(), qPrintable(QStringLiteral("templates no source writes, in "
                                                        "views/messages/pipeline_messages.cpp:\n") +
                                         stale.join(u'\n')));
    QCOMPARE(qsizetype(rasterlab::messageCatalogue().size()), qsizetype(listed.size()));
}

// Text the pipeline wraps with Message::untranslated is shown as it is in every language:
// names, numbers and tokens from the files, never a sentence written in the source.
void TestPipelineMessages::pipelineWritesOnlyTemplates() {
    int calls = 0;
    for (const QString& path : sourcesIn(QStringLiteral("pipeline"))) {
        if (path.startsWith(u"pipeline/core/message.")) continue;
        const QString text =
            QString::fromUtf8(testing::readFile(testing::sourceDir() + u'/' + path));
        calls += int(text.count(QStringLiteral("untranslated(")));
        const SourceScan s = scan(text);
        QVERIFY2(
            s.untranslatedLiterals.empty(),
            qPrintable(
                QStringLiteral("%1:%2: text written in the source must be a "
                               "template (\"...\"_msg), not untranslated")
                    .arg(path)
                    .arg(s.untranslatedLiterals.empty() ? 0 : s.untranslatedLiterals.front())));
    }
    QVERIFY(calls > 0);  // the scan looked at the calls there are

    // The scan itself: adjacent literals are one, comments and character literals are skipped.
    const SourceScan sample = scan(
        QStringLiteral("f(\"a \" /* \"x\" */ \"b %1\"_msg(n), '\"', \"c\"); // \"d\"_msg\n"
                       "g(Message::untranslated(std::string(\"e\") + s), \"f\"\n  \"g\"_msg);"));
    QCOMPARE(sample.literals.size(), std::size_t(4));
    QCOMPARE(sample.literals[0].text, QStringLiteral("a b %1"));
    QCOMPARE(sample.literals[0].suffix, QStringLiteral("_msg"));
    QCOMPARE(sample.literals[3].text, QStringLiteral("fg"));
    QCOMPARE(sample.literals[3].line, 2);
    QCOMPARE(sample.untranslatedLiterals, std::vector<int>{2});
}

void TestPipelineMessages::everyTemplateIsTranslated_data() {
    QTest::addColumn<QString>("language");
    QTest::newRow("pt_BR") << QStringLiteral("pt_BR");
    QTest::newRow("en") << QStringLiteral("en");
}

// In the compiled translations the window loads: each template has a translation with the
// same placeholders, so a template added to the catalogue without one fails here.
void TestPipelineMessages::everyTemplateIsTranslated() {
    QFETCH(QString, language);
    QTranslator translator;
    QVERIFY(translator.load(QStringLiteral(":/i18n/rasterlab_") + language));
    QStringList untranslated;
    std::vector<const char*> templates(rasterlab::messageCatalogue().begin(),
                                       rasterlab::messageCatalogue().end());
    for (const char* t : {"%1: %2", "%1: warning: %2", "%1: note: %2"}) templates.push_back(t);
    for (const char* t : templates) {
        const QString translation = translator.translate("Messages", t);
        if (translation.isEmpty()) untranslated << QString::fromUtf8(t);
        QVERIFY2(translation.isEmpty() || placeholders(translation) == placeholders(t),
                 qPrintable(QString::fromUtf8(t) + QStringLiteral(" -> ") + translation));
    }
    QVERIFY2(untranslated.isEmpty(),
             qPrintable(QStringLiteral("no translation (run the target update_translations and "
                                       "translate):\n") +
                        untranslated.join(u'\n')));
}

// Without a translator, the window shows exactly what the command line prints.
void TestPipelineMessages::untranslatedIsEnglish() {
    const char* const cameras[] = {
        "0 0 0\n0 a 1\n0 1 0\n1 1 1\n",
        "0 0 0\n0 0 1\n0 1 0\n1 1,5 1\n",
        "0 0 0\n0 0 1\n0 1 0\n",
        "C = 0 0 0\nN = 0 0 1\nV = 0 1 0\nd = 1\n",
        "0 0 0\n0 0 1 7 8\n0 1 0\n1 1 1\nx\ny\n",
        "1 2\n",
    };
    int errors = 0, diagnostics = 0;
    for (const char* text : cameras) {
        for (rl::CameraLayout layout : rl::kCameraLayouts) {
            rl::Diagnostics d;
            auto camera = rl::readCameraFile(text, "cam.cfg", d, layout);
            if (!camera) {
                QCOMPARE(translated(camera.error()),
                         QString::fromStdString(camera.error().toString()));
                ++errors;
            }
            for (const rl::Diagnostic& item : d.items()) {
                QCOMPARE(translated(item), QString::fromStdString(item.toString()));
                ++diagnostics;
            }
        }
    }
    QVERIFY(errors > 10);
    QVERIFY(diagnostics > 5);
}

// In Portuguese: the template translated, its arguments (translated in turn, or as written in
// the file) in place, the file:line:col in front.
void TestPipelineMessages::portugueseReaderMessages() {
    rasterlab::Translators translators;
    translators.install(QStringLiteral("pt_BR"));
    rl::Diagnostics d;
    auto camera = rl::readCameraFile("0 0 0\n0 a 1\n0 1 0\n1 1 1\n", "cam.cfg", d);
    QVERIFY(!camera);
    QCOMPARE(QString::fromStdString(camera.error().toString()),
             QStringLiteral("cam.cfg:2:3: expected a number for N, found 'a'"));
    QCOMPARE(translated(camera.error()),
             QStringLiteral("cam.cfg:2:3: esperava um número para N, encontrou 'a'"));
    // A token that looks like a placeholder is shown as written.
    camera = rl::readCameraFile("0 0 0\n0 0 1\n0 1 0\n1 %2 1,5\n", "cam.cfg", d);
    QVERIFY(!camera);
    QCOMPARE(translated(camera.error()),
             QStringLiteral("cam.cfg:4:3: esperava um número para d hx hy, encontrou '%2'"));
    // Nested pieces: the hint, and the counted words.
    camera = rl::readCameraFile("0 0 0\n0 0 1\n0 1 0\n1 1,5 1\n", "cam.cfg", d);
    QCOMPARE(translated(camera.error()),
             QStringLiteral("cam.cfg:4:3: esperava um número para d hx hy, encontrou '1,5' (o "
                            "separador decimal é '.')"));
    rl::Diagnostics warned;
    camera = rl::readCameraFile("0 0 0\n0 0 1 7\n0 1 0\n1 1 1\n", "cam.cfg", warned);
    QVERIFY(camera);
    QCOMPARE(warned.size(), std::size_t(2));
    QCOMPARE(translated(warned.items()[1]),
             QStringLiteral("cam.cfg:2:7: aviso: ignorou 1 valor após N"));
    translators.install(QStringLiteral("en"));
    QCOMPARE(translated(warned.items()[1]),
             QStringLiteral("cam.cfg:2:7: warning: ignored 1 value after N"));
}

// The window in Portuguese, opening files as the user does: the error of a command file in the
// Messages dock and the status bar, a camera file's warning in the dock, each after the
// file:line:col of the English message.
void TestPipelineMessages::windowShowsPortuguese() {
    rasterlab::Translators translators;
    translators.install(QStringLiteral("pt_BR"));
    QTemporaryDir dir;
    const QString commands = writeFixture(dir, QStringLiteral("bad.txt"), kBadCommandFile);
    const QString camera =
        writeFixture(dir, QStringLiteral("cam.cfg"), "0 0 0\n0 0 1 7\n0 1 0\n1 1 1\n");
    QVERIFY(!commands.isEmpty() && !camera.isEmpty());

    rasterlab::MainWindow window;
    auto* messages = window.findChild<QListWidget*>(QStringLiteral("messagesList"));
    QVERIFY(messages);
    QVERIFY(!window.openPath(commands));
    const QString error =
        commands + QStringLiteral(":2:7: esperava um número em 'xyz' (x y z), encontrou 'b'");
    QVERIFY(messages->count() >= 1);
    QCOMPARE(messages->item(0)->text(), QStringLiteral("Erro: ") + error);
    QCOMPARE(window.statusBar()->currentMessage(), error);

    QVERIFY(window.openPath(camera));
    QStringList shown;
    for (int k = 0; k < messages->count(); ++k) shown << messages->item(k)->text();
    const QString warning = camera + QStringLiteral(":2:7: aviso: ignorou 1 valor após N");
    QVERIFY2(shown.contains(warning), qPrintable(shown.join(u'\n')));
    QVERIFY2(!shown.join(u'\n').contains(QStringLiteral("Erro")), qPrintable(shown.join(u'\n')));
}

// The command line prints the English messages whatever the language of its environment:
// scripts and the course's checks compare them.
void TestPipelineMessages::commandLineStaysEnglish() {
    QTemporaryDir dir;
    const QString commands = writeFixture(dir, QStringLiteral("bad.txt"), kBadCommandFile);
    QVERIFY(!commands.isEmpty());
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("LANG"), QStringLiteral("pt_BR.UTF-8"));
    environment.insert(QStringLiteral("LANGUAGE"), QStringLiteral("pt_BR"));
    testing::CliRun run;
    QVERIFY2(testing::runCli({QStringLiteral("run"), commands, QStringLiteral("--outdir"),
                              QStringLiteral("out")},
                             dir.path(), run, environment),
             qPrintable(run.problem));
    QCOMPARE(run.exitCode, 1);
    QCOMPARE(run.err, commands + QStringLiteral(":2:7: expected a number in 'xyz' (x y z), found "
                                                "'b'\n"));
}

QTEST_MAIN(TestPipelineMessages)
#include "tst_pipeline_messages.moc"
