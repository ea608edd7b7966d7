// The text scanner under every reader: number parsing in the C locale, quoting of tokens
// for messages, and the line and column of each token whatever the file's line endings,
// blank lines, spaces, TABs or byte-order mark.
#include <QtTest>

#include <cmath>
#include <limits>
#include <string_view>

#include "pipeline/io/text_scanner.h"

namespace {

std::string_view viewOf(const QByteArray& bytes) {
    return {bytes.constData(), static_cast<std::size_t>(bytes.size())};
}

// Byte for byte (Latin-1), so that a byte-order mark inside a token stays visible.
QString textOf(std::string_view text) {
    return QString::fromLatin1(text.data(), static_cast<qsizetype>(text.size()));
}

// A line as "number|col:token col:token|endColumn", e.g. "2|1:0 3:50|5".
QString describe(const rl::TextLine& line) {
    QStringList tokens;
    for (const rl::Token& token : line.tokens) {
        if (token.line != line.number)
            return QStringLiteral("token on line %1 in line %2").arg(token.line).arg(line.number);
        tokens << QStringLiteral("%1:%2").arg(token.column).arg(textOf(token.text));
    }
    return QStringLiteral("%1|%2|%3").arg(line.number).arg(tokens.join(' ')).arg(line.endColumn);
}

QStringList allLines(rl::LineScanner& scanner) {
    QStringList lines;
    rl::TextLine line;
    while (scanner.next(line)) lines << describe(line);
    return lines;
}

const QByteArray kBom = QByteArrayLiteral("\xEF\xBB\xBF");

}  // namespace

class TestTextScanner : public QObject {
    Q_OBJECT

private slots:
    void parseReal_data();
    void parseReal();
    void parseInteger_data();
    void parseInteger();
    void quoted_data();
    void quoted();
    void lines_data();
    void lines();
    void locations();
    void unread();
    void unreadAfterBlankLines();
    void countRemainingLines_data();
    void countRemainingLines();
    void endOfInput_data();
    void endOfInput();
    void afterLast_data();
    void afterLast();
    void bytes();
};

