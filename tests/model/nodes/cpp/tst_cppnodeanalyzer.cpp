// The C++ analyzer on small fixture workspaces (tests/data/cpp_*/ws), field by field.
// tools/survey (rosarch-survey nodes <workspace>) prints what it finds in a real workspace.
#include "analysistext.h"
#include "cppanalysis.h"
#include "cppnodeanalyzer.h"
#include "cppsyntax.h"
#include "syntaxtree.h"
#include "testsupport.h"
#include "workspacescanner.h"

#include <QTemporaryDir>
#include <QtTest>

#include <atomic>

using namespace rosarch;
using namespace rosarch::test::cpp;

namespace {

// The analysis of a workspace holding one C++ file of package `pkg`.
LanguageAnalysis analyzeFile(const QTemporaryDir &dir, const QString &name,
                             const QByteArray &content)
{
    QFile f(dir.filePath(name));
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(content);
    f.close();
    Workspace ws;
    ws.root = dir.path();
    ws.files.append({name, QStringLiteral("pkg"), SourceFile::Language::Cpp, f.size()});
    return CppNodeAnalyzer(ws).analyze();
}

QStringList portNames(const AtomicNode *n)
{
    QStringList names;
    if (n)
        for (const Port &p : n->ports)
            names.append(p.name);
    return names;
}

} // namespace

