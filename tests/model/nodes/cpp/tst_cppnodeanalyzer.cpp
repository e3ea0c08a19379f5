// The C++ analyzer on small fixture workspaces (tests/data/cpp_*/ws), field by field.
// tools/survey (rosarch-survey nodes <workspace>) prints what it finds in a real workspace.
#include "analysistext.h"
#include "nodes/cpp/cppnodeanalyzer.h"
#include "nodes/nodeanalyzer.h"
#include "support/cppanalysis.h"
#include "support/testsupport.h"
#include "workspace/workspacescanner.h"

#include <QMutex>
#include <QTemporaryDir>
#include <QtTest>

#include <atomic>

using namespace rosarch;
using namespace rosarch::test::cpp;

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
        // A constructor parameter: the instance decides; never the parameter's own name.
        QCOMPARE(base->nodeName, QString());
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

    // A local declared without a value and handed to a method (or a free function) that
    // assigns its reference parameter holds what the callee assigns; one handed to a function
    // taking a const reference, or assigned nothing, stays an expression.
    void namesThroughReferenceParameters()
    {
        const LanguageAnalysis fixture = analyzeCase(QStringLiteral("cpp_out_parameters"));
        const AtomicNode *guard = findNode(fixture, QStringLiteral("SpeedGuard"));
        QVERIFY(guard);
        QCOMPARE(resolvedPortNames(*guard),
                 (QStringList{QStringLiteral("cmd_vel_smoothed parameter input_topic"),
                              QStringLiteral("cmd_vel parameter output_topic"),
                              QStringLiteral("~/report parameter report_name"),
                              QStringLiteral("label expression")}));
        QCOMPARE(guard->ports[0].nameExpression, QStringLiteral("input_topic"));
        QCOMPARE(guard->ports[0].via, QStringLiteral("VelocityInput"));

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const LanguageAnalysis a = analyzeFile(
            dir, QStringLiteral("free.cpp"),
            "void load(rclcpp::Node & node, std::string & topic, std::string & unused) {\n"
            "  topic = node.declare_parameter(\"scan_topic\", std::string(\"scan\"));\n"
            "}\n"
            "class F : public rclcpp::Node {\npublic:\n  F() : Node(\"f\") {\n"
            "    std::string topic;\n    std::string other;\n"
            "    load(*this, topic, other);\n"
            "    a_ = create_publisher<std_msgs::msg::String>(topic, 1);\n"
            "    b_ = create_publisher<std_msgs::msg::String>(other, 1);\n"
            "    std::string given = \"given\";\n    load(*this, given, other);\n"
            "    c_ = create_publisher<std_msgs::msg::String>(given, 1);\n"
            "  }\n};\n");
        QCOMPARE(a.nodes.size(), 1);
        QCOMPARE(resolvedPortNames(a.nodes[0]),
                 (QStringList{QStringLiteral("scan parameter scan_topic"),
                              QStringLiteral("other expression"), QStringLiteral("given local")}));
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

    void stageOneReportsOneProgression()
    {
        // The status bar's bar fills once for stage 1: the Python files, then the C++ files.
        const Workspace ws = WorkspaceScanner::scan(test::dataDir(QStringLiteral("gui_ws")));
        int files = 0;
        for (const SourceFile &f : ws.files)
            files += f.language == SourceFile::Language::Python ||
                     f.language == SourceFile::Language::Cpp;
        QVERIFY(files >= 2);
        QMutex mutex;
        QList<std::pair<int, int>> reports;
        StageControl control;
        control.progressed = [&](int done, int total, const QString &) {
            const QMutexLocker lock(&mutex);
            reports.append({done, total});
        };
        const AtomicNodeList list = NodeAnalyzer::run(ws, control);
        QVERIFY(!list.nodes.isEmpty());
        QVERIFY(!reports.isEmpty());
        int last = 0;
        for (const auto &[done, total] : std::as_const(reports)) {
            QCOMPARE(total, files);
            QVERIFY2(done >= last, qPrintable(QStringLiteral("%1 after %2").arg(done).arg(last)));
            last = done;
        }
        QCOMPARE(last, files);
    }
};

QTEST_GUILESS_MAIN(TestCppNodeAnalyzer)
#include "tst_cppnodeanalyzer.moc"