void TestTextScanner::parseReal_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<bool>("accepted");
    QTest::addColumn<double>("expected");

    // Accepted, with their exact values.
    QTest::newRow("fixed decimals 50.0000") << QByteArray("50.0000") << true << 50.0;
    QTest::newRow("three-digit exponent 9.5e-005") << QByteArray("9.5e-005") << true << 9.5e-5;
    QTest::newRow("capital E -1E-15") << QByteArray("-1E-15") << true << -1e-15;
    QTest::newRow("plus sign +2") << QByteArray("+2") << true << 2.0;
    QTest::newRow("leading dot .5") << QByteArray(".5") << true << 0.5;
    QTest::newRow("trailing dot 1.") << QByteArray("1.") << true << 1.0;
    QTest::newRow("zero") << QByteArray("0") << true << 0.0;
    QTest::newRow("negative zero") << QByteArray("-0") << true << 0.0;
    QTest::newRow("negative leading dot -.25") << QByteArray("-.25") << true << -0.25;
    QTest::newRow("explicit exponent sign 1e+2") << QByteArray("1e+2") << true << 100.0;
    QTest::newRow("plus sign and exponent +6.5E1") << QByteArray("+6.5E1") << true << 65.0;
    QTest::newRow("0.667") << QByteArray("0.667") << true << 0.667;
    QTest::newRow("large 1e308") << QByteArray("1e308") << true << 1e308;
    QTest::newRow("long mantissa") << QByteArray("20.9095156136808") << true << 20.9095156136808;

    // Rejected.
    QTest::newRow("empty") << QByteArray("") << false << 0.0;
    QTest::newRow("letters abc") << QByteArray("abc") << false << 0.0;
    QTest::newRow("decimal comma 1,5") << QByteArray("1,5") << false << 0.0;
    QTest::newRow("nan") << QByteArray("nan") << false << 0.0;
    QTest::newRow("NaN") << QByteArray("NaN") << false << 0.0;
    QTest::newRow("-nan") << QByteArray("-nan") << false << 0.0;
    QTest::newRow("inf") << QByteArray("inf") << false << 0.0;
    QTest::newRow("-inf") << QByteArray("-inf") << false << 0.0;
    QTest::newRow("+inf") << QByteArray("+inf") << false << 0.0;
    QTest::newRow("infinity") << QByteArray("infinity") << false << 0.0;
    QTest::newRow("out of range 1e999") << QByteArray("1e999") << false << 0.0;
    QTest::newRow("out of range -1e999") << QByteArray("-1e999") << false << 0.0;
    QTest::newRow("two dots 1.2.3") << QByteArray("1.2.3") << false << 0.0;
    QTest::newRow("hexadecimal 0x10") << QByteArray("0x10") << false << 0.0;
    QTest::newRow("incomplete exponent 1e") << QByteArray("1e") << false << 0.0;
    QTest::newRow("incomplete exponent 1e+") << QByteArray("1e+") << false << 0.0;
    QTest::newRow("sign only -") << QByteArray("-") << false << 0.0;
    QTest::newRow("sign only +") << QByteArray("+") << false << 0.0;
    QTest::newRow("dot only") << QByteArray(".") << false << 0.0;
    QTest::newRow("two signs +-2") << QByteArray("+-2") << false << 0.0;
    QTest::newRow("two signs -+2") << QByteArray("-+2") << false << 0.0;
    QTest::newRow("two signs ++2") << QByteArray("++2") << false << 0.0;
    QTest::newRow("two signs --2") << QByteArray("--2") << false << 0.0;
    QTest::newRow("leading space") << QByteArray(" 1") << false << 0.0;
    QTest::newRow("trailing space") << QByteArray("1 ") << false << 0.0;
    QTest::newRow("trailing CR") << QByteArray("1\r") << false << 0.0;
    QTest::newRow("suffix 1f") << QByteArray("1f") << false << 0.0;
    QTest::newRow("Fortran exponent 1d5") << QByteArray("1d5") << false << 0.0;
    QTest::newRow("two numbers 1-2") << QByteArray("1-2") << false << 0.0;
}

void TestTextScanner::parseReal() {
    QFETCH(QByteArray, text);
    QFETCH(bool, accepted);
    QFETCH(double, expected);

    const std::optional<double> value = rl::parseReal(viewOf(text));
    QCOMPARE(value.has_value(), accepted);
    if (!accepted) return;
    // Exact: the reader must give the double nearest to the decimal text.
    QVERIFY2(*value == expected, qPrintable(QStringLiteral("%1 parsed as %2, expected %3")
                                                .arg(QString::fromLatin1(text))
                                                .arg(*value, 0, 'g', 17)
                                                .arg(expected, 0, 'g', 17)));
}

void TestTextScanner::parseInteger_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<bool>("accepted");
    QTest::addColumn<qlonglong>("expected");

    QTest::newRow("12") << QByteArray("12") << true << 12LL;
    QTest::newRow("plus sign +3") << QByteArray("+3") << true << 3LL;
    QTest::newRow("negative -1") << QByteArray("-1") << true << -1LL;
    QTest::newRow("zero") << QByteArray("0") << true << 0LL;
    QTest::newRow("leading zeros 007") << QByteArray("007") << true << 7LL;
    QTest::newRow("largest long long")
        << QByteArray("9223372036854775807") << true << std::numeric_limits<qlonglong>::max();

    QTest::newRow("decimal 1.0") << QByteArray("1.0") << false << 0LL;
    QTest::newRow("letter x") << QByteArray("x") << false << 0LL;
    QTest::newRow("empty") << QByteArray("") << false << 0LL;
    QTest::newRow("too large 99999999999999999999")
        << QByteArray("99999999999999999999") << false << 0LL;
    QTest::newRow("exponent 1e3") << QByteArray("1e3") << false << 0LL;
    QTest::newRow("hexadecimal 0x10") << QByteArray("0x10") << false << 0LL;
    QTest::newRow("sign only +") << QByteArray("+") << false << 0LL;
    QTest::newRow("sign only -") << QByteArray("-") << false << 0LL;
    QTest::newRow("two signs +-3") << QByteArray("+-3") << false << 0LL;
    QTest::newRow("two signs ++3") << QByteArray("++3") << false << 0LL;
    QTest::newRow("trailing letter 12a") << QByteArray("12a") << false << 0LL;
    QTest::newRow("leading space") << QByteArray(" 1") << false << 0LL;
    QTest::newRow("trailing CR") << QByteArray("1\r") << false << 0LL;
}

