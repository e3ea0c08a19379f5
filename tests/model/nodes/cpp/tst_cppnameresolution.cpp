// How the C++ analyzer resolves names: port names from literals, locals, members, parameters
// and expressions, names handed through helper classes and methods, and interface types.
#include "cppanalysis.h"
#include "cppnameresolver.h"
#include "cppnodeanalyzer.h"
#include "cppsyntax.h"
#include "testsupport.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::cpp;

class TestCppNameResolution : public QObject
{
    Q_OBJECT
private Q_SLOTS:
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
                QStringLiteral(
                    "publisher std::string(get_name()) + \"/heartbeat\" std_msgs/msg/String cb= "
                    "origin=expression expr=std::string(get_name()) + \"/heartbeat\" param= guard= "
                    "gp= via= @%1:45")
                    .arg(f),
                QStringLiteral("publisher late std_msgs/msg/String cb= origin=member "
                               "expr=late_topic_ param= guard= gp= via= @%1:51")
                    .arg(f),
            }));
        QVERIFY(a.nodes[0].ports.last().isResolved());
        QVERIFY(!a.nodes[0].ports[9].isResolved());
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
