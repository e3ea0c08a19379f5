// Conditional compilation before parsing: the condition evaluator, the blanking of inactive
// branches (lines and columns of the rest unchanged), macros, includes, malformed input, and
// the compile definitions a CMakeLists.txt makes.
#include "nodes/cpp/cppmacroindex.h"
#include "syntax/cppconditionevaluator.h"
#include "syntax/cpppreprocessor.h"
#include "syntax/cppsyntax.h"

#include <QtTest>

using namespace rosarch;

namespace {

CppMacros macros(std::initializer_list<std::pair<const char *, const char *>> list)
{
    CppMacros m;
    for (const auto &[name, body] : list)
        m.insert(name, CppMacro{body, {}, false});
    return m;
}

// The lines of `source` that survive, trimmed, joined by '|' (blank lines dropped).
QString kept(const QByteArray &source)
{
    QStringList out;
    for (const QByteArray &line : source.split('\n'))
        if (!line.trimmed().isEmpty())
            out << QString::fromUtf8(line.trimmed());
    return out.join(u'|');
}

CppPreprocessor::Result run(QByteArray *source, const CppMacros &initial = {})
{
    const QByteArray before = *source;
    CppPreprocessor::Result r = CppPreprocessor::run(source, QStringLiteral("f.cpp"), initial);
    // Whatever is blanked, the file keeps its length and every newline where it was.
    [&] {
        QCOMPARE(source->size(), before.size());
        for (qsizetype i = 0; i < before.size(); ++i)
            if (before.at(i) == '\n' || source->at(i) == '\n')
                QCOMPARE(source->at(i), before.at(i));
    }();
    return r;
}

QStringList codes(const CppPreprocessor::Result &r)
{
    QStringList out;
    for (const Diagnostic &d : r.diagnostics)
        out << d.code + QLatin1Char(':') + QString::number(d.evidence.line);
    return out;
}

} // namespace