void TestTextScanner::parseInteger() {
    QFETCH(QByteArray, text);
    QFETCH(bool, accepted);
    QFETCH(qlonglong, expected);

    const std::optional<long long> value = rl::parseInteger(viewOf(text));
    QCOMPARE(value.has_value(), accepted);
    if (accepted) QCOMPARE(qlonglong(*value), expected);
}

void TestTextScanner::quoted_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QByteArray>("expected");

    QTest::newRow("short token") << QByteArray("abc") << QByteArray("'abc'");
    QTest::newRow("empty token") << QByteArray("") << QByteArray("''");
    QTest::newRow("exactly 24 characters")
        << QByteArray("abcdefghijklmnopqrstuvwx") << QByteArray("'abcdefghijklmnopqrstuvwx'");
    QTest::newRow("25 characters are cut")
        << QByteArray("abcdefghijklmnopqrstuvwxy") << QByteArray("'abcdefghijklmnopqrstuvwx...'");
    QTest::newRow("long token is cut") << QByteArray("0.123456789012345678901234567890")
                                       << QByteArray("'0.1234567890123456789012...'");
    QTest::newRow("TAB as \\x09") << QByteArray("a\tb") << QByteArray("'a\\x09b'");
    QTest::newRow("CR as \\x0d") << QByteArray("1\r") << QByteArray("'1\\x0d'");
    QTest::newRow("NUL as \\x00") << QByteArray("a\0b", 3) << QByteArray("'a\\x00b'");
    QTest::newRow("escape as \\x1b") << QByteArray("\x1b[0m") << QByteArray("'\\x1b[0m'");
    QTest::newRow("DEL as \\x7f") << QByteArray("x\x7f") << QByteArray("'x\\x7f'");
    QTest::newRow("control byte in a long token")
        << QByteArray(
               "\x01"
               "bcdefghijklmnopqrstuvwxyz")
        << QByteArray("'\\x01bcdefghijklmnopqrstuvwx...'");
    QTest::newRow("UTF-8 kept as is")
        << QByteArray("ilumina\xC3\xA7\xC3\xA3o") << QByteArray("'ilumina\xC3\xA7\xC3\xA3o'");
}

void TestTextScanner::quoted() {
    QFETCH(QByteArray, text);
    QFETCH(QByteArray, expected);

    const std::string result = rl::quoted(viewOf(text));
    QCOMPARE(QByteArray::fromStdString(result), expected);
}

