// How the C++ analyzer resolves names: port names from literals, locals, members, parameters
// and expressions, names handed through helper classes and methods, and interface types.
#include "nodes/cpp/cppnameresolver.h"
#include "nodes/cpp/cppnodeanalyzer.h"
#include "support/cppanalysis.h"
#include "support/testsupport.h"
#include "syntax/cppsyntax.h"

#include <QTemporaryDir>
#include <QtTest>

#include <array>

using namespace rosarch;
using namespace rosarch::test::cpp;

namespace {

// Analyses files written into a temporary workspace: (path, package, content) triples.
LanguageAnalysis analyzeFiles(const QList<std::array<QByteArray, 3>> &files)
{
    QTemporaryDir dir;
    Workspace ws;
    ws.root = dir.path();
    for (const auto &[path, package, content] : files) {
        const QString rel = QString::fromUtf8(path);
        QDir().mkpath(QFileInfo(dir.filePath(rel)).path());
        QFile f(dir.filePath(rel));
        if (!f.open(QIODevice::WriteOnly))
            return {};
        f.write(content);
        ws.files.append({rel, QString::fromUtf8(package), SourceFile::Language::Cpp, f.size()});
    }
    return CppNodeAnalyzer(ws).analyze();
}

// A node publishing on each of `names` (expressions) after the statements `prelude`, with
// `members` declared in the class.
QByteArray publishingNode(const QByteArrayList &names, const QByteArray &members = {},
                          const QByteArray &prelude = {})
{
    QByteArray body = prelude;
    for (const QByteArray &n : names)
        body += "    pubs_.push_back(create_publisher<std_msgs::msg::String>(" + n + ", 1));\n";
    return "class N : public rclcpp::Node {\npublic:\n  N() : Node(\"n\") {\n" + body + "  }\n" +
           members + "};\n";
}

QStringList resolvedNames(const LanguageAnalysis &a)
{
    QStringList out;
    for (const AtomicNode &n : a.nodes)
        out += resolvedPortNames(n);
    return out;
}

} // namespace

