#include "nodes/python/pythonnodeanalyzer.h"
#include "support/pythonanalysis.h"
#include "support/testsupport.h"
#include "workspace/workspacescanner.h"

#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::python;

namespace {

/// A one-package workspace in `dir` holding the Python modules given (name -> source).
LanguageAnalysis analyzeModules(const QTemporaryDir &dir, const QMap<QString, QByteArray> &modules)
{
    const QString package = dir.path() + QStringLiteral("/src/demo");
    test::writeFile(package + QStringLiteral("/package.xml"),
                    "<package format=\"3\"><name>demo</name><export><build_type>ament_python"
                    "</build_type></export></package>\n");
    test::writeFile(package + QStringLiteral("/demo/__init__.py"), "");
    for (auto it = modules.cbegin(); it != modules.cend(); ++it)
        test::writeFile(package + QStringLiteral("/demo/") + it.key() + QStringLiteral(".py"),
                        it.value());
    return PythonNodeAnalyzer(WorkspaceScanner::scan(dir.path())).analyze();
}

/// "file:line" of each call site on the way to a port.
QStringList chain(const Port &p)
{
    QStringList out;
    for (const Evidence &e : p.viaEvidence)
        out << QStringLiteral("%1:%2").arg(e.file.section(QLatin1Char('/'), -1)).arg(e.line);
    return out;
}

} // namespace