void TestTextScanner::lines_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QStringList>("expected");  // describe() of each line

    const QStringList threeLines = {"1|1:3 3:1|4", "2|1:0 3:50.0000 11:-1E-15|17",
                                    "3|1:1 3:2 5:3|6"};
    QTest::newRow("LF") << QByteArray("3 1\n0 50.0000 -1E-15\n1 2 3\n") << threeLines;
    QTest::newRow("CRLF") << QByteArray("3 1\r\n0 50.0000 -1E-15\r\n1 2 3\r\n") << threeLines;
    QTest::newRow("no final newline") << QByteArray("3 1\n0 50.0000 -1E-15\n1 2 3") << threeLines;
    QTest::newRow("CRLF, no final newline")
        << QByteArray("3 1\r\n0 50.0000 -1E-15\r\n1 2 3") << threeLines;
    QTest::newRow("mixed LF and CRLF")
        << QByteArray("3 1\r\n0 50.0000 -1E-15\n1 2 3\r\n") << threeLines;
    QTest::newRow("blank lines are skipped but counted")
        << QByteArray("\n3 1\n\n\n0 50.0000 -1E-15\n\n1 2 3\n\n")
        << QStringList{"2|1:3 3:1|4", "5|1:0 3:50.0000 11:-1E-15|17", "7|1:1 3:2 5:3|6"};
    QTest::newRow("blank lines holding spaces, TABs and CR")
        << QByteArray("  \r\n3 1\r\n\t\r\n \t \r\n1 2 3\r\n\r\n")
        << QStringList{"2|1:3 3:1|4", "5|1:1 3:2 5:3|6"};
    QTest::newRow("leading spaces")
        << QByteArray("   3 1\n  1 2 3\n") << QStringList{"1|4:3 6:1|7", "2|3:1 5:2 7:3|8"};
    QTest::newRow("leading TAB counts as one column")
        << QByteArray("\t3 1\n\t\t1 2 3\n") << QStringList{"1|2:3 4:1|5", "2|3:1 5:2 7:3|8"};
    QTest::newRow("TAB inside a line")
        << QByteArray("0\t50.0000 \t-1E-15\n") << QStringList{"1|1:0 3:50.0000 12:-1E-15|18"};
    QTest::newRow("trailing spaces and TABs")
        << QByteArray("3 1  \t\n1 2 3 \r\n") << QStringList{"1|1:3 3:1|4", "2|1:1 3:2 5:3|6"};
    QTest::newRow("form feed and vertical tab are spaces")
        << QByteArray("3\f1\v\n") << QStringList{"1|1:3 3:1|4"};
    // The byte-order mark is not part of line 1: its first token is in column 1.
    QTest::newRow("UTF-8 BOM") << kBom + QByteArray("3 1\n1 2 3\n")
                               << QStringList{"1|1:3 3:1|4", "2|1:1 3:2 5:3|6"};
    QTest::newRow("UTF-8 BOM, leading space and CRLF")
        << kBom + QByteArray(" 3 1\r\n1 2 3") << QStringList{"1|2:3 4:1|5", "2|1:1 3:2 5:3|6"};
    QTest::newRow("UTF-8 BOM then a blank line")
        << kBom + QByteArray("\r\n3 1") << QStringList{"2|1:3 3:1|4"};
    QTest::newRow("a BOM later in the file is not skipped")
        << QByteArray("1\n") + kBom + QByteArray("2\n")
        << QStringList{"1|1:1|2", QString::fromLatin1("2|1:\xEF\xBB\xBF"
                                                      "2|5")};
    QTest::newRow("empty") << QByteArray("") << QStringList{};
    QTest::newRow("only a BOM") << kBom << QStringList{};
    QTest::newRow("only blank lines") << QByteArray("\n\r\n \t\n") << QStringList{};
    QTest::newRow("one token, no newline") << QByteArray("x") << QStringList{"1|1:x|2"};
}

void TestTextScanner::lines() {
    QFETCH(QByteArray, text);
    QFETCH(QStringList, expected);

    rl::LineScanner scanner(viewOf(text), "in.txt");
    QCOMPARE(allLines(scanner), expected);
    rl::TextLine line;
    QVERIFY(!scanner.next(line));  // stays at the end
    QCOMPARE(scanner.bytesRemaining(), std::size_t(0));
}

