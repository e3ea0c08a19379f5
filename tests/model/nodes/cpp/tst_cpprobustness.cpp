// Parse robustness of the C++ analyzer: broken members and statements, grammar gaps, export
// and string macros, preprocessor conditionals.
#include "analysistext.h"
#include "nodes/cpp/cppnodeanalyzer.h"
#include "support/cppanalysis.h"
#include "support/testsupport.h"
#include "syntax/cppsyntax.h"
#include "syntax/syntaxtree.h"
#include "workspace/workspacescanner.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::cpp;

namespace {

QStringList portNames(const AtomicNode *n)
{
    QStringList names;
    if (n)
        for (const Port &p : n->ports)
            names.append(p.name);
    return names;
}

} // namespace

class TestCppRobustness : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void syntaxErrorKeepsTheRest()
    {
        const LanguageAnalysis a = analyzeCase(QStringLiteral("cpp_syntax_error"));
        QCOMPARE(classNames(a), (QStringList{QStringLiteral("broken_pkg/Fine"),
                                             QStringLiteral("broken_pkg/Survivor"),
                                             QStringLiteral("broken_pkg/Unfinished")}));
        QCOMPARE(a.diagnostics.size(), 1);
        QCOMPARE(a.diagnostics[0].code, QStringLiteral("syntax-error"));
        QCOMPARE(a.diagnostics[0].evidence.file, QStringLiteral("broken_pkg/src/half_written.cpp"));
        QCOMPARE(a.diagnostics[0].evidence.line, 13);
        QVERIFY2(a.diagnostics[0].message.endsWith(QLatin1String("the rest parses: line 13.")),
                 qPrintable(a.diagnostics[0].message));
        QCOMPARE(findNode(a, QStringLiteral("Survivor"))->ports.size(), 1);
        QCOMPARE(findNode(a, QStringLiteral("Unfinished"))->ports.value(0).name,
                 QStringLiteral("draft"));
        QCOMPARE(a.entryPoints.size(), 2);
    }

    // A broken member costs that member: the statement or line is blanked and the file parsed
    // again, so the class keeps its other members and the class after it is still found.
    void brokenMemberCostsOnlyItself()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const LanguageAnalysis a = analyzeFile(
            dir, QStringLiteral("n.cpp"),
            "class N : public rclcpp::Node\n"                                            // 1
            "{\n"                                                                        // 2
            "public:\n"                                                                  // 3
            "  N() : Node(\"n\")\n"                                                      // 4
            "  {\n"                                                                      // 5
            "    a_ = create_publisher<std_msgs::msg::String>(\"before\", 10);\n"        // 6
            "    b_ = create_publisher<std_msgs::msg::String>(\"same_function\", 10);\n" // 7
            "  }\n"                                                                      // 8
            "  void broken() { int x = ; foo(}; }\n"                                     // 9
            "  void later()\n"                                                           // 10
            "  {\n"                                                                      // 11
            "    c_ = create_subscription<std_msgs::msg::String>(\"after\", 10, cb);\n"  // 12
            "  }\n"                                                                      // 13
            "  int max_;\n"                                                              // 14
            "};\n"                                                                       // 15
            "class M : public rclcpp::Node\n"                                            // 16
            "{\n"                                                                        // 17
            "public:\n"                                                                  // 18
            "  M() : Node(\"m\") { d_ = create_publisher<std_msgs::msg::Empty>(\"next\", 1); }\n"
            "};\n");
        QCOMPARE(classNames(a), (QStringList{QStringLiteral("pkg/M"), QStringLiteral("pkg/N")}));
        QCOMPARE(portNames(findNode(a, QStringLiteral("N"))),
                 (QStringList{QStringLiteral("before"), QStringLiteral("same_function"),
                              QStringLiteral("after")}));
        QCOMPARE(portNames(findNode(a, QStringLiteral("M"))), QStringList{QStringLiteral("next")});
        QCOMPARE(a.diagnostics.size(), 1);
        const Diagnostic &d = a.diagnostics.first();
        QCOMPARE(d.code, QStringLiteral("syntax-error"));
        QCOMPARE(d.evidence.line, 9);
        QVERIFY2(d.message.endsWith(QLatin1String("the rest parses: line 9.")),
                 qPrintable(d.message));
        // Evidence after the blanked line is where it was written.
        QCOMPARE(findNode(a, QStringLiteral("N"))->ports.value(2).evidence.line, 12);
        QCOMPARE(findNode(a, QStringLiteral("N"))->ports.value(2).evidence.column, 10);
    }

    // Balanced braces: only the broken statement goes, the rest of its function stays.
    void brokenStatementCostsOnlyItself()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const LanguageAnalysis a = analyzeFile(
            dir, QStringLiteral("s.cpp"),
            "struct S : rclcpp::Node\n"                                                      // 1
            "{\n"                                                                            // 2
            "  S() : Node(\"s\")\n"                                                          // 3
            "  {\n"                                                                          // 4
            "    int x = (3 + ;\n"                                                           // 5
            "    a_ = create_publisher<std_msgs::msg::String>(\"kept\", 10);\n"              // 6
            "  }\n"                                                                          // 7
            "  void more() { b_ = create_publisher<std_msgs::msg::String>(\"also\", 1); }\n" // 8
            "};\n");
        QCOMPARE(classNames(a), QStringList{QStringLiteral("pkg/S")});
        QCOMPARE(portNames(findNode(a, QStringLiteral("S"))),
                 (QStringList{QStringLiteral("kept"), QStringLiteral("also")}));
        QCOMPARE(a.diagnostics.size(), 1);
        QVERIFY2(a.diagnostics[0].message.endsWith(QLatin1String("the rest parses: line 5.")),
                 qPrintable(a.diagnostics[0].message));
    }

    // A function-like macro that wraps a string names a port through its expansion.
    void stringMacrosNamePorts()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const LanguageAnalysis a = analyzeFile(
            dir, QStringLiteral("m.cpp"),
            "#define ROBOT \"robot\"\n"                                                  // 1
            "#define TOPIC(x) ROBOT \"/\" x\n"                                           // 2
            "#define NS(x) \"ns/\" #x\n"                                                 // 3
            "class M : public rclcpp::Node\n"                                            // 4
            "{\n"                                                                        // 5
            "public:\n"                                                                  // 6
            "  M() : Node(\"m\")\n"                                                      // 7
            "  {\n"                                                                      // 8
            "    a_ = create_publisher<std_msgs::msg::String>(TOPIC(\"status\"), 10);\n" // 9
            "    b_ = create_publisher<std_msgs::msg::String>(NS(odom), 10);\n"          // 10
            "    c_ = create_publisher<std_msgs::msg::String>(TOPIC(name_), 10);\n"      // 11
            "  }\n"                                                                      // 12
            "};\n");
        const AtomicNode *m = findNode(a, QStringLiteral("M"));
        QVERIFY(m);
        QCOMPARE(m->ports.size(), 3);
        QCOMPARE(m->ports[0].name, QStringLiteral("robot/status"));
        QCOMPARE(m->ports[0].nameOrigin, NameOrigin::Literal);
        QCOMPARE(m->ports[0].evidence.line, 9);
        QCOMPARE(m->ports[0].evidence.column, 10);
        QCOMPARE(m->ports[1].name, QStringLiteral("ns/odom"));
        QVERIFY(m->ports[2].nameOrigin != NameOrigin::Literal); // a variable is not expanded
    }

    // Ports behind #if, a class whose branches open braces differently, macros as names; the
    // ports themselves are in tests/data/cpp_preprocessor/expected.
    void conditionalCompilation()
    {
        const LanguageAnalysis a = analyzeCase(QStringLiteral("cpp_preprocessor"));
        QCOMPARE(classNames(a), (QStringList{QStringLiteral("rover_base/RoverDriver"),
                                             QStringLiteral("rover_base/StatusReporter")}));
        QCOMPARE(a.diagnostics.size(), 1);
        const Diagnostic &guess = a.diagnostics.first();
        QCOMPARE(guess.code, QStringLiteral("preprocessor-guess"));
        QCOMPARE(guess.severity, Diagnostic::Severity::Info);
        QCOMPARE(guess.evidence.file, QStringLiteral("src/rover_base/src/rover_driver.cpp"));
        QCOMPARE(guess.evidence.line, 45);
        QVERIFY(guess.message.contains(QStringLiteral("RCLCPP_VERSION_GTE(28, 0, 0)")));
        const AtomicNode *driver = findNode(a, QStringLiteral("RoverDriver"));
        QVERIFY(driver);
        QStringList names;
        for (const Port &p : driver->ports)
            names << p.name;
        QCOMPARE(names, (QStringList{QStringLiteral("odom"), QStringLiteral("cmd_vel"),
                                     QStringLiteral("scan"), QStringLiteral("emergency_stop")}));
    }

    void macroNoiseIsNotAnError()
    {
        // Format macros after strings, export macros, a registration without ';'.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile f(dir.filePath(QStringLiteral("noisy.cpp")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("#include <cinttypes>\n"
                "class NOISY_PUBLIC Noisy : public rclcpp::Node\n"
                "{\n"
                "public:\n"
                "  NOISY_PUBLIC\n"
                "  explicit Noisy(const rclcpp::NodeOptions & o)\n"
                "  : Node(\"noisy\", o)\n"
                "  {\n"
                "    RCLCPP_INFO(get_logger(), \"%\" PRId64, count_);\n"
                "    pub_ = create_publisher<std_msgs::msg::Int64>(\"count\", 1);\n"
                "  }\n"
                "  int64_t count_ = 0;\n"
                "};\n"
                "RCLCPP_COMPONENTS_REGISTER_NODE(Noisy)\n");
        f.close();
        Workspace ws;
        ws.root = dir.path();
        ws.files.append({QStringLiteral("noisy.cpp"), QStringLiteral("noisy_pkg"),
                         SourceFile::Language::Cpp, f.size()});
        const LanguageAnalysis a = CppNodeAnalyzer(ws).analyze();
        QVERIFY2(a.diagnostics.isEmpty(), qPrintable(AnalysisText::analysis(a)));
        QCOMPARE(a.nodes.size(), 1);
        QCOMPARE(a.nodes[0].nodeName, QStringLiteral("noisy"));
        QCOMPARE(a.nodes[0].packageName, QStringLiteral("noisy_pkg"));
        QCOMPARE(a.nodes[0].ports.value(0).type, QStringLiteral("std_msgs/msg/Int64"));
        QCOMPARE(a.registrations.size(), 1);
        QCOMPARE(a.registrations[0].evidence.line, 14);
    }

    // Valid C++ the grammar cannot read is rewritten in place, so it parses without errors and
    // every offset stays.
    void grammarGapsAreBlanked()
    {
        QByteArray src("void f(Border<T> border = {}, int n = 1)\n"
                       "{\n"
                       "  a = new double *[n + 2];\n"
                       "  b = new double *[n]();\n"
                       "  goal_ = typename ActionT::Goal();\n"
                       "  r = typename ns::Handle<ActionT>::Result();\n"
                       "  g->setPose(typename NodeT::Coordinates(mx, my));\n"
                       "  bb->template set(\"node\", c);\n"
                       "  bb->template get<int>(\"node\");\n"
                       "  x = {};\n"
                       "}\n");
        const QByteArray before = src;
        cppsyntax::blankGrammarGaps(&src);
        QCOMPARE(src.size(), before.size());
        QCOMPARE(src, QByteArray("void f(Border<T> border = 0 , int n = 1)\n"
                                 "{\n"
                                 "  a = new double  [n + 2];\n"
                                 "  b = new double  [n]  ;\n"
                                 "  goal_ =          ActionT::Goal();\n"
                                 "  r =          ns::Handle<ActionT>::Result();\n"
                                 "  g->setPose(         NodeT::Coordinates(mx, my));\n"
                                 "  bb->         set(\"node\", c);\n"
                                 "  bb->template get<int>(\"node\");\n"
                                 "  x = {};\n"
                                 "}\n"));
        const SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Cpp, src, QString());
        QVERIFY(!ts_node_has_error(tree.root()));
    }

    void exportMacrosAreBlanked()
    {
        QByteArray src(
            "#define FOO_PUBLIC __attribute__((visibility(\"default\")))\n"
            "class FOO_PUBLIC Foo { FOO_PUBLIC void f(const char *s = \"BAR_PUBLIC\"); };\n");
        const QByteArray before = src;
        cppsyntax::blankExportMacros(&src);
        QCOMPARE(src.size(), before.size());
        QVERIFY(src.startsWith("#define FOO_PUBLIC")); // preprocessor lines stay
        QVERIFY(src.contains(
            "class            Foo {            void f(const char *s = \"BAR_PUBLIC\"); };"));
        // PCL's export macro and CUDA's function qualifiers have no visibility suffix.
        QByteArray attributes("template <>\n"
                              "class PCL_EXPORTS PassThrough<pcl::PCLPointCloud2> : public F {};\n"
                              "void __device__ setCellValue(float wx);\n"
                              "__global__ void kernel(int * __restrict__ a);\n");
        cppsyntax::blankExportMacros(&attributes);
        QCOMPARE(attributes, QByteArray("template <>\n"
                                        "class             PassThrough<pcl::PCLPointCloud2> : "
                                        "public F {};\n"
                                        "void            setCellValue(float wx);\n"
                                        "           void kernel(int * __restrict__ a);\n"));
        QVERIFY(!ts_node_has_error(
            SyntaxTree::parse(SyntaxTree::Grammar::Cpp, attributes, QString()).root()));
        // Values are enumerators or constants, whatever their suffix.
        QByteArray values("auto d = RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL;\n"
                          "EXPECT_EQ(q.durability, RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL);\n");
        const QByteArray unchanged = values;
        cppsyntax::blankExportMacros(&values);
        QCOMPARE(values, unchanged);
    }
};

QTEST_GUILESS_MAIN(TestCppRobustness)
#include "tst_cpprobustness.moc"