/// Nodes that hand themselves to helpers, and py_trees behaviour trees set up with the node.
class TestPythonHelpers : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void helpers()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_helpers"));
        QCOMPARE(qualifiedNames(a),
                 (QStringList{QStringLiteral("py_helper_demo.robot.Robot"),
                              QStringLiteral("py_helper_demo.monitor_tool.Worker"),
                              QStringLiteral("py_helper_demo.monitor_tool.main"),
                              QStringLiteral("py_helper_demo.scripted")}));
        const QString h = QStringLiteral(" @src/py_helper_demo/py_helper_demo/helpers.py:");
        const AtomicNode *robot = node(a, QStringLiteral("py_helper_demo.robot.Robot"));
        QVERIFY(robot);
        QCOMPARE(
            portLines(*robot),
            (QStringList{
                QStringLiteral("publisher cmd_vel geometry_msgs/msg/Twist cb= local expr=topic "
                               "via=CommandRelay") +
                    h + QStringLiteral("11:20-11:64"),
                QStringLiteral("subscriber cmd_vel_in geometry_msgs/msg/Twist cb=relay literal "
                               "via=CommandRelay") +
                    h + QStringLiteral("14:9-14:75"),
                QStringLiteral("publisher robot/diagnostics std_msgs/msg/String cb= local "
                               "expr=name + '/diagnostics' via=add_diagnostics") +
                    h + QStringLiteral("21:5-21:61"),
                QStringLiteral("service_server self_test std_srvs/srv/Trigger cb=lambda literal "
                               "via=add_diagnostics") +
                    h + QStringLiteral("22:12-22:89"),
                QStringLiteral(
                    "subscriber status std_msgs/msg/String cb=on_status literal via=StatusWatcher "
                    "@src/py_helper_demo/py_helper_demo/robot.py:11:9-11:72")}));
        // the procedural node hands itself to the same helper, with another topic
        const AtomicNode *scripted = node(a, QStringLiteral("py_helper_demo.scripted"));
        QVERIFY(scripted);
        QVERIFY(scripted->procedural);
        QCOMPARE(portLines(*scripted),
                 (QStringList{QStringLiteral("publisher scripted_cmd geometry_msgs/msg/Twist cb= "
                                             "local expr=topic via=CommandRelay") +
                                  h + QStringLiteral("11:20-11:64"),
                              QStringLiteral("subscriber cmd_vel_in geometry_msgs/msg/Twist "
                                             "cb=relay literal via=CommandRelay") +
                                  h + QStringLiteral("14:9-14:75")}));
    }

    void methodHandoffAndProceduralNodesInOneFile()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_helpers"));
        const QString f = QStringLiteral("src/py_helper_demo/py_helper_demo/monitor_tool.py");
        // built in a method of a class that is not a node; named after that class
        const AtomicNode *worker = node(a, QStringLiteral("py_helper_demo.monitor_tool.Worker"));
        QVERIFY(worker);
        QCOMPARE(worker->className, QStringLiteral("monitor_tool_Worker"));
        QCOMPARE(worker->nodeName, QStringLiteral("worker"));
        QVERIFY(worker->procedural);
        QCOMPARE(range(worker->evidence), f + QStringLiteral(":18:5-22:64"));
        // registry.watch(Header, 'heartbeat', node): type and name come from the call site
        QCOMPARE(portLines(*worker),
                 (QStringList{
                     QStringLiteral("subscriber heartbeat std_msgs/msg/Header cb=on_message local "
                                    "expr=topic via=Registry @") +
                         f + QStringLiteral(":10:16-10:78"),
                     QStringLiteral("publisher worker_status std_msgs/msg/String cb= literal @") +
                         f + QStringLiteral(":22:9-22:64")}));
        const AtomicNode *probe = node(a, QStringLiteral("py_helper_demo.monitor_tool.main"));
        QVERIFY(probe);
        QCOMPARE(probe->className, QStringLiteral("monitor_tool_main"));
        QCOMPARE(probe->nodeName, QStringLiteral("probe"));
        QVERIFY(probe->ports.isEmpty());
        bool found = false;
        for (const EntryPoint &e : a.entryPoints) {
            if (e.file != f)
                continue;
            found = true;
            QCOMPARE(e.function, QStringLiteral("main"));
            QCOMPARE(e.instantiatedClasses,
                     (QStringList{QStringLiteral("py_helper_demo.monitor_tool.Worker"),
                                  QStringLiteral("py_helper_demo.monitor_tool.main")}));
        }
        QVERIFY(found);
    }

    void behaviourTree()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_behaviour_tree"));
        QCOMPARE(qualifiedNames(a), QStringList{QStringLiteral("bt_mission.mission.Mission")});
        const AtomicNode &mission = a.nodes.first();
        const QString b = QStringLiteral(" @src/bt_mission/bt_mission/behaviours.py:");
        QCOMPARE(
            portLines(mission),
            (QStringList{
                QStringLiteral("subscriber /battery/state sensor_msgs/msg/BatteryState "
                               "cb=on_battery local expr=self.topic_name via=BatteryCheck") +
                    b + QStringLiteral("23:9-23:90"),
                QStringLiteral("subscriber /backup_battery/state sensor_msgs/msg/BatteryState "
                               "cb=on_battery local expr=self.topic_name via=BatteryCheck") +
                    b + QStringLiteral("23:9-23:90"),
                QStringLiteral("publisher scout/goal_pose geometry_msgs/msg/PoseStamped cb= local "
                               "expr=f'{self.robot}/goal_pose' via=PublishGoal") +
                    b + QStringLiteral("44:26-44:91"),
                QStringLiteral("action_client navigate_to_pose nav2_msgs/action/NavigateToPose "
                               "cb= member expr=self.action_name via=NavigateTo") +
                    b + QStringLiteral("64:27-64:84"),
                QStringLiteral("service_client docking/start std_srvs/srv/Trigger cb= local "
                               "expr=self.service_name via=CallTrigger") +
                    b + QStringLiteral("80:23-80:69"),
                QStringLiteral("publisher mission/status std_msgs/msg/String cb= member "
                               "expr=self.topic via=StatusReporter "
                               "@src/bt_mission/bt_mission/reporter.py:14:30-14:80")}));
        // the setup call first, then each call on the way to the behaviour
        QCOMPARE(chain(mission.ports.at(0)),
                 (QStringList{QStringLiteral("mission.py:16"), QStringLiteral("mission.py:20"),
                              QStringLiteral("tree.py:25"), QStringLiteral("tree.py:13")}));
        QCOMPARE(chain(mission.ports.at(1)).last(), QStringLiteral("tree.py:14"));
        QCOMPARE(chain(mission.ports.at(2)),
                 (QStringList{QStringLiteral("mission.py:16"), QStringLiteral("mission.py:20"),
                              QStringLiteral("tree.py:21")}));
        QCOMPARE(chain(mission.ports.at(5)), QStringList{QStringLiteral("mission.py:14")});
        QVERIFY(a.diagnostics.isEmpty());
    }

    void setupProtocolForms()
    {
        QTemporaryDir dir;
        const LanguageAnalysis a = analyzeModules(
            dir, {{QStringLiteral("leaves"),
                   "from std_msgs.msg import String\n"
                   "import py_trees\n"
                   "\n"
                   "class Listen(py_trees.behaviour.Behaviour):\n"
                   "    def __init__(self, name, topic):\n"
                   "        super().__init__(name)\n"
                   "        self.topic = topic\n"
                   "    def setup(self, node=None, **kwargs):\n"
                   "        self.node = node\n"
                   "    def initialise(self):\n"
                   "        self.node.create_subscription(String, self.topic, self.cb, 1)\n"
                   "    def cb(self, msg):\n"
                   "        pass\n"
                   "\n"
                   "class ListenScan(Listen):\n"
                   "    pass\n"
                   "\n"
                   "class ListenOdom(Listen):\n"
                   "    def __init__(self):\n"
                   "        super().__init__('odom', topic='odom')\n"
                   "\n"
                   "class Say(py_trees.behaviour.Behaviour):\n"
                   "    def __init__(self, prefix='robot'):\n"
                   "        self.prefix = prefix\n"
                   "    def setup(self, **kw):\n"
                   "        kw.get('node').create_publisher(String, '{ns}/say'.format(ns="
                   "self.prefix), 1)\n"
                   "\n"
                   "class Unused(py_trees.behaviour.Behaviour):\n"
                   "    def setup(self, **kwargs):\n"
                   "        kwargs['node'].create_publisher(String, 'unused', 1)\n"},
                  {QStringLiteral("proc"),
                   "import py_trees, rclpy\n"
                   "from demo.leaves import ListenScan, ListenOdom, Say\n"
                   "\n"
                   "def main():\n"
                   "    node = rclpy.create_node('proc')\n"
                   "    root = py_trees.composites.Selector('root', False, children=[\n"
                   "        ListenScan('scan', 'scan'), ListenOdom(), Say(prefix='r2')])\n"
                   "    root.setup(node=node)\n"},
                  {QStringLiteral("plain"),
                   "import rclpy\n"
                   "from rclpy.node import Node\n"
                   "from std_msgs.msg import String\n"
                   "from demo.leaves import Say\n"
                   "\n"
                   "class Recorder:\n"
                   "    def attach(self, owner):\n"
                   "        owner.create_subscription(String, 'recorded', self.on, 1)\n"
                   "    def on(self, msg):\n"
                   "        pass\n"
                   "\n"
                   "class Plain(Node):\n"
                   "    def __init__(self):\n"
                   "        super().__init__('plain')\n"
                   "        self.say = Say()\n"
                   "        Recorder().attach(self)\n"}});
        const QString leaves = QStringLiteral(" @src/demo/demo/leaves.py:");
        const AtomicNode *proc = node(a, QStringLiteral("demo.proc"));
        QVERIFY(proc);
        // a `node` parameter of setup, kwargs.get('node'), a base class's setup reached with
        // the derived class's arguments (none of its own, or passed on by its constructor)
        QCOMPARE(portLines(*proc),
                 (QStringList{QStringLiteral("subscriber odom std_msgs/msg/String cb=cb local "
                                             "expr=self.topic via=ListenOdom") +
                                  leaves + QStringLiteral("11:9-11:70"),
                              QStringLiteral("subscriber scan std_msgs/msg/String cb=cb local "
                                             "expr=self.topic via=ListenScan") +
                                  leaves + QStringLiteral("11:9-11:70"),
                              QStringLiteral("publisher r2/say std_msgs/msg/String cb= local "
                                             "expr='{ns}/say'.format(ns=self.prefix) via=Say") +
                                  leaves + QStringLiteral("26:9-26:86")}));
        QCOMPARE(chain(proc->ports.at(1)),
                 (QStringList{QStringLiteral("proc.py:8"), QStringLiteral("proc.py:7")}));
        // no setup(node=self): Say keeps its ports to itself; a method hand-off still counts
        const AtomicNode *plain = node(a, QStringLiteral("demo.plain.Plain"));
        QVERIFY(plain);
        QCOMPARE(portLines(*plain),
                 QStringList{QStringLiteral("subscriber recorded std_msgs/msg/String cb=on literal "
                                            "via=Recorder @src/demo/demo/plain.py:8:9-8:66")});
        QCOMPARE(chain(plain->ports.first()), QStringList{QStringLiteral("plain.py:16")});
        QVERIFY(a.diagnostics.isEmpty());
    }

    void setupBoundGivesDiagnostic()
    {
        // a tree built eleven function calls away from the node's setup call
        QByteArray source = "import rclpy\n"
                            "from rclpy.node import Node\n"
                            "from std_msgs.msg import String\n"
                            "\n"
                            "class Leaf:\n"
                            "    def setup(self, **kwargs):\n"
                            "        kwargs['node'].create_publisher(String, 'deep', 1)\n"
                            "\n"
                            "def build0():\n"
                            "    return Leaf()\n";
        for (int i = 1; i <= 10; ++i)
            source +=
                QStringLiteral("def build%1():\n    return build%2()\n").arg(i).arg(i - 1).toUtf8();
        source += "class Deep(Node):\n"
                  "    def __init__(self):\n"
                  "        super().__init__('deep')\n"
                  "        self.root = build10()\n"
                  "        self.root.setup(node=self)\n";
        QTemporaryDir dir;
        const LanguageAnalysis a = analyzeModules(dir, {{QStringLiteral("deep"), source}});
        const AtomicNode *deep = node(a, QStringLiteral("demo.deep.Deep"));
        QVERIFY(deep);
        QVERIFY(deep->ports.isEmpty());
        QCOMPARE(a.diagnostics.size(), 1);
        QCOMPARE(a.diagnostics.first().code, QStringLiteral("helper-depth"));
        QCOMPARE(a.diagnostics.first().evidence.file, QStringLiteral("src/demo/demo/deep.py"));
        QVERIFY2(a.diagnostics.first().message.contains(QStringLiteral("behaviour tree")),
                 qPrintable(a.diagnostics.first().message));

        // functions that each call the next six times, 6^5 paths: following stops at the
        // bound, and the leaf found before it still counts
        QByteArray wide = "from rclpy.node import Node\n"
                          "from std_msgs.msg import String\n"
                          "class Leaf:\n"
                          "    def setup(self, **kwargs):\n"
                          "        kwargs['node'].create_publisher(String, 'wide', 1)\n"
                          "def level0():\n"
                          "    return 0\n";
        for (int i = 1; i <= 5; ++i)
            wide += QStringLiteral("def level%1():\n    return [%2]\n")
                        .arg(i)
                        .arg(QStringList(6, QStringLiteral("level%1()").arg(i - 1))
                                 .join(QStringLiteral(", ")))
                        .toUtf8();
        wide += "class Wide(Node):\n"
                "    def __init__(self):\n"
                "        super().__init__('wide')\n"
                "        self.leaf = Leaf()\n"
                "        level5()\n"
                "        self.setup(node=self)\n";
        QTemporaryDir wideDir;
        const LanguageAnalysis w = analyzeModules(wideDir, {{QStringLiteral("wide"), wide}});
        const AtomicNode *wideNode = node(w, QStringLiteral("demo.wide.Wide"));
        QVERIFY(wideNode);
        QCOMPARE(wideNode->ports.size(), 1);
        QCOMPARE(wideNode->ports.first().name, QStringLiteral("wide"));
        QCOMPARE(w.diagnostics.size(), 1);
        QCOMPARE(w.diagnostics.first().code, QStringLiteral("helper-depth"));
    }
};

QTEST_GUILESS_MAIN(TestPythonHelpers)
#include "tst_pythonhelpers.moc"