class TestCppNodeAnalyzer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void basicStyles()
    {
        const LanguageAnalysis a = analyzeCase(QStringLiteral("cpp_basic"));
        QCOMPARE(classNames(a), (QStringList{QStringLiteral("demo_cpp/Listener"),
                                             QStringLiteral("demo_cpp/Talker"),
                                             QStringLiteral("demo_cpp/old_school")}));
        QVERIFY2(a.diagnostics.isEmpty(), qPrintable(AnalysisText::analysis(a)));

        // Declared in a header, defined out of line, export macro before the constructor.
        const AtomicNode *talker = findNode(a, QStringLiteral("Talker"));
        QVERIFY(talker);
        QCOMPARE(talker->qualifiedName, QStringLiteral("demo_cpp::Talker"));
        QCOMPARE(talker->nodeName, QStringLiteral("talker"));
        QCOMPARE(talker->compileType, AtomicNode::CompileType::Cpp);
        QCOMPARE(talker->baseClasses, QStringList{QStringLiteral("rclcpp::Node")});
        QCOMPARE(talker->headerFiles,
                 QStringList{QStringLiteral("src/demo_cpp/include/demo_cpp/talker.hpp")});
        QCOMPARE(talker->sourceFiles, QStringList{QStringLiteral("src/demo_cpp/src/talker.cpp")});
        QVERIFY(!talker->lifecycle);
        QVERIFY(!talker->procedural);
        QVERIFY(talker->id.isEmpty());
        QVERIFY(talker->executables.isEmpty());
        QCOMPARE(talker->evidence.file, QStringLiteral("src/demo_cpp/include/demo_cpp/talker.hpp"));
        QCOMPARE(talker->evidence.line, 14);
        QCOMPARE(talker->evidence.endLine, 30);
        QCOMPARE(
            describePorts(*talker),
            (QStringList{
                QStringLiteral("publisher chatter std_msgs/msg/String cb= origin=literal expr= "
                               "param= guard= gp= via= @src/demo_cpp/src/talker.cpp:17"),
                QStringLiteral("subscriber reset std_msgs/msg/Empty cb=on_reset origin=literal "
                               "expr= param= guard= gp= via= @src/demo_cpp/src/talker.cpp:18"),
            }));
        const Port &chatter = talker->ports.first();
        QCOMPARE(chatter.evidence.column, 10);
        QCOMPARE(chatter.evidence.endLine, 17);
        QVERIFY(chatter.id.isEmpty());

        // Lambda, and a variable holding a lambda.
        const AtomicNode *listener = findNode(a, QStringLiteral("Listener"));
        QVERIFY(listener);
        QCOMPARE(listener->qualifiedName, QStringLiteral("Listener"));
        QCOMPARE(listener->nodeName, QStringLiteral("listener"));
        QVERIFY(listener->headerFiles.isEmpty());
        QCOMPARE(listener->sourceFiles,
                 QStringList{QStringLiteral("src/demo_cpp/src/listener.cpp")});
        QCOMPARE(
            describePorts(*listener),
            (QStringList{
                QStringLiteral("subscriber chatter std_msgs/msg/String cb=lambda origin=literal "
                               "expr= param= guard= gp= via= @src/demo_cpp/src/listener.cpp:13"),
                QStringLiteral("subscriber echo std_msgs/msg/String cb=on_echo origin=literal "
                               "expr= param= guard= gp= via= @src/demo_cpp/src/listener.cpp:21"),
            }));

        // Procedural: className is the file stem, evidence the enclosing function.
        const AtomicNode *oldSchool = findNode(a, QStringLiteral("old_school"));
        QVERIFY(oldSchool);
        QVERIFY(oldSchool->procedural);
        QCOMPARE(oldSchool->nodeName, QStringLiteral("old_school"));
        QCOMPARE(oldSchool->evidence.line, 12);
        QCOMPARE(oldSchool->evidence.endLine, 21);
        QCOMPARE(describePorts(*oldSchool),
                 (QStringList{
                     QStringLiteral("publisher status std_msgs/msg/String cb= origin=literal expr= "
                                    "param= guard= gp= via= @src/demo_cpp/src/old_school.cpp:16"),
                     QStringLiteral(
                         "subscriber command std_msgs/msg/String cb=on_command origin=literal "
                         "expr= param= guard= gp= via= @src/demo_cpp/src/old_school.cpp:17"),
                 }));
    }

    void notNodes()
    {
        // BT::SyncActionNode subclasses, plain classes named *Node, and an unqualified `Node`
        // that no using-declaration ties to rclcpp are not ROS nodes.
        const LanguageAnalysis a = analyzeCase(QStringLiteral("cpp_basic"));
        QVERIFY(!findNode(a, QStringLiteral("SpinActionNode")));
        QVERIFY(!findNode(a, QStringLiteral("TreeNode")));
        QVERIFY(!findNode(a, QStringLiteral("GraphNode")));
        const LanguageAnalysis inherit = analyzeCase(QStringLiteral("cpp_inherit"));
        QVERIFY(!findNode(inherit, QStringLiteral("BtActionNode")));
    }

    void entryPointsAndRegistrations()
    {
        const LanguageAnalysis a = analyzeCase(QStringLiteral("cpp_basic"));
        QCOMPARE(a.entryPoints.size(), 2); // trees.cpp's main instantiates no node
        QCOMPARE(a.entryPoints[0].file, QStringLiteral("src/demo_cpp/src/listener.cpp"));
        QCOMPARE(a.entryPoints[0].function, QStringLiteral("main"));
        QCOMPARE(a.entryPoints[0].instantiatedClasses, QStringList{QStringLiteral("Listener")});
        QCOMPARE(a.entryPoints[0].evidence.line, 29);
        QCOMPARE(a.entryPoints[1].file, QStringLiteral("src/demo_cpp/src/old_school.cpp"));
        QCOMPARE(a.entryPoints[1].instantiatedClasses, QStringList{QStringLiteral("old_school")});
        QCOMPARE(a.registrations.size(), 1);
        QCOMPARE(a.registrations[0].pluginClass, QStringLiteral("demo_cpp::Talker"));
        QCOMPARE(a.registrations[0].file, QStringLiteral("src/demo_cpp/src/talker.cpp"));
        QCOMPARE(a.registrations[0].evidence.line, 37);
        QCOMPARE(a.registrations[0].evidence.column, 1);

        // X::make_shared(), std::make_shared<ns::X>() for two classes in one main.
        const LanguageAnalysis comm = analyzeCase(QStringLiteral("cpp_comm"));
        QStringList entries;
        for (const EntryPoint &e : comm.entryPoints)
            entries << e.file + QLatin1Char(':') + e.instantiatedClasses.join(QLatin1Char(','));
        QCOMPARE(entries,
                 (QStringList{
                     QStringLiteral("comm_demo/src/adder.cpp:Adder"),
                     QStringLiteral("comm_demo/src/camera.cpp:Camera"),
                     QStringLiteral(
                         "comm_demo/src/"
                         "fibonacci.cpp:comm_demo::FibonacciServer,comm_demo::FibonacciClient"),
                 }));
    }

    void lifecycleAndInheritance()
    {
        const LanguageAnalysis a = analyzeCase(QStringLiteral("cpp_inherit"));
        QCOMPARE(classNames(a), (QStringList{QStringLiteral("base_pkg/ManagedNode"),
                                             QStringLiteral("robot_pkg/Driver"),
                                             QStringLiteral("robot_pkg/SafeDriver")}));
        const AtomicNode *base = findNode(a, QStringLiteral("ManagedNode"));
        QVERIFY(base->lifecycle);
        QCOMPARE(base->nodeName,
                 QStringLiteral("name")); // a constructor parameter: kept as written
        QCOMPARE(
            describePorts(*base),
            QStringList{QStringLiteral("publisher /diagnostics diagnostic_msgs/msg/DiagnosticArray "
                                       "cb= origin=literal expr= param= guard= gp= via= "
                                       "@src/base_pkg/include/base_pkg/managed_node.hpp:19")});

        // Out-of-line on_configure with a return type alias; the base's port is inherited.
        const AtomicNode *driver = findNode(a, QStringLiteral("Driver"));
        QVERIFY(driver->lifecycle);
        QCOMPARE(driver->qualifiedName, QStringLiteral("robot_pkg::Driver"));
        QCOMPARE(driver->baseClasses, QStringList{QStringLiteral("base_pkg::ManagedNode")});
        QCOMPARE(driver->nodeName, QStringLiteral("driver"));
        QCOMPARE(driver->headerFiles,
                 QStringList{QStringLiteral("src/robot_pkg/include/robot_pkg/driver.hpp")});
        QCOMPARE(driver->sourceFiles, QStringList{QStringLiteral("src/robot_pkg/src/driver.cpp")});
        QCOMPARE(describePorts(*driver),
                 (QStringList{
                     QStringLiteral("publisher /diagnostics diagnostic_msgs/msg/DiagnosticArray "
                                    "cb= origin=literal expr= param= guard= gp= via= inherited "
                                    "@src/base_pkg/include/base_pkg/managed_node.hpp:19"),
                     QStringLiteral(
                         "subscriber cmd_vel geometry_msgs/msg/Twist cb=on_cmd_vel origin=literal "
                         "expr= param= guard= gp= via= @src/robot_pkg/src/driver.cpp:15"),
                     QStringLiteral("publisher odom nav_msgs/msg/Odometry cb= origin=literal expr= "
                                    "param= guard= gp= via= @src/robot_pkg/src/driver.cpp:17"),
                 }));

        // Two levels down; no base initializer, so Driver's default constructor names it.
        const AtomicNode *safe = findNode(a, QStringLiteral("SafeDriver"));
        QVERIFY(safe->lifecycle);
        QCOMPARE(safe->nodeName, QStringLiteral("driver"));
        QCOMPARE(safe->ports.size(), 4);
        QVERIFY(safe->ports[0].inherited && safe->ports[1].inherited && safe->ports[2].inherited);
        QVERIFY(!safe->ports[3].inherited);
        QCOMPARE(safe->ports[3].name, QStringLiteral("emergency_stop"));

        QCOMPARE(a.entryPoints.size(), 1);
        QCOMPARE(a.entryPoints[0].instantiatedClasses,
                 QStringList{QStringLiteral("robot_pkg::Driver")});
    }

    void servicesActionsAndTypes()
    {
        const LanguageAnalysis a = analyzeCase(QStringLiteral("cpp_comm"));
        QCOMPARE(classNames(a),
                 (QStringList{QStringLiteral("comm_demo/Adder"), QStringLiteral("comm_demo/Camera"),
                              QStringLiteral("comm_demo/FibonacciClient"),
                              QStringLiteral("comm_demo/FibonacciServer")}));
        // `class Adder : public Node` with `using rclcpp::Node`; typedef and using aliases.
        const AtomicNode *adder = findNode(a, QStringLiteral("Adder"));
        QCOMPARE(adder->baseClasses, QStringList{QStringLiteral("Node")});
        QCOMPARE(
            describePorts(*adder),
            (QStringList{
                QStringLiteral(
                    "service_server add_two_ints example_interfaces/srv/AddTwoInts cb=handle_add "
                    "origin=literal expr= param= guard= gp= via= @comm_demo/src/adder.cpp:18"),
                QStringLiteral(
                    "service_client remote/add_two_ints example_interfaces/srv/AddTwoInts cb= "
                    "origin=literal expr= param= guard= gp= via= @comm_demo/src/adder.cpp:21"),
            }));
        // create_server(this, ...) names handle_goal; the four-interface form and lambdas.
        const AtomicNode *server = findNode(a, QStringLiteral("FibonacciServer"));
        QCOMPARE(
            describePorts(*server),
            (QStringList{
                QStringLiteral(
                    "action_server fibonacci example_interfaces/action/Fibonacci cb=handle_goal "
                    "origin=literal expr= param= guard= gp= via= @comm_demo/src/fibonacci.cpp:20"),
                QStringLiteral(
                    "action_server fibonacci_legacy example_interfaces/action/Fibonacci cb=lambda "
                    "origin=literal expr= param= guard= gp= via= @comm_demo/src/fibonacci.cpp:26"),
            }));
        const AtomicNode *client = findNode(a, QStringLiteral("FibonacciClient"));
        QCOMPARE(
            describePorts(*client),
            QStringList{QStringLiteral(
                "action_client fibonacci example_interfaces/action/Fibonacci cb= origin=literal "
                "expr= param= guard= gp= via= @comm_demo/src/fibonacci.cpp:59")});
        // image_transport: free function and ImageTransport::advertise.
        const AtomicNode *camera = findNode(a, QStringLiteral("Camera"));
        QCOMPARE(describePorts(*camera),
                 (QStringList{
                     QStringLiteral("publisher image_raw sensor_msgs/msg/Image cb= origin=literal "
                                    "expr= param= guard= gp= via= @comm_demo/src/camera.cpp:14"),
                     QStringLiteral(
                         "publisher camera_info sensor_msgs/msg/CameraInfo cb= origin=literal "
                         "expr= param= guard= gp= via= @comm_demo/src/camera.cpp:15"),
                     QStringLiteral("publisher preview sensor_msgs/msg/Image cb= origin=literal "
                                    "expr= param= guard= gp= via= @comm_demo/src/camera.cpp:21"),
                 }));
    }

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

    // point_cloud_transport: PointCloudTransport::subscribe / advertise through a member or a
    // local, and the free functions; the type is always sensor_msgs/msg/PointCloud2.
    void pointCloudTransport()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const LanguageAnalysis a = analyzeFile(
            dir, QStringLiteral("cloud.cpp"),
            "class Cloud : public rclcpp::Node\n" // 1
            "{\n"                                 // 2
            "public:\n"                           // 3
            "  Cloud() : Node(\"cloud\")\n"       // 4
            "  {\n"                               // 5
            "    pct_ = std::make_shared<point_cloud_transport::PointCloudTransport>(*this);\n"
            "    sub_ = pct_->subscribe(\"points\", rclcpp::SensorDataQoS(),\n"             // 7
            "      std::bind(&Cloud::onPoints, this, std::placeholders::_1), {}, &hint);\n" // 8
            "    point_cloud_transport::PointCloudTransport transport(*this);\n"            // 9
            "    pub_ = transport.advertise(\"filtered\", 10);\n"                           // 10
            "    raw_ = point_cloud_transport::create_subscription(\n"                      // 11
            "      this, \"raw\", std::bind(&Cloud::onRaw, this, std::placeholders::_1), "
            "\"raw\");\n"
            "    out_ = point_cloud_transport::create_publisher(this, \"out\");\n" // 13
            "  }\n"                                                                // 14
            "};\n");
        const AtomicNode *cloud = findNode(a, QStringLiteral("Cloud"));
        QVERIFY(cloud);
        QCOMPARE(describePorts(*cloud),
                 (QStringList{
                     QStringLiteral("subscriber points sensor_msgs/msg/PointCloud2 cb=onPoints "
                                    "origin=literal expr= param= guard= gp= via= @cloud.cpp:7"),
                     QStringLiteral("publisher filtered sensor_msgs/msg/PointCloud2 cb= "
                                    "origin=literal expr= param= guard= gp= via= @cloud.cpp:10"),
                     QStringLiteral("subscriber raw sensor_msgs/msg/PointCloud2 cb=onRaw "
                                    "origin=literal expr= param= guard= gp= via= @cloud.cpp:11"),
                     QStringLiteral("publisher out sensor_msgs/msg/PointCloud2 cb= "
                                    "origin=literal expr= param= guard= gp= via= @cloud.cpp:13"),
                 }));
        QCOMPARE(cloud->ports.value(0).qos, QStringLiteral("rclcpp::SensorDataQoS()"));
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

    void moreCallForms()
    {
        // Entry points through new / make_unique / a local object; member-function-pointer and
        // free-function callbacks; generic publishers; rclcpp::create_publisher(node, ...).
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile f(dir.filePath(QStringLiteral("forms.cpp")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "namespace forms {\n"                                                               // 1
            "class A : public rclcpp::Node {\n"                                                 // 2
            "public:\n"                                                                         // 3
            "  A() : rclcpp::Node(\"a\") {\n"                                                   // 4
            "    sub_ = create_subscription<std_msgs::msg::Bool>(\"flag\", 1, &A::on_flag);\n"  // 5
            "    gen_ = create_generic_publisher(\"raw\", \"std_msgs/msg/String\", 1);\n"       // 6
            "    old_ = rclcpp::create_publisher<std_msgs::msg::Int32>(this, \"legacy\", 1);\n" // 7
            "  }\n"                                                                             // 8
            "  void on_flag(std_msgs::msg::Bool::ConstSharedPtr) {}\n"                          // 9
            "};\n"                                                                   // 10
            "struct B : rclcpp::Node { B() : Node(\"b\") {} };\n"                    // 11
            "struct C : public rclcpp::Node { explicit C(int) : Node(\"c\") {} };\n" // 12
            "}  // namespace forms\n"                                                // 13
            "int main() {\n"                                                         // 14
            "  auto a = std::make_unique<forms::A>();\n"                             // 15
            "  forms::B * b = new forms::B();\n"                                     // 16
            "  forms::C c(3);\n"                                                     // 17
            "  return 0;\n"                                                          // 18
            "}\n");
        f.close();
        Workspace ws;
        ws.root = dir.path();
        ws.files.append({QStringLiteral("forms.cpp"), QStringLiteral("forms"),
                         SourceFile::Language::Cpp, f.size()});
        const LanguageAnalysis a = CppNodeAnalyzer(ws).analyze();
        QCOMPARE(classNames(a), (QStringList{QStringLiteral("forms/A"), QStringLiteral("forms/B"),
                                             QStringLiteral("forms/C")}));
        QCOMPARE(describePorts(a.nodes[0]),
                 (QStringList{
                     QStringLiteral("subscriber flag std_msgs/msg/Bool cb=on_flag origin=literal "
                                    "expr= param= guard= gp= via= @forms.cpp:5"),
                     QStringLiteral("publisher raw std_msgs/msg/String cb= origin=literal expr= "
                                    "param= guard= gp= via= @forms.cpp:6"),
                     QStringLiteral("publisher legacy std_msgs/msg/Int32 cb= origin=literal expr= "
                                    "param= guard= gp= via= @forms.cpp:7"),
                 }));
        QCOMPARE(a.nodes[1].nodeName, QStringLiteral("b"));
        QCOMPARE(a.entryPoints.size(), 1);
        QCOMPARE(a.entryPoints[0].instantiatedClasses,
                 (QStringList{QStringLiteral("forms::A"), QStringLiteral("forms::B"),
                              QStringLiteral("forms::C")}));
        QCOMPARE(a.entryPoints[0].evidence.line, 14);
    }

    void unreadableFiles()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile bin(dir.filePath(QStringLiteral("blob.cpp")));
        QVERIFY(bin.open(QIODevice::WriteOnly));
        bin.write(QByteArray("class A : public rclcpp::Node {};\0\0\0", 37));
        bin.close();
        Workspace ws;
        ws.root = dir.path();
        ws.files.append({QStringLiteral("blob.cpp"), QString(), SourceFile::Language::Cpp, 37});
        ws.files.append({QStringLiteral("missing.hpp"), QString(), SourceFile::Language::Cpp, 0});
        ws.files.append({QStringLiteral("script.py"), QString(), SourceFile::Language::Python, 0});
        const LanguageAnalysis a = CppNodeAnalyzer(ws).analyze();
        QVERIFY(a.nodes.isEmpty());
        QCOMPARE(a.diagnostics.size(), 2);
        QCOMPARE(a.diagnostics[0].code, QStringLiteral("binary-file"));
        QCOMPARE(a.diagnostics[1].code, QStringLiteral("unreadable-file"));
        QCOMPARE(a.diagnostics[1].evidence.file, QStringLiteral("missing.hpp"));
    }

    void deterministicProgressAndCancel()
    {
        const Workspace ws =
            WorkspaceScanner::scan(test::dataDir(QStringLiteral("cpp_helpers/ws")));
        int cppFiles = 0;
        for (const SourceFile &f : ws.files)
            cppFiles += f.language == SourceFile::Language::Cpp ? 1 : 0;
        QCOMPARE(cppFiles, 9);

        std::atomic<int> reports{0};
        std::atomic<int> lastTotal{0};
        StageControl control;
        control.progressed = [&](int, int total, const QString &) {
            ++reports;
            lastTotal = total;
        };
        const LanguageAnalysis first = CppNodeAnalyzer(ws).analyze(control);
        QCOMPARE(reports.load(), cppFiles);
        QCOMPARE(lastTotal.load(), cppFiles);
        const LanguageAnalysis second = CppNodeAnalyzer(ws).analyze();
        QCOMPARE(AnalysisText::analysis(first), AnalysisText::analysis(second));
        QVERIFY(first.nodes == second.nodes);

        StageControl cancel;
        cancel.canceled = [] { return true; };
        const LanguageAnalysis canceled = CppNodeAnalyzer(ws).analyze(cancel);
        QVERIFY(canceled.nodes.isEmpty());
        QVERIFY(canceled.entryPoints.isEmpty());
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
        // Values are enumerators or constants, whatever their suffix.
        QByteArray values("auto d = RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL;\n"
                          "EXPECT_EQ(q.durability, RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL);\n");
        const QByteArray unchanged = values;
        cppsyntax::blankExportMacros(&values);
        QCOMPARE(values, unchanged);
    }
};

QTEST_GUILESS_MAIN(TestCppNodeAnalyzer)
#include "tst_cppnodeanalyzer.moc"