void TestTextScanner::locations() {
    const QByteArray text("\n  -200 -50\t300\r\n");
    rl::LineScanner scanner(viewOf(text), "camera.cfg");
    QCOMPARE(QString::fromStdString(scanner.fileName()), QStringLiteral("camera.cfg"));
    rl::TextLine line;
    QVERIFY(scanner.next(line));
    QCOMPARE(line.tokens.size(), std::size_t(3));
    QCOMPARE(QString::fromStdString(scanner.at(line.tokens[0]).toString()),
             QStringLiteral("camera.cfg:2:3"));
    QCOMPARE(QString::fromStdString(scanner.at(line.tokens[1]).toString()),
             QStringLiteral("camera.cfg:2:8"));
    QCOMPARE(QString::fromStdString(scanner.at(line.tokens[2]).toString()),
             QStringLiteral("camera.cfg:2:12"));
    QCOMPARE(QString::fromStdString(scanner.at(line.number, 1).toString()),
             QStringLiteral("camera.cfg:2:1"));
    QCOMPARE(QString::fromStdString(scanner.afterLast(line).toString()),
             QStringLiteral("camera.cfg:2:15"));
}

void TestTextScanner::unread() {
    const QByteArray text("1 2 3\n4 5 6\n7 8 9\n");
    rl::LineScanner scanner(viewOf(text), "in.txt");
    rl::TextLine line;
    QVERIFY(scanner.next(line));
    QVERIFY(scanner.next(line));
    QCOMPARE(describe(line), QStringLiteral("2|1:4 3:5 5:6|6"));

    scanner.unread();
    QCOMPARE(scanner.countRemainingLines(), 2);
    QVERIFY(scanner.next(line));
    QCOMPARE(describe(line), QStringLiteral("2|1:4 3:5 5:6|6"));
    QVERIFY(scanner.next(line));
    QCOMPARE(describe(line), QStringLiteral("3|1:7 3:8 5:9|6"));

    // The last line can be put back too, and the line numbers go on from it.
    scanner.unread();
    QVERIFY(scanner.next(line));
    QCOMPARE(describe(line), QStringLiteral("3|1:7 3:8 5:9|6"));
    QVERIFY(!scanner.next(line));
}

void TestTextScanner::unreadAfterBlankLines() {
    // The line put back keeps its number; the blank lines before it are skipped again.
    const QByteArray text("3 1\r\n\r\n\r\n40\r\n\r\n0 0 0\r\n");
    rl::LineScanner scanner(viewOf(text), "in.txt");
    rl::TextLine line;
    QVERIFY(scanner.next(line));
    QVERIFY(scanner.next(line));
    QCOMPARE(describe(line), QStringLiteral("4|1:40|3"));
    scanner.unread();
    QCOMPARE(allLines(scanner), (QStringList{"4|1:40|3", "6|1:0 3:0 5:0|6"}));
}

void TestTextScanner::countRemainingLines_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("consumed");  // lines read with next() first
    QTest::addColumn<int>("expected");

    const QByteArray lf("3 1\n\n0 0 0\n1 0 0\n\n0 1 0\n1 2 3\n\n");
    const QByteArray crlfNoFinal("3 1\r\n\r\n0 0 0\r\n1 0 0\r\n\r\n0 1 0\r\n1 2 3");
    QTest::newRow("LF, nothing read") << lf << 0 << 5;
    QTest::newRow("LF, header read") << lf << 1 << 4;
    QTest::newRow("LF, all read") << lf << 5 << 0;
    QTest::newRow("CRLF without final newline, header read") << crlfNoFinal << 1 << 4;
    QTest::newRow("CRLF without final newline, four read") << crlfNoFinal << 4 << 1;
    QTest::newRow("empty") << QByteArray() << 0 << 0;
    QTest::newRow("blank lines only") << QByteArray("\r\n \r\n\t\n") << 0 << 0;
    QTest::newRow("BOM") << kBom + QByteArray("1\n2") << 0 << 2;
}

void TestTextScanner::countRemainingLines() {
    QFETCH(QByteArray, text);
    QFETCH(int, consumed);
    QFETCH(int, expected);

    rl::LineScanner scanner(viewOf(text), "in.txt");
    rl::TextLine line;
    for (int i = 0; i < consumed; ++i) QVERIFY(scanner.next(line));
    QCOMPARE(scanner.countRemainingLines(), expected);
    // Counting consumes nothing.
    QCOMPARE(scanner.countRemainingLines(), expected);
    QCOMPARE(int(allLines(scanner).size()), expected);
}