class TestCppPreprocessor : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void conditions_data()
    {
        QTest::addColumn<QByteArray>("condition");
        QTest::addColumn<bool>("decided");
        QTest::addColumn<qlonglong>("value");
        QTest::newRow("literal") << QByteArray("1") << true << 1LL;
        QTest::newRow("zero") << QByteArray("0") << true << 0LL;
        QTest::newRow("defined") << QByteArray("defined(ONE)") << true << 1LL;
        QTest::newRow("defined without parens") << QByteArray("defined ONE") << true << 1LL;
        QTest::newRow("not defined") << QByteArray("!defined(NOPE)") << true << 1LL;
        QTest::newRow("unknown is 0") << QByteArray("NOPE") << true << 0LL;
        QTest::newRow("macro value") << QByteArray("VERSION >= 3") << true << 1LL;
        QTest::newRow("macro through macro") << QByteArray("ALIAS == 3") << true << 1LL;
        QTest::newRow("arithmetic") << QByteArray("(VERSION * 10 + 2) / 4 == 8") << true << 1LL;
        QTest::newRow("precedence")
            << QByteArray("1 + 2 * 3 == 7 && 10 - 4 - 3 == 3") << true << 1LL;
        QTest::newRow("logic") << QByteArray("defined ONE && !defined(NOPE) || 0") << true << 1LL;
        QTest::newRow("ternary") << QByteArray("ONE ? 5 : 6") << true << 5LL;
        QTest::newRow("hex and suffix") << QByteArray("0x10 == 16UL") << true << 1LL;
        QTest::newRow("comparison chain") << QByteArray("2 < 3 != 0") << true << 1LL;
        QTest::newRow("function-like")
            << QByteArray("RCLCPP_VERSION_GTE(28, 0, 0)") << false << 0LL;
        QTest::newRow("has_include")
            << QByteArray("__has_include(<cv_bridge/cv_bridge.hpp>)") << false << 0LL;
        QTest::newRow("decided around an unknown")
            << QByteArray("0 && RCLCPP_VERSION_GTE(28, 0, 0)") << true << 0LL;
        QTest::newRow("decided around an unknown, or")
            << QByteArray("F(1) || defined(ONE)") << true << 1LL;
        QTest::newRow("undecided and") << QByteArray("ONE && F(1)") << false << 0LL;
        QTest::newRow("division by zero") << QByteArray("1 / 0") << false << 0LL;
        QTest::newRow("malformed") << QByteArray("(1 + ") << false << 0LL;
        QTest::newRow("empty") << QByteArray("") << false << 0LL;
        QTest::newRow("string") << QByteArray("\"x\"") << false << 0LL;
        QTest::newRow("self reference") << QByteArray("SELF") << true << 0LL;
        QTest::newRow("deep parentheses")
            << QByteArray(200, '(') + "1" + QByteArray(200, ')') << false << 0LL;
    }

    void conditions()
    {
        QFETCH(QByteArray, condition);
        QFETCH(bool, decided);
        QFETCH(qlonglong, value);
        const CppMacros m =
            macros({{"ONE", "1"}, {"VERSION", "3"}, {"ALIAS", "VERSION"}, {"SELF", "SELF"}});
        const CppConditionEvaluator::Result r = CppConditionEvaluator(m).evaluate(condition);
        QCOMPARE(r.decided, decided);
        if (decided)
            QCOMPARE(r.value, value);
    }

    void nestingAndElif()
    {
        QByteArray src = "#define MODE 2\n"
                         "#if MODE == 1\n"
                         "a\n"
                         "#elif MODE == 2\n"
                         "  #ifdef NOPE\n"
                         "b\n"
                         "  #else\n"
                         "c\n"
                         "    #if 1\n"
                         "d\n"
                         "    #endif\n"
                         "  #endif\n"
                         "#elif MODE == 2\n"
                         "e\n"
                         "#else\n"
                         "f\n"
                         "#endif\n"
                         "g\n";
        const CppPreprocessor::Result r = run(&src);
        QCOMPARE(kept(src), QStringLiteral("#define MODE 2|c|d|g"));
        QVERIFY(r.diagnostics.isEmpty());
    }

    void inactiveDefinesDoNotCount()
    {
        QByteArray src = "#if 0\n#define A 1\n#endif\n#ifdef A\nx\n#endif\n"
                         "#define B 1\n#undef B\n#ifndef B\ny\n#endif\n";
        const CppPreprocessor::Result r = run(&src);
        QCOMPARE(kept(src), QStringLiteral("#define B 1|#undef B|y"));
        QVERIFY(!r.macros.contains("A"));
        QVERIFY(!r.macros.contains("B"));
    }

    void initialDefinitions()
    {
        QByteArray src = "#ifdef USE_LASER\nlaser\n#else\ncamera\n#endif\n";
        run(&src, macros({{"USE_LASER", "1"}}));
        QCOMPARE(kept(src), QStringLiteral("laser"));
    }

    // The #if branch is taken and the rest dropped, with one note naming the condition.
    void undecidableTakesTheFirstBranch()
    {
        QByteArray src = "#if RCLCPP_VERSION_GTE(28, 0, 0)\n"
                         "new_api();\n"
                         "#elif 1\n"
                         "middle();\n"
                         "#else\n"
                         "old_api();\n"
                         "#endif\n"
                         "#if 0\n"
                         "#elif __has_include(<x.hpp>)\n"
                         "has();\n"
                         "#else\n"
                         "has_not();\n"
                         "#endif\n";
        const CppPreprocessor::Result r = run(&src);
        QCOMPARE(kept(src), QStringLiteral("new_api();|has();"));
        QCOMPARE(codes(r), (QStringList{QStringLiteral("preprocessor-guess:1"),
                                        QStringLiteral("preprocessor-guess:9")}));
        QVERIFY(r.diagnostics[0].message.contains(QStringLiteral("RCLCPP_VERSION_GTE(28, 0, 0)")));
        QCOMPARE(r.diagnostics[0].severity, Diagnostic::Severity::Info);
    }

    void guessNotesAreBounded()
    {
        QByteArray src;
        for (int i = 0; i < 25; ++i)
            src += "#if F(" + QByteArray::number(i) + ")\nx\n#endif\n";
        const CppPreprocessor::Result r = run(&src);
        QCOMPARE(r.diagnostics.size(), CppPreprocessor::kMaxGuessNotes + 1);
        QVERIFY(r.diagnostics.last().message.startsWith(QStringLiteral("15 more")));
    }

    void unbalanced()
    {
        QByteArray src = "a\n#endif\nb\n#else\n#if 0\nc\n#else\nd\n#else\ne\n#endif\n#ifdef X\nf\n";
        const CppPreprocessor::Result r = run(&src);
        QCOMPARE(kept(src), QStringLiteral("a|b|d|e"));
        QCOMPARE(codes(r), (QStringList{QStringLiteral("preprocessor-malformed:2"),
                                        QStringLiteral("preprocessor-malformed:4"),
                                        QStringLiteral("preprocessor-malformed:9"),
                                        QStringLiteral("preprocessor-malformed:12")}));
        QCOMPARE(r.diagnostics[0].severity, Diagnostic::Severity::Warning);
    }

    void deepNestingIsBounded()
    {
        const int depth = 5000;
        QByteArray src;
        for (int i = 0; i < depth; ++i)
            src += "#if 1\n";
        src += "x\n";
        for (int i = 0; i < depth; ++i)
            src += "#endif\n";
        const CppPreprocessor::Result r = run(&src);
        QCOMPARE(kept(src), QStringLiteral("x"));
        QCOMPARE(
            codes(r),
            QStringList{
                QStringLiteral("preprocessor-malformed:%1").arg(CppPreprocessor::kMaxDepth + 1)});
    }

    // Lines and columns of what stays are those of the file as written.
    void columnsStay()
    {
        QByteArray src = "int a;  // é\r\n"
                         "#if defined(A) && \\\n"
                         "    B\n"
                         "int b;\n"
                         "#else /* the other\n"
                         "   configuration */ int c;\n"
                         "#endif\n"
                         "\tint d = 1'000;\n";
        const QByteArray before = src;
        run(&src);
        const QList<QByteArray> lines = src.split('\n');
        QCOMPARE(lines.size(), 9);
        QCOMPARE(lines[0], QByteArray("int a;  // é\r"));
        QCOMPARE(lines[1], QByteArray(19, ' '));
        QCOMPARE(lines[2], QByteArray(5, ' '));
        QCOMPARE(lines[3], QByteArray(6, ' '));
        // The comment opened on the #else line still has its start where it was.
        QCOMPARE(lines[4], QByteArray("      /* the other"));
        QCOMPARE(lines[5], QByteArray("   configuration */ int c;"));
        QCOMPARE(lines[7], QByteArray("\tint d = 1'000;"));
        QCOMPARE(src.indexOf("int c;"), before.indexOf("int c;"));
    }

    // Directives inside comments, strings and raw strings are not directives.
    void commentsAndStrings()
    {
        QByteArray src = "/*\n#if 0\n*/\na\n"
                         "auto s = R\"x(\n#if 0\n)x\";\n"
                         "const char *t = \"/*\";\n"
                         "#if 0\nb\n#endif\n";
        const CppPreprocessor::Result r = run(&src);
        QCOMPARE(kept(src), QStringLiteral("/*|#if 0|*/|a|auto s = R\"x(|#if 0|)x\";|"
                                           "const char *t = \"/*\";"));
        QVERIFY(r.diagnostics.isEmpty());
    }

    void macrosAndGuards()
    {
        QByteArray src = "#ifndef PKG__TOPICS_HPP_\n"
                         "#define PKG__TOPICS_HPP_\n"
                         "#define TOPIC \"scan\"\n"
                         "#define PREFIXED \"robot/\" \"odom\"\n"
                         "#define RATE 10\n"
                         "#define MAKE(x) \"robot/\" x\n"
                         "#define LONG \\\n  \"long\"\n"
                         "#endif  // PKG__TOPICS_HPP_\n";
        const CppPreprocessor::Result r = run(&src);
        QVERIFY(r.macros.contains("PKG__TOPICS_HPP_"));
        QVERIFY(!r.exported.contains("PKG__TOPICS_HPP_"));
        QCOMPARE(r.exported.size(), 5);
        QCOMPARE(CppPreprocessor::constantValue(r.exported.value("TOPIC").body),
                 QStringLiteral("scan"));
        QCOMPARE(CppPreprocessor::constantValue(r.exported.value("PREFIXED").body),
                 QStringLiteral("robot/odom"));
        QCOMPARE(CppPreprocessor::constantValue(r.exported.value("RATE").body),
                 QStringLiteral("10"));
        QCOMPARE(CppPreprocessor::constantValue(r.exported.value("LONG").body),
                 QStringLiteral("long"));
        QVERIFY(r.exported.value("MAKE").functionLike);
        QCOMPARE(r.exported.value("MAKE").parameters, QList<QByteArray>{"x"});
        QVERIFY(CppPreprocessor::constantValue("foo()").isNull());
        // Through other macros, defined before or after.
        const CppMacros m = macros(
            {{"NS", "\"rover/\""}, {"FULL", "NS \"status\""}, {"BAD", "NS + 1"}, {"LOOP", "LOOP"}});
        QCOMPARE(CppPreprocessor::constantValue("FULL", m), QStringLiteral("rover/status"));
        QVERIFY(CppPreprocessor::constantValue("BAD", m).isNull());
        QVERIFY(CppPreprocessor::constantValue("LOOP", m).isNull());
        QVERIFY(CppPreprocessor::constantValue("UNKNOWN", m).isNull());
    }

    // A guard is only `#ifndef G` followed at once by `#define G`.
    // Function-like macros that wrap a string: arguments put in, #x made a string, through
    // object-like macros; anything else (pasting, a wrong count, code) is no constant.
    void functionLikeStringMacros()
    {
        const CppMacros m = macros({{"ROOT", "\"robot\""}});
        const CppMacro topic{"ROOT \"/\" x", {"x"}, true};
        QCOMPARE(CppPreprocessor::expandedValue(topic, {"\"scan\""}, m),
                 QStringLiteral("robot/scan"));
        QCOMPARE(CppPreprocessor::expandedValue(topic, {"ROOT"}, m), QStringLiteral("robot/robot"));
        const CppMacro named{"\"ns/\" # x \"/x\"", {"x"}, true};
        QCOMPARE(CppPreprocessor::expandedValue(named, {"  odom  "}), QStringLiteral("ns/odom/x"));
        const CppMacro two{"a \"_\" b", {"a", "b"}, true};
        QCOMPARE(CppPreprocessor::expandedValue(two, {"\"l\"", "\"r\""}), QStringLiteral("l_r"));
        QVERIFY(CppPreprocessor::expandedValue(two, {"\"l\""}).isNull());
        QVERIFY(
            CppPreprocessor::expandedValue(CppMacro{"a ## b", {"a", "b"}, true}, {"\"l\"", "\"r\""})
                .isNull());
        QVERIFY(CppPreprocessor::expandedValue(CppMacro{"f(x)", {"x"}, true}, {"\"y\""}).isNull());
        QVERIFY(CppPreprocessor::expandedValue(topic, {"name_"}).isNull()); // a variable
        QVERIFY(CppPreprocessor::expandedValue(CppMacro{"\"x\"", {}, false}, {}).isNull());
    }

    void notAGuard()
    {
        QByteArray src = "#ifndef USE_SIM\n#define USE_HW 1\n#define USE_SIM 0\n#endif\n";
        const CppPreprocessor::Result r = run(&src);
        QVERIFY(r.exported.contains("USE_SIM"));
        QVERIFY(r.exported.contains("USE_HW"));
    }

    void includesBringMacros()
    {
        const CppMacros header = macros({{"USE_LASER", "1"}});
        QByteArray src = "#include <other/x.hpp>\n#ifdef USE_LASER\nbefore\n#endif\n"
                         "#include \"pkg/config.hpp\"\n#ifdef USE_LASER\nafter\n#endif\n";
        QStringList asked;
        const CppPreprocessor::Result r = CppPreprocessor::run(
            &src, QStringLiteral("f.cpp"), {},
            [&](const QByteArray &written, bool angled) -> const CppMacros * {
                asked << QString::fromUtf8(written) + (angled ? QStringLiteral(" <>") : "");
                return written == "pkg/config.hpp" ? &header : nullptr;
            });
        QCOMPARE(asked,
                 (QStringList{QStringLiteral("other/x.hpp <>"), QStringLiteral("pkg/config.hpp")}));
        QCOMPARE(kept(src), QStringLiteral("#include <other/x.hpp>|#include \"pkg/config.hpp\"|"
                                           "after"));
        QVERIFY(r.exported.contains("USE_LASER"));
    }

    // Qt's moc keywords, which the parser takes for syntax errors, keep their columns.
    void qtKeywords()
    {
        QByteArray src = "class Panel : public QWidget\n"
                         "{\n"
                         "  Q_OBJECT  // moc\n"
                         "public Q_SLOTS:\n"
                         "  void a();\n"
                         "protected slots :\n"
                         "signals:\n"
                         "  Q_SIGNALS:\n"
                         "  void Q_OBJECT_like();\n"
                         "  int slots = 0;\n"
                         "};\n";
        const qsizetype size = src.size();
        cppsyntax::blankQtKeywords(&src);
        QCOMPARE(src.size(), size);
        QCOMPARE(src.split('\n'),
                 (QList<QByteArray>{"class Panel : public QWidget", "{", "            // moc",
                                    "public        :", "  void a();", "protected       :",
                                    "public :", "  public   :", "  void Q_OBJECT_like();",
                                    "  int slots = 0;", "};", ""}));
    }

    void compileDefinitions()
    {
        const CppMacros m = CppMacroIndex::compileDefinitions(
            "add_compile_definitions(USE_LASER MAX_RANGE=30)\n"
            "add_definitions(-DQT_NO_KEYWORDS -Wall \"-DTOPIC=\\\"scan\\\"\")\n"
            "target_compile_definitions(${PROJECT_NAME} PRIVATE \"HAVE_DRAND48\" PUBLIC -DSIM=0"
            " ${PCL_DEFINITIONS} $<$<CONFIG:Debug>:DEBUG_MODE>)\n");
        QList<QByteArray> names = m.keys();
        std::sort(names.begin(), names.end());
        QCOMPARE(names, (QList<QByteArray>{"HAVE_DRAND48", "MAX_RANGE", "QT_NO_KEYWORDS", "SIM",
                                           "TOPIC", "USE_LASER"}));
        QCOMPARE(m.value("USE_LASER").body, QByteArray("1"));
        QCOMPARE(m.value("MAX_RANGE").body, QByteArray("30"));
        QCOMPARE(m.value("QT_NO_KEYWORDS").body, QByteArray("1"));
        QCOMPARE(m.value("TOPIC").body, QByteArray("\"scan\""));
        QCOMPARE(m.value("HAVE_DRAND48").body, QByteArray("1"));
        QCOMPARE(m.value("SIM").body, QByteArray("0"));
    }
};

QTEST_GUILESS_MAIN(TestCppPreprocessor)
#include "tst_cpppreprocessor.moc"