class TestCppNameResolution : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    // A controller reads fields of a struct its parameter handler fills (another class, another
    // file); constants of another package; std::format, fmt::format, std::string, to_string.
    void namesFromElsewhere()
    {
        const LanguageAnalysis a = analyzeCase(QStringLiteral("cpp_names_deep"));
        QCOMPARE(classNames(a), QStringList{QStringLiteral("deep_controller/ControllerServer")});
        const QString f = QStringLiteral("src/deep_controller/src/controller_server.cpp");
        QCOMPARE(
            describePorts(a.nodes[0]).mid(0, 3),
            (QStringList{
                QStringLiteral("subscriber odom nav_msgs/msg/Odometry cb=lambda origin=parameter "
                               "expr=params_->odom_topic param=odom_topic guard= gp= via= @%1:45")
                    .arg(f),
                QStringLiteral("subscriber speed_limit std_msgs/msg/Float64 cb=lambda "
                               "origin=parameter expr=params_->speed_limit_topic "
                               "param=speed_limit_topic guard= gp= via= @%1:47")
                    .arg(f),
                QStringLiteral("publisher base_link/pose geometry_msgs/msg/PoseStamped cb= "
                               "origin=parameter expr=params_->base_frame + \"/pose\" "
                               "param=base_frame guard= gp= via= @%1:49")
                    .arg(f),
            }));
        QCOMPARE(resolvedNames(a).mid(3),
                 (QStringList{
                     QStringLiteral("cmd_vel member"),
                     QStringLiteral("alarm local"),
                     QStringLiteral("status local"),
                     QStringLiteral("heartbeat member"),
                     QStringLiteral("robot1/diagnostics parameter robot_name"),
                     QStringLiteral("~/wheels/rate_2 local"),
                     QStringLiteral("robot/1/state local"),
                     QStringLiteral("request->pose_topic expression"),
                 }));
    }

    // Fields found by the object's struct type, and by the field's name in the package when
    // a type is unknown; one name filled from two parameters, or a field of another package's
    // untyped object, decides nothing.
    void structFields()
    {
        const QByteArray handler =
            "template<typename T> struct Holder { T params_; };\n"
            "struct Params { std::string in; std::string out; std::string both; };\n"
            "struct Other { std::string both; };\n"
            "class Handler : public Holder<Params> {\npublic:\n"
            "  Handler(rclcpp::Node * node) {\n"
            "    params_.in = node->declare_parameter(\"in_topic\", \"in\");\n"
            "    node->declare_parameter(\"out_topic\", std::string(\"out\"));\n"
            "    node->get_parameter(\"out_topic\", params_.out);\n"
            "    params_.both = node->declare_parameter(\"both_a\", \"a\");\n"
            "    other_.both = node->declare_parameter(\"both_b\", \"b\");\n"
            "  }\n  Other other_;\n};\n";
        const QByteArray node = publishingNode(
            {"params_->in", "params_->out", "params_->both", "other_.both", "handler_->get()->in",
             "p.in", "q.in"},
            "  Params * params_;\n  Other other_;\n  std::shared_ptr<Handler> handler_;\n",
            "    Params p;\n    auto & q = params_;\n");
        const LanguageAnalysis a =
            analyzeFiles({{"a/handler.hpp", "a", handler}, {"a/node.cpp", "a", node}});
        QCOMPARE(resolvedNames(a), (QStringList{
                                       QStringLiteral("in parameter in_topic"),
                                       QStringLiteral("out parameter out_topic"),
                                       // typed Params: the untyped both_a binding, not Other's
                                       QStringLiteral("a parameter both_a"),
                                       QStringLiteral("b parameter both_b"),
                                       QStringLiteral("in parameter in_topic"),
                                       // a local of the struct's type, a reference to the member
                                       QStringLiteral("in parameter in_topic"),
                                       QStringLiteral("in parameter in_topic"),
                                   }));
        // Another package reading an object of unknown type learns nothing from package a.
        const LanguageAnalysis b =
            analyzeFiles({{"a/handler.hpp", "a", handler},
                          {"b/node.cpp", "b",
                           publishingNode({"handler_->get()->in", "cfg_.in"},
                                          "  std::shared_ptr<Handler> handler_;\n"
                                          "  Cfg cfg_;\n")}});
        QCOMPARE(resolvedNames(b), (QStringList{QStringLiteral("handler_->get()->in expression"),
                                                QStringLiteral("cfg_.in expression")}));
    }

    // Namespace-level constants of any file: the package's own definition first; definitions
    // elsewhere only when they agree.
    void workspaceConstants()
    {
        const LanguageAnalysis a = analyzeFiles({
            {"a/topics.hpp", "a", "namespace a { constexpr char kTopic[] = \"mine\"; }\n"},
            {"b/topics.hpp", "b", "namespace b { constexpr char kTopic[] = \"theirs\"; }\n"},
            {"b/more.hpp", "b",
             "namespace b { const std::string kOnly = \"only\";\n"
             "struct Names { static constexpr const char * kStatic = \"static\"; }; }\n"},
            {"c/x.hpp", "c", "namespace c { constexpr char kSplit[] = \"x\"; }\n"},
            {"d/y.hpp", "d", "namespace d { constexpr char kSplit[] = \"y\"; }\n"},
            {"a/node.cpp", "a",
             publishingNode({"kTopic", "b::kOnly", "b::Names::kStatic", "kSplit",
                             "std::string(kOnly) + \"/\" + kTopic"})},
        });
        QCOMPARE(resolvedNames(a), (QStringList{
                                       QStringLiteral("mine local"),
                                       QStringLiteral("only local"),
                                       QStringLiteral("static member"),
                                       QStringLiteral("kSplit expression"),
                                       QStringLiteral("only/mine local"),
                                   }));
    }

    void formattedNames_data()
    {
        QTest::addColumn<QByteArray>("expression");
        QTest::addColumn<QString>("name");
        QTest::newRow("std::format")
            << QByteArray("std::format(\"{}/{}\", ns, \"scan\")") << "robot/scan local";
        QTest::newRow("fmt positional")
            << QByteArray("fmt::format(\"{1}_{0}\", ns, \"x\")") << "x_robot local";
        QTest::newRow("braces") << QByteArray("std::format(\"{{{}}}\", \"a\")") << "{a} literal";
        QTest::newRow("plain spec") << QByteArray("std::format(\"cam{0:}\", 3)") << "cam3 literal";
        QTest::newRow("spec") << QByteArray("std::format(\"cam{:02}\", 3)")
                              << "std::format(\"cam{:02}\", 3) expression";
        QTest::newRow("missing argument")
            << QByteArray("std::format(\"{}/{}\", ns)") << "std::format(\"{}/{}\", ns) expression";
        QTest::newRow("unknown part") << QByteArray("std::format(\"{}\", get_ns())")
                                      << "std::format(\"{}\", get_ns()) expression";
        QTest::newRow("to_string") << QByteArray("\"cam\" + std::to_string(2)") << "cam2 literal";
        QTest::newRow("to_string double") << QByteArray("\"cam\" + std::to_string(0.5)")
                                          << "\"cam\" + std::to_string(0.5) expression";
        QTest::newRow("c_str") << QByteArray("std::string(ns.c_str())") << "robot local";
        QTest::newRow("parameter")
            << QByteArray("std::format(\"{}/odom\", declare_parameter(\"ns\", \"r\"))")
            << "r/odom parameter ns";
    }

    // A loop counter's initial value is not its value in the body: `image_raw0` would be wrong.
    // Neither is a value set in a for statement's head or unbraced body (up to three levels
    // above the value), however the variable is declared or assigned.
    void loopCounter_data()
    {
        QTest::addColumn<QByteArray>("body");
        QTest::addColumn<QString>("name");
        QTest::newRow("declared in the head")
            << QByteArray("for (std::size_t i = 0; i < 3; ++i)\n"
                          "  pubs_.push_back(create_publisher<std_msgs::msg::String>(\n"
                          "    \"~/image_raw\" + std::to_string(i), 1));\n")
            << "\"~/image_raw\" + std::to_string(i) expression";
        QTest::newRow("constant") << QByteArray("const int first = 0;\n"
                                                "pub_ = create_publisher<std_msgs::msg::String>(\n"
                                                "  \"~/image_raw\" + std::to_string(first), 1);\n")
                                  << "~/image_raw0 local";
        QTest::newRow("assigned in the head")
            << QByteArray("int i = 4;\nfor (i = 0; i < 3; ++i) {}\n"
                          "pub_ = create_publisher<std_msgs::msg::String>(\n"
                          "  \"~/image_raw\" + std::to_string(i), 1);\n")
            << "\"~/image_raw\" + std::to_string(i) expression";
        QTest::newRow("assigned in the update")
            << QByteArray("int i = 4;\nfor (int k = 0; k < 3; i = 2) {}\n"
                          "pub_ = create_publisher<std_msgs::msg::String>(\n"
                          "  \"~/image_raw\" + std::to_string(i), 1);\n")
            << "\"~/image_raw\" + std::to_string(i) expression";
        QTest::newRow("unbraced body")
            << QByteArray("int i = 4;\nfor (int k = 0; k < 3; ++k) i = 2;\n"
                          "pub_ = create_publisher<std_msgs::msg::String>(\n"
                          "  \"~/image_raw\" + std::to_string(i), 1);\n")
            << "\"~/image_raw\" + std::to_string(i) expression";
        QTest::newRow("braced body")
            << QByteArray("int i = 4;\nfor (int k = 0; k < 3; ++k) { i = 2; }\n"
                          "pub_ = create_publisher<std_msgs::msg::String>(\n"
                          "  \"~/image_raw\" + std::to_string(i), 1);\n")
            << "~/image_raw2 local";
        QTest::newRow("compound assignment in the body")
            << QByteArray("int i = 4;\nfor (int k = 0; k < 3; ++k) i += 2;\n"
                          "pub_ = create_publisher<std_msgs::msg::String>(\n"
                          "  \"~/image_raw\" + std::to_string(i), 1);\n")
            << "\"~/image_raw\" + std::to_string(i) expression";
        QTest::newRow("compound assignment in a block")
            << QByteArray("int i = 4;\n{ i += 2; }\n"
                          "pub_ = create_publisher<std_msgs::msg::String>(\n"
                          "  \"~/image_raw\" + std::to_string(i), 1);\n")
            << "\"~/image_raw\" + std::to_string(i) expression";
        QTest::newRow("constructed")
            << QByteArray("for (int k = 0; k < 1; ++k) {}\nint i(3);\n"
                          "pub_ = create_publisher<std_msgs::msg::String>(\n"
                          "  \"~/image_raw\" + std::to_string(i), 1);\n")
            << "~/image_raw3 local";
    }

    void loopCounter()
    {
        QFETCH(QByteArray, body);
        QFETCH(QString, name);
        const QByteArray code =
            "class N : public rclcpp::Node {\npublic:\n  N() : Node(\"n\") {\n" + body +
            "  }\n};\n";
        QCOMPARE(resolvedNames(analyzeFiles({{"a/n.cpp", "a", code}})), QStringList{name});
    }

    void formattedNames()
    {
        QFETCH(QByteArray, expression);
        QFETCH(QString, name);
        const QByteArray code = "class N : public rclcpp::Node {\npublic:\n  N() : Node(\"n\") {\n"
                                "    const std::string ns = \"robot\";\n"
                                "    pub_ = create_publisher<std_msgs::msg::String>(" +
                                expression + ", 1);\n  }\n};\n";
        QCOMPARE(resolvedNames(analyzeFiles({{"a/n.cpp", "a", code}})), QStringList{name});
    }

    void portNames()
    {
        const LanguageAnalysis a = analyzeCase(QStringLiteral("cpp_names"));
        QCOMPARE(a.nodes.size(), 1);
        const QString f = QStringLiteral("names_demo/src/relay.cpp");
        QCOMPARE(
            describePorts(a.nodes[0]),
            (QStringList{
                QStringLiteral("subscriber local_in std_msgs/msg/String cb=on_in origin=local "
                               "expr=local_topic param= guard= gp= via= @%1:22")
                    .arg(f),
                QStringLiteral("publisher relayed std_msgs/msg/String cb= origin=member "
                               "expr=output_topic_ param= guard= gp= via= @%1:23")
                    .arg(f),
                QStringLiteral("publisher echo std_msgs/msg/String cb= origin=member "
                               "expr=echo_topic_ param= guard= gp= via= @%1:24")
                    .arg(f),
                QStringLiteral("publisher alarm std_msgs/msg/String cb= origin=parameter "
                               "expr=alarm_topic_ param=alarm_topic guard= gp= via= @%1:28")
                    .arg(f),
                QStringLiteral("publisher debug std_msgs/msg/String cb= origin=parameter "
                               "expr=debug_topic param=debug_topic guard= gp= via= @%1:31")
                    .arg(f),
                QStringLiteral("publisher log std_msgs/msg/String cb= origin=parameter "
                               "expr=get_parameter(\"log_topic\").as_string() param=log_topic "
                               "guard= gp= via= @%1:34")
                    .arg(f),
                QStringLiteral(
                    "service_server ~/reset std_srvs/srv/Trigger cb=on_reset origin=literal expr= "
                    "param= guard=use_service gp=use_service via= @%1:38")
                    .arg(f),
                QStringLiteral("subscriber ~/reset std_msgs/msg/String cb=on_in origin=literal "
                               "expr= param= guard=!(use_service) gp=use_service via= @%1:41")
                    .arg(f),
                QStringLiteral("publisher status std_msgs/msg/String cb= origin=local "
                               "expr=kStatusTopic param= guard= gp= via= @%1:44")
                    .arg(f),
                // get_name(): the running node's name, which each instance fills in
                QStringLiteral(
                    "publisher {node}/heartbeat std_msgs/msg/String cb= origin=member "
                    "expr=std::string(get_name()) + \"/heartbeat\" param= guard= gp= via= @%1:45")
                    .arg(f),
                QStringLiteral("publisher late std_msgs/msg/String cb= origin=member "
                               "expr=late_topic_ param= guard= gp= via= @%1:51")
                    .arg(f),
            }));
        QVERIFY(a.nodes[0].ports.last().isResolved());
        QVERIFY(a.nodes[0].ports[9].isResolved()); // a template each instance completes
        QVERIFY(a.nodes[0].ports[9].name.startsWith(QLatin1String(kNodeNamePlaceholder)));
    }

    void helpers()
    {
        const LanguageAnalysis a = analyzeCase(QStringLiteral("cpp_helpers"));
        QCOMPARE(classNames(a), (QStringList{QStringLiteral("helpers_demo/Bridge"),
                                             QStringLiteral("helpers_demo/Controller"),
                                             QStringLiteral("helpers_demo/Docker"),
                                             QStringLiteral("helpers_demo/status_tools"),
                                             QStringLiteral("helpers_demo/teleop")}));
        // make_shared<Helper>(shared_from_this(), "cmd_vel"): the constructor argument names
        // the port; battery_(this) in the initializer list with a nav2-style parameter.
        const AtomicNode *controller = findNode(a, QStringLiteral("Controller"));
        QCOMPARE(describePorts(*controller),
                 (QStringList{
                     QStringLiteral("publisher cmd_vel geometry_msgs/msg/Twist cb= origin=literal "
                                    "expr= param= guard= gp= via=CmdVelPublisher "
                                    "@helpers_demo/include/helpers_demo/cmd_vel_publisher.hpp:18"),
                     QStringLiteral(
                         "subscriber battery_state sensor_msgs/msg/BatteryState cb=on_battery "
                         "origin=parameter expr=topic_ param=battery_topic guard= gp= "
                         "via=BatteryMonitor @helpers_demo/src/battery_monitor.cpp:13"),
                 }));
        // A procedural node handing itself to the same helper.
        const AtomicNode *teleop = findNode(a, QStringLiteral("teleop"));
        QVERIFY(teleop->procedural);
        QCOMPARE(describePorts(*teleop),
                 QStringList{QStringLiteral(
                     "publisher teleop/cmd_vel geometry_msgs/msg/Twist cb= origin=literal expr= "
                     "param= guard= gp= via=CmdVelPublisher "
                     "@helpers_demo/include/helpers_demo/cmd_vel_publisher.hpp:18")});
        // A registered component that owns its node.
        const AtomicNode *bridge = findNode(a, QStringLiteral("Bridge"));
        QCOMPARE(bridge->nodeName, QStringLiteral("bridge"));
        QVERIFY(bridge->baseClasses.isEmpty());
        QVERIFY(!bridge->procedural);
        QCOMPARE(describePorts(*bridge),
                 (QStringList{
                     QStringLiteral("subscriber in std_msgs/msg/String cb=lambda origin=literal "
                                    "expr= param= guard= gp= via= @helpers_demo/src/bridge.cpp:17"),
                     QStringLiteral("publisher out std_msgs/msg/String cb= origin=literal expr= "
                                    "param= guard= gp= via= @helpers_demo/src/bridge.cpp:19"),
                 }));
        // A helper template: `using ActionServer = SimpleActionServer<DockRobot>` gives the
        // type, the constructor argument the name, through a member (action_name_).
        const AtomicNode *docker = findNode(a, QStringLiteral("Docker"));
        QCOMPARE(describePorts(*docker),
                 QStringList{QStringLiteral(
                     "action_server dock_robot nav2_msgs/action/DockRobot cb=handle_goal "
                     "origin=literal expr= param= guard= gp= via=SimpleActionServer "
                     "@helpers_demo/include/helpers_demo/simple_action_server.hpp:24")});
        // A free function handed the node; a node factory is no node of its own.
        const AtomicNode *status = findNode(a, QStringLiteral("status_tools"));
        QCOMPARE(status->nodeName, QStringLiteral("status_tool"));
        QCOMPARE(describePorts(*status),
                 QStringList{QStringLiteral(
                     "publisher status std_msgs/msg/String cb= origin=literal expr= param= guard= "
                     "gp= via=add_status_publisher @helpers_demo/src/status_tools.cpp:13")});
        for (const AtomicNode &n : a.nodes)
            QVERIFY(n.nodeName != QLatin1String("_internal"));
        // Helper classes are not nodes, and UnusedHelper's port belongs to nobody.
        QVERIFY(!findNode(a, QStringLiteral("CmdVelPublisher")));
        QVERIFY(!findNode(a, QStringLiteral("UnusedHelper")));
        QVERIFY(!findNode(a, QStringLiteral("SimpleActionServer")));
        for (const AtomicNode &n : a.nodes)
            for (const Port &p : n.ports)
                QVERIFY(p.name != QLatin1String("unused"));
    }

    void helperMethodHandsNodeOn()
    {
        // Outer's constructor passes the node to its own method, which builds another helper.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile f(dir.filePath(QStringLiteral("deep.cpp")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "struct Sub {\n"
            "  Sub(rclcpp::Node::SharedPtr node, const std::string & topic) {\n"
            "    sub_ = node->create_subscription<std_msgs::msg::Empty>(topic, 1, &Sub::on);\n"
            "  }\n"
            "  void on(std_msgs::msg::Empty::ConstSharedPtr) {}\n"
            "  rclcpp::Subscription<std_msgs::msg::Empty>::SharedPtr sub_;\n"
            "};\n"
            "class Outer {\n"
            "public:\n"
            "  Outer(rclcpp::Node::SharedPtr node, std::string topic) { configure(node, topic); }\n"
            "  void configure(rclcpp::Node::SharedPtr node, std::string topic) {\n"
            "    sub_ = std::make_unique<Sub>(node, topic);\n"
            "  }\n"
            "  std::unique_ptr<Sub> sub_;\n"
            "};\n"
            "class N : public rclcpp::Node {\n"
            "public:\n"
            "  N() : Node(\"n\") {}\n"
            "  void init() { outer_ = std::make_shared<Outer>(shared_from_this(), \"deep\"); }\n"
            "  std::shared_ptr<Outer> outer_;\n"
            "};\n");
        f.close();
        Workspace ws;
        ws.root = dir.path();
        ws.files.append({QStringLiteral("deep.cpp"), QStringLiteral("deep"),
                         SourceFile::Language::Cpp, f.size()});
        const LanguageAnalysis a = CppNodeAnalyzer(ws).analyze();
        QCOMPARE(classNames(a), QStringList{QStringLiteral("deep/N")});
        QCOMPARE(
            describePorts(a.nodes[0]),
            QStringList{QStringLiteral("subscriber deep std_msgs/msg/Empty cb=on origin=literal "
                                       "expr= param= guard= gp= via=Sub @deep.cpp:3")});
    }

    // What a plugin's entry point may be handed as its node.
    void nodeHandleTypes()
    {
        for (const char *yes :
             {"rclcpp::Node::SharedPtr", "nav2::LifecycleNode::WeakPtr",
              "const rclcpp_lifecycle::LifecycleNode::WeakPtr &", "std::shared_ptr<rclcpp::Node> &",
              "rclcpp::Node *", "rclcpp::Node & node",
              "std::weak_ptr<rclcpp_lifecycle::LifecycleNode>"})
            QVERIFY2(isNodeHandleType(QString::fromLatin1(yes)), yes);
        for (const char *no : {"rclcpp::NodeOptions", "const std::string &", "NodeT",
                               "BT::TreeNode *", "std::shared_ptr<tf2_ros::Buffer>", "Node2D"})
            QVERIFY2(!isNodeHandleType(QString::fromLatin1(no)), no);
    }

    // `prefix + "/" + name` resolves part by part; a part that is a declared parameter makes the
    // whole parameter-derived, an unknown part leaves the whole expression as written.
    void concatenatedNames()
    {
        QTemporaryDir dir;
        QFile f(dir.filePath(QStringLiteral("joined.cpp")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("class Joined : public rclcpp::Node {\n"
                "public:\n"
                "  Joined() : Node(\"joined\") {\n"
                "    prefix_ = declare_parameter(\"prefix\", std::string(\"arm\"));\n"
                "    a_ = create_publisher<std_msgs::msg::Empty>(prefix_ + \"/state\", 1);\n"
                "    const std::string base = \"robot\";\n"
                "    b_ = create_publisher<std_msgs::msg::Empty>(base + \"/\" + kName, 1);\n"
                "    c_ = create_publisher<std_msgs::msg::Empty>(base + unknown(), 1);\n"
                "  }\n"
                "  static constexpr const char * kName = \"status\";\n"
                "};\n"
                "const std::string kName = \"status\";\n");
        f.close();
        Workspace ws;
        ws.root = dir.path();
        ws.files.append({QStringLiteral("joined.cpp"), QStringLiteral("joined"),
                         SourceFile::Language::Cpp, f.size()});
        const LanguageAnalysis a = CppNodeAnalyzer(ws).analyze();
        QCOMPARE(a.nodes.size(), 1);
        const QList<Port> &ports = a.nodes[0].ports;
        QCOMPARE(ports.size(), 3);
        QCOMPARE(ports[0].name, QStringLiteral("arm/state"));
        QCOMPARE(ports[0].nameOrigin, NameOrigin::Parameter);
        QCOMPARE(ports[0].parameter, QStringLiteral("prefix"));
        QCOMPARE(ports[1].name, QStringLiteral("robot/status"));
        QVERIFY(ports[1].isResolved());
        QCOMPARE(ports[2].nameOrigin, NameOrigin::Expression);
        QCOMPARE(ports[2].name, QStringLiteral("base + unknown()"));
    }

    // Helper chains are followed to a bound; the port beyond it is not given to the node, and a
    // note says where the analysis stopped.
    void helperChainsAreBounded()
    {
        QTemporaryDir dir;
        QFile f(dir.filePath(QStringLiteral("chain.cpp")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        QByteArray code;
        for (int level = 5; level >= 1; --level) {
            const QByteArray inner = level == 5
                                         ? QByteArray("    pub_ = node->create_publisher<std_msgs::"
                                                      "msg::Empty>(\"deep\", 1);\n")
                                         : QByteArray("    next_ = std::make_shared<H%1>(node);\n")
                                               .replace("%1", QByteArray::number(level + 1));
            code += "struct H" + QByteArray::number(level) + " {\n  explicit H" +
                    QByteArray::number(level) + "(rclcpp::Node * node) {\n" + inner + "  }\n};\n";
        }
        code += "class Deep : public rclcpp::Node {\npublic:\n  Deep() : Node(\"deep\") { "
                "h_ = std::make_shared<H1>(this); }\n};\n";
        f.write(code);
        f.close();
        Workspace ws;
        ws.root = dir.path();
        ws.files.append({QStringLiteral("chain.cpp"), QStringLiteral("chain"),
                         SourceFile::Language::Cpp, f.size()});
        const LanguageAnalysis a = CppNodeAnalyzer(ws).analyze();
        QCOMPARE(a.nodes.size(), 1);
        QVERIFY(a.nodes[0].ports.isEmpty()); // five helpers deep: beyond the bound
        const auto bound =
            std::find_if(a.diagnostics.begin(), a.diagnostics.end(), [](const Diagnostic &d) {
                return d.code == QLatin1String("helper-depth");
            });
        QVERIFY(bound != a.diagnostics.end());
        QVERIFY2(bound->message.contains(QStringLiteral("Deep")), qPrintable(bound->message));
        QCOMPARE(bound->evidence.file, QStringLiteral("chain.cpp"));
    }

    // The classes are linked in parallel: each note of a bound hit goes to the class whose chain
    // hit it, in the classes' order, and a class within the bound gets its port and no note.
    void eachClassGetsItsOwnHelperDepthNote()
    {
        QByteArray code;
        constexpr int kClasses = 40;
        for (int c = 0; c < kClasses; ++c) {
            const QByteArray id = QByteArray::number(c);
            const int depth = c % 2 == 0 ? 5 : 2; // even classes: beyond the bound of 3
            for (int level = depth; level >= 1; --level) {
                const QByteArray name = "H" + id + "_" + QByteArray::number(level);
                const QByteArray inner =
                    level == depth ? "    pub_ = node->create_publisher<std_msgs::msg::Empty>(\"t" +
                                         id + "\", 1);\n"
                                   : "    next_ = std::make_shared<H" + id + "_" +
                                         QByteArray::number(level + 1) + ">(node);\n";
                code += "struct " + name + " {\n  explicit " + name + "(rclcpp::Node * node) {\n" +
                        inner + "  }\n};\n";
            }
            code += "class Deep" + id + " : public rclcpp::Node {\npublic:\n  Deep" + id +
                    "() : Node(\"d" + id + "\") { h_ = std::make_shared<H" + id +
                    "_1>(this); }\n};\n";
        }
        const LanguageAnalysis a = analyzeFiles({{"chains.cpp", "chains", code}});
        QCOMPARE(a.nodes.size(), kClasses);
        QStringList noted;
        for (const Diagnostic &d : a.diagnostics)
            if (d.code == QLatin1String("helper-depth"))
                noted.append(
                    d.message.section(QLatin1Char(' '), 5, 5)); // "... helpers of DeepN here"
        QStringList deep; // in the classes' order, as the notes are
        for (int c = 0; c < kClasses; c += 2)
            deep.append(QStringLiteral("Deep%1").arg(c));
        for (const AtomicNode &n : a.nodes) {
            const int c = n.className.mid(4).toInt();
            if (c % 2 == 0) {
                QVERIFY2(n.ports.isEmpty(), qPrintable(n.className));
            } else {
                QCOMPARE(n.ports.size(), 1);
                QCOMPARE(n.ports.first().name, QStringLiteral("t%1").arg(c));
            }
        }
        QCOMPARE(noted, deep);
    }

    void interfaceTypes_data()
    {
        QTest::addColumn<QString>("written");
        QTest::addColumn<QString>("canonical");
        QTest::newRow("msg") << "std_msgs::msg::String"
                             << "std_msgs/msg/String";
        QTest::newRow("global") << "::std_msgs::msg::String"
                                << "std_msgs/msg/String";
        QTest::newRow("shared ptr") << "std_msgs::msg::String::SharedPtr"
                                    << "std_msgs/msg/String";
        QTest::newRow("const shared ptr") << "sensor_msgs::msg::Image::ConstSharedPtr"
                                          << "sensor_msgs/msg/Image";
        QTest::newRow("srv") << "std_srvs::srv::Trigger"
                             << "std_srvs/srv/Trigger";
        QTest::newRow("action") << "nav2_msgs::action::FollowPath"
                                << "nav2_msgs/action/FollowPath";
        QTest::newRow("feedback") << "nav2_msgs::action::DockRobot::Impl::FeedbackMessage"
                                  << "nav2_msgs/action/DockRobot_FeedbackMessage";
        QTest::newRow("allocator") << "std_msgs::msg::String_<std::allocator<void>>"
                                   << "std_msgs/msg/String";
        QTest::newRow("type adapter") << "rclcpp::TypeAdapter<std::string, std_msgs::msg::String>"
                                      << "std_msgs/msg/String";
        QTest::newRow("unknown") << "MyType"
                                 << "MyType";
        QTest::newRow("no package") << "msg::String"
                                    << "msg::String";
    }

    void interfaceTypes()
    {
        QFETCH(QString, written);
        QFETCH(QString, canonical);
        QCOMPARE(cppsyntax::canonicalInterfaceType(written), canonical);
    }
};

QTEST_GUILESS_MAIN(TestCppNameResolution)
#include "tst_cppnameresolution.moc"