void TestTextScanner::endOfInput_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("expected");

    QTest::newRow("final LF") << QByteArray("1 2\n3 4\n") << QStringLiteral("in.txt:3:1");
    QTest::newRow("no final newline") << QByteArray("1 2\n3 4") << QStringLiteral("in.txt:2:4");
    QTest::newRow("final CRLF") << QByteArray("1 2\r\n3 4\r\n") << QStringLiteral("in.txt:3:1");
    QTest::newRow("CRLF, no final newline")
        << QByteArray("1 2\r\n3 4") << QStringLiteral("in.txt:2:4");
    QTest::newRow("final CR without LF") << QByteArray("1 2\r") << QStringLiteral("in.txt:1:4");
    QTest::newRow("trailing blank lines")
        << QByteArray("1 2\n\n\n") << QStringLiteral("in.txt:4:1");
    QTest::newRow("trailing spaces, no newline")
        << QByteArray("1 2  ") << QStringLiteral("in.txt:1:6");
    QTest::newRow("empty") << QByteArray() << QStringLiteral("in.txt:1:1");
    // Columns after a byte-order mark are counted as for the tokens: from the first byte
    // after the mark.
    QTest::newRow("BOM, no newline") << kBom + QByteArray("1 2") << QStringLiteral("in.txt:1:4");
    QTest::newRow("BOM only") << kBom << QStringLiteral("in.txt:1:1");
    QTest::newRow("BOM, final LF") << kBom + QByteArray("1 2\n") << QStringLiteral("in.txt:2:1");
}

void TestTextScanner::endOfInput() {
    QFETCH(QByteArray, text);
    QFETCH(QString, expected);

    rl::LineScanner scanner(viewOf(text), "in.txt");
    QCOMPARE(QString::fromStdString(scanner.endOfInput().toString()), expected);
    // The same whether or not the input was read.
    allLines(scanner);
    QCOMPARE(QString::fromStdString(scanner.endOfInput().toString()), expected);
}

void TestTextScanner::afterLast_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("expected");

    QTest::newRow("plain") << QByteArray("1 2 3\n") << QStringLiteral("in.txt:1:6");
    QTest::newRow("CRLF") << QByteArray("1 2 3\r\n") << QStringLiteral("in.txt:1:6");
    QTest::newRow("leading and trailing spaces")
        << QByteArray("  1 2 3   \n") << QStringLiteral("in.txt:1:8");
    QTest::newRow("TABs") << QByteArray("\t1\t2\t\n") << QStringLiteral("in.txt:1:5");
    QTest::newRow("after blank lines")
        << QByteArray("\n\r\n0.5 0.625\r\n") << QStringLiteral("in.txt:3:10");
    QTest::newRow("BOM") << kBom + QByteArray("1 2") << QStringLiteral("in.txt:1:4");
}

void TestTextScanner::afterLast() {
    QFETCH(QByteArray, text);
    QFETCH(QString, expected);

    rl::LineScanner scanner(viewOf(text), "in.txt");
    rl::TextLine line;
    QVERIFY(scanner.next(line));
    QCOMPARE(QString::fromStdString(scanner.afterLast(line).toString()), expected);
}

void TestTextScanner::bytes() {
    const QByteArray text = kBom + QByteArray("1 2\n3 4\n");
    rl::LineScanner scanner(viewOf(text), "in.txt");
    QCOMPARE(scanner.bytesTotal(), std::size_t(11));
    QCOMPARE(scanner.bytesRemaining(), std::size_t(8));  // the BOM is skipped
    rl::TextLine line;
    QVERIFY(scanner.next(line));
    QCOMPARE(scanner.bytesRemaining(), std::size_t(4));
    QVERIFY(scanner.next(line));
    QCOMPARE(scanner.bytesRemaining(), std::size_t(0));
}

QTEST_GUILESS_MAIN(TestTextScanner)
#include "tst_text_scanner.moc"
