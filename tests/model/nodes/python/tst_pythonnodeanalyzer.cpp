#include "cache/analysiscache.h"
#include "nodes/python/pythonnodeanalyzer.h"
#include "support/pythonanalysis.h"
#include "support/testsupport.h"
#include "syntax/syntaxtree.h"
#include "workspace/workspacescanner.h"

#include <QtTest>

#include <atomic>

using namespace rosarch;
using namespace rosarch::test::python;
using rosarch::test::dataDir;

class TestPythonNodeAnalyzer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void directSubclass()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_basic"));
        QCOMPARE(qualifiedNames(a),
                 (QStringList{QStringLiteral("py_basic_demo.lambda_listener.LambdaListener"),
                              QStringLiteral("py_basic_demo.listener.Listener"),
                              QStringLiteral("py_basic_demo.star_talker.StarTalker"),
                              QStringLiteral("py_basic_demo.talker.Talker"),
                              QStringLiteral("py_basic_demo.old_school")}));
        const AtomicNode *talker = node(a, QStringLiteral("py_basic_demo.talker.Talker"));
        QVERIFY(talker);
        QCOMPARE(talker->id, QString());
        QCOMPARE(talker->className, QStringLiteral("Talker"));
        QCOMPARE(talker->nodeName, QStringLiteral("talker"));
        QCOMPARE(talker->packageName, QStringLiteral("py_basic_demo"));
        QCOMPARE(talker->sourceFiles,
                 QStringList{QStringLiteral("src/py_basic_demo/py_basic_demo/talker.py")});
        QVERIFY(talker->headerFiles.isEmpty());
        QCOMPARE(talker->compileType, AtomicNode::CompileType::Python);
        QCOMPARE(talker->baseClasses, QStringList{QStringLiteral("Node")});
        QVERIFY(!talker->lifecycle);
        QVERIFY(!talker->procedural);
        QVERIFY(talker->executables.isEmpty());
        QVERIFY(talker->plugins.isEmpty());
        QCOMPARE(range(talker->evidence),
                 QStringLiteral("src/py_basic_demo/py_basic_demo/talker.py:7:1-17:30"));
        QVERIFY(talker->evidence.containsLine(15)); // a line inside tick() maps back to the class
        QCOMPARE(
            portLines(*talker),
            QStringList{QStringLiteral("publisher chatter std_msgs/msg/String cb= literal "
                                       "@src/py_basic_demo/py_basic_demo/talker.py:11:20-11:64")});
        QCOMPARE(talker->ports.first().id, QString());

        // super(Listener, self).__init__, base written as rclpy.node.Node, type imported "as"
        const AtomicNode *listener = node(a, QStringLiteral("py_basic_demo.listener.Listener"));
        QVERIFY(listener);
        QCOMPARE(listener->nodeName, QStringLiteral("listener"));
        QCOMPARE(listener->baseClasses, QStringList{QStringLiteral("rclpy.node.Node")});
        QCOMPARE(portLines(*listener),
                 QStringList{
                     QStringLiteral("subscriber chatter std_msgs/msg/String cb=on_text literal "
                                    "@src/py_basic_demo/py_basic_demo/listener.py:11:20-11:79")});

        // node_name= keyword, module alias for rclpy.node, keyword arguments, lambda callback
        const AtomicNode *lambda =
            node(a, QStringLiteral("py_basic_demo.lambda_listener.LambdaListener"));
        QVERIFY(lambda);
        QCOMPARE(lambda->nodeName, QStringLiteral("lambda_listener"));
        QCOMPARE(lambda->baseClasses, QStringList{QStringLiteral("rclpy_node.Node")});
        QCOMPARE(portLines(*lambda),
                 QStringList{QStringLiteral(
                     "subscriber chatter std_msgs/msg/String cb=lambda literal "
                     "@src/py_basic_demo/py_basic_demo/lambda_listener.py:10:9-14:28")});

        // Node from `from rclpy.node import *`; the type held in a local variable
        const AtomicNode *star = node(a, QStringLiteral("py_basic_demo.star_talker.StarTalker"));
        QVERIFY(star);
        QCOMPARE(portLines(*star),
                 QStringList{
                     QStringLiteral("publisher star std_msgs/msg/String cb= literal "
                                    "@src/py_basic_demo/py_basic_demo/star_talker.py:10:9-10:52")});
        QVERIFY(a.diagnostics.isEmpty());
    }

    void classesNamedNodeThatAreNotNodes()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_basic"));
        for (const AtomicNode &n : a.nodes)
            QVERIFY2(
                !n.sourceFiles.contains(QStringLiteral("src/py_basic_demo/py_basic_demo/trees.py")),
                qPrintable(n.qualifiedName));
    }

    void proceduralNode()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_basic"));
        const AtomicNode *n = node(a, QStringLiteral("py_basic_demo.old_school"));
        QVERIFY(n);
        QCOMPARE(n->className, QStringLiteral("old_school"));
        QCOMPARE(n->nodeName, QStringLiteral("old_school"));
        QVERIFY(n->procedural);
        QVERIFY(n->baseClasses.isEmpty());
        QCOMPARE(n->sourceFiles,
                 QStringList{QStringLiteral("src/py_basic_demo/py_basic_demo/old_school.py")});
        QCOMPARE(range(n->evidence),
                 QStringLiteral("src/py_basic_demo/py_basic_demo/old_school.py:9:1-15:21"));
        QCOMPARE(portLines(*n),
                 (QStringList{
                     QStringLiteral("publisher chatter std_msgs/msg/String cb= literal "
                                    "@src/py_basic_demo/py_basic_demo/old_school.py:12:17-12:61"),
                     QStringLiteral("subscriber echo std_msgs/msg/String cb=on_message literal "
                                    "@src/py_basic_demo/py_basic_demo/old_school.py:13:5-13:61")}));
    }

    void builderChainStopsAtItsBoundAndSaysWhere()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_builder_depth"));
        const auto main = std::find_if(a.entryPoints.cbegin(), a.entryPoints.cend(),
                                       [](const EntryPoint &e) { return e.function == "main"; });
        QVERIFY(main != a.entryPoints.cend());
        QStringList built;
        for (const NodeConstruction &k : main->constructions)
            built << k.nodeName;
        // level_three is the third call from main(): its own node is built, the one of the
        // function it calls is past the bound
        QCOMPARE(built,
                 (QStringList{QStringLiteral("first_stage"), QStringLiteral("third_stage")}));
        QStringList notes;
        for (const Diagnostic &d : a.diagnostics)
            notes << QStringLiteral("%1 %2:%3").arg(d.code, d.evidence.file).arg(d.evidence.line);
        QCOMPARE(notes, QStringList{QStringLiteral(
                            "builder-depth src/relay_chain/relay_chain/chain.py:17")});
        // a function nearer the node follows the whole chain
        const auto one =
            std::find_if(a.entryPoints.cbegin(), a.entryPoints.cend(),
                         [](const EntryPoint &e) { return e.function == "level_one"; });
        QVERIFY(one != a.entryPoints.cend());
        QCOMPARE(one->constructions.size(), 2);
    }

    void entryPoints()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_basic"));
        QStringList got;
        for (const EntryPoint &e : a.entryPoints)
            got << QStringLiteral("%1:%2 -> %3 @%4")
                       .arg(e.file, e.function, e.instantiatedClasses.join(QLatin1Char(' ')))
                       .arg(e.evidence.line);
        QCOMPARE(
            got,
            (QStringList{
                QStringLiteral("src/py_basic_demo/py_basic_demo/both.py:run -> "
                               "py_basic_demo.talker.Talker py_basic_demo.listener.Listener @8"),
                QStringLiteral("src/py_basic_demo/py_basic_demo/lambda_listener.py:main -> "
                               "py_basic_demo.lambda_listener.LambdaListener @17"),
                QStringLiteral("src/py_basic_demo/py_basic_demo/listener.py:main -> "
                               "py_basic_demo.listener.Listener @17"),
                QStringLiteral("src/py_basic_demo/py_basic_demo/old_school.py:main -> "
                               "py_basic_demo.old_school @9"),
                QStringLiteral("src/py_basic_demo/py_basic_demo/talker.py:main -> "
                               "py_basic_demo.talker.Talker @20")}));
    }

    void names()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_names"));
        const AtomicNode *n = node(a, QStringLiteral("py_names_demo.names.Names"));
        QVERIFY(n);
        const QString f = QStringLiteral(" @src/py_names_demo/py_names_demo/names.py:");
        QCOMPARE(
            portLines(*n),
            (QStringList{
                QStringLiteral(
                    "publisher member_topic std_msgs/msg/String cb= member expr=self.topic") +
                    f + QStringLiteral("24:9-24:54"),
                QStringLiteral(
                    "publisher local_topic std_msgs/msg/String cb= local expr=local_topic") +
                    f + QStringLiteral("25:9-25:55"),
                QStringLiteral(
                    "subscriber camera/image sensor_msgs/msg/Image cb=on_image parameter "
                    "expr=self.get_parameter('input_topic').value param=input_topic") +
                    f + QStringLiteral("26:9-26:100"),
                QStringLiteral("publisher out sensor_msgs/msg/Image cb= parameter expr=out "
                               "param=output_topic") +
                    f + QStringLiteral("28:9-28:46"),
                QStringLiteral("publisher ~/private std_msgs/msg/String cb= literal") + f +
                    QStringLiteral("29:9-29:55"),
                QStringLiteral("publisher status std_msgs/msg/String cb= local expr=STATUS_TOPIC") +
                    f + QStringLiteral("30:9-30:56"),
                QStringLiteral("publisher {node}/debug std_msgs/msg/String cb= "
                               "local expr=self.get_name() + '/debug'") +
                    f + QStringLiteral("31:9-31:70"),
                QStringLiteral("publisher {node}/formatted std_msgs/msg/String cb= "
                               "local expr=f'{self.get_name()}/formatted'") +
                    f + QStringLiteral("32:9-32:74"),
                QStringLiteral(
                    "publisher class_topic std_msgs/msg/String cb= member expr=self.CLASS_TOPIC") +
                    f + QStringLiteral("33:9-33:60"),
                QStringLiteral("publisher cmd_vel geometry_msgs/msg/Twist cb= parameter "
                               "expr=self.get_parameter('cmd_topic').value param=cmd_topic") +
                    f + QStringLiteral("34:9-34:80"),
                QStringLiteral("publisher mirror sensor_msgs/msg/Image cb= parameter "
                               "expr=self.mirror param=mirror_topic") +
                    f + QStringLiteral("36:9-36:54"),
                QStringLiteral("publisher debug_image sensor_msgs/msg/Image cb= literal "
                               "guard=[self.debug] guard_param=use_debug") +
                    f + QStringLiteral("39:13-39:59"),
                QStringLiteral("publisher fast std_msgs/msg/String cb= literal "
                               "guard=[self.get_parameter('rate').value > 5] guard_param=rate") +
                    f + QStringLiteral("41:13-41:54"),
                QStringLiteral("publisher slow std_msgs/msg/String cb= literal guard=[not "
                               "(self.get_parameter('rate').value > 5)] guard_param=rate") +
                    f + QStringLiteral("43:13-43:54")}));
        // the node's own name is a placeholder that each instance fills in
        QVERIFY(n->ports.at(6).isResolved());
        QVERIFY(n->ports.at(6).name.startsWith(QLatin1String(kNodeNamePlaceholder)));
        QVERIFY(n->ports.at(0).isResolved());
    }

    void proceduralParametersAndGuard()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_names"));
        const AtomicNode *n = node(a, QStringLiteral("py_names_demo.param_node"));
        QVERIFY(n);
        QCOMPARE(n->nodeName, QStringLiteral("param_node"));
        QCOMPARE(portLines(*n),
                 (QStringList{
                     QStringLiteral(
                         "publisher from_param std_msgs/msg/String cb= parameter expr=topic "
                         "param=topic @src/py_names_demo/py_names_demo/param_node.py:10:5-10:45"),
                     QStringLiteral("subscriber feedback std_msgs/msg/String cb=lambda literal "
                                    "guard=[enabled] guard_param=enabled "
                                    "@src/py_names_demo/py_names_demo/param_node.py:13:9-13:75")}));

        // built at module level under `if __name__ == '__main__':`, which is no guard
        const AtomicNode *script = node(a, QStringLiteral("py_names_demo.script_node"));
        QVERIFY(script);
        QCOMPARE(script->className, QStringLiteral("script_node"));
        QCOMPARE(range(script->evidence),
                 QStringLiteral("src/py_names_demo/py_names_demo/script_node.py:6:5-6:44"));
        QCOMPARE(portLines(*script),
                 QStringList{
                     QStringLiteral("publisher script_topic std_msgs/msg/String cb= literal "
                                    "@src/py_names_demo/py_names_demo/script_node.py:7:5-7:54")});
        for (const EntryPoint &e : a.entryPoints)
            QVERIFY(e.file != script->evidence.file); // no function starts it
    }

    void servicesActionsLifecycle()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_comm"));
        QCOMPARE(a.nodes.size(), 6);
        const QString dir = QStringLiteral("src/py_comm_demo/py_comm_demo/");
        const AtomicNode *server = node(a, QStringLiteral("py_comm_demo.adder_server.AdderServer"));
        QVERIFY(server);
        QCOMPARE(server->nodeName,
                 QStringLiteral("adder_server")); // Node.__init__(self, 'adder_server')
        QCOMPARE(portLines(*server),
                 (QStringList{
                     QStringLiteral("service_server add_two_ints example_interfaces/srv/AddTwoInts "
                                    "cb=handle_add literal @") +
                         dir + QStringLiteral("adder_server.py:13:20-13:84"),
                     QStringLiteral(
                         "service_server enable std_srvs/srv/SetBool cb=on_enable literal @") +
                         dir + QStringLiteral("adder_server.py:14:23-14:110")}));
        const AtomicNode *client = node(a, QStringLiteral("py_comm_demo.adder_client.AdderClient"));
        QVERIFY(client);
        QCOMPARE(
            portLines(*client),
            QStringList{
                QStringLiteral(
                    "service_client add_two_ints example_interfaces/srv/AddTwoInts cb= literal @") +
                dir + QStringLiteral("adder_client.py:10:20-10:84")});
        const AtomicNode *actionServer =
            node(a, QStringLiteral("py_comm_demo.fibonacci_server.FibonacciServer"));
        QVERIFY(actionServer);
        QCOMPARE(
            portLines(*actionServer),
            QStringList{QStringLiteral("action_server fibonacci "
                                       "example_interfaces/action/Fibonacci cb=execute literal @") +
                        dir + QStringLiteral("fibonacci_server.py:11:24-14:39")});
        const AtomicNode *actionClient =
            node(a, QStringLiteral("py_comm_demo.fibonacci_client.FibonacciClient"));
        QVERIFY(actionClient);
        QCOMPARE(
            portLines(*actionClient),
            QStringList{
                QStringLiteral(
                    "action_client fibonacci example_interfaces/action/Fibonacci cb= literal @") +
                dir + QStringLiteral("fibonacci_client.py:11:24-11:89")});
        const AtomicNode *lifecycle =
            node(a, QStringLiteral("py_comm_demo.lifecycle_talker.LifecycleTalker"));
        QVERIFY(lifecycle);
        QVERIFY(lifecycle->lifecycle);
        // the name is a constructor parameter; the only instantiation passes 'lc_talker'
        QCOMPARE(lifecycle->nodeName, QStringLiteral("lc_talker"));
        QCOMPARE(portLines(*lifecycle),
                 QStringList{QStringLiteral(
                                 "publisher lifecycle_chatter std_msgs/msg/String cb= literal @") +
                             dir + QStringLiteral("lifecycle_talker.py:14:21-14:85")});
        QVERIFY(!server->lifecycle);

        // Node('plain_node') in a function is a procedural node, like rclpy.create_node
        const AtomicNode *plain = node(a, QStringLiteral("py_comm_demo.plain_node"));
        QVERIFY(plain);
        QVERIFY(plain->procedural);
        QCOMPARE(plain->nodeName, QStringLiteral("plain_node"));
        QCOMPARE(
            portLines(*plain),
            QStringList{QStringLiteral("service_client reset std_srvs/srv/Trigger cb= literal @") +
                        dir + QStringLiteral("plain_node.py:9:13-9:49")});
    }

    void inheritance()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_inherit"));
        QCOMPARE(qualifiedNames(a),
                 (QStringList{QStringLiteral("py_inherit_demo.battery.BatteryMonitor"),
                              QStringLiteral("py_inherit_demo.temperature.CpuTemperatureMonitor"),
                              QStringLiteral("py_inherit_demo.base.MonitorBase"),
                              QStringLiteral("py_inherit_demo.temperature.TemperatureMonitor")}));
        const QString base = QStringLiteral(" @src/py_inherit_demo/py_inherit_demo/base.py:");
        const QString status =
            QStringLiteral("publisher status std_msgs/msg/String cb= local expr=status_topic");
        const QString reset =
            QStringLiteral("service_server reset std_srvs/srv/Trigger cb=on_reset literal");
        const QString heartbeat =
            QStringLiteral("publisher heartbeat std_msgs/msg/String cb= literal");

        const AtomicNode *monitor = node(a, QStringLiteral("py_inherit_demo.base.MonitorBase"));
        QVERIFY(monitor);
        // Never instantiated: the instance decides; never the parameter's own name.
        QCOMPARE(monitor->nodeName, QString());
        QCOMPARE(portLines(*monitor),
                 (QStringList{status + base + QStringLiteral("11:27-11:74"),
                              reset + base + QStringLiteral("12:26-12:78"),
                              heartbeat + base + QStringLiteral("16:26-16:71")}));

        // setup() overridden without super(): the base's heartbeat is not created; a mixin adds
        // estop
        const AtomicNode *battery =
            node(a, QStringLiteral("py_inherit_demo.battery.BatteryMonitor"));
        QVERIFY(battery);
        QCOMPARE(battery->nodeName, QStringLiteral("battery_monitor"));
        QCOMPARE(battery->baseClasses,
                 (QStringList{QStringLiteral("EstopMixin"), QStringLiteral("MonitorBase")}));
        const QString bat = QStringLiteral(" @src/py_inherit_demo/py_inherit_demo/battery.py:");
        QCOMPARE(portLines(*battery),
                 (QStringList{
                     status + QStringLiteral(" inherited") + base + QStringLiteral("11:27-11:74"),
                     reset + QStringLiteral(" inherited") + base + QStringLiteral("12:26-12:78"),
                     QStringLiteral(
                         "subscriber estop std_msgs/msg/String cb=on_estop literal inherited") +
                         base + QStringLiteral("26:9-26:68"),
                     QStringLiteral(
                         "subscriber battery sensor_msgs/msg/BatteryState cb=on_battery literal") +
                         bat + QStringLiteral("11:9-11:79"),
                     QStringLiteral(
                         "publisher battery_summary sensor_msgs/msg/BatteryState cb= literal") +
                         bat + QStringLiteral("16:9-16:66")}));

        // no constructor of its own: node name from its instantiation; super().setup() keeps
        // heartbeat
        const QString temp =
            QStringLiteral(" @src/py_inherit_demo/py_inherit_demo/temperature.py:");
        const AtomicNode *temperature =
            node(a, QStringLiteral("py_inherit_demo.temperature.TemperatureMonitor"));
        QVERIFY(temperature);
        QCOMPARE(temperature->nodeName, QStringLiteral("temperature_monitor"));
        QCOMPARE(temperature->baseClasses, QStringList{QStringLiteral("base.MonitorBase")});
        QCOMPARE(
            portLines(*temperature),
            (QStringList{
                status + QStringLiteral(" inherited") + base + QStringLiteral("11:27-11:74"),
                reset + QStringLiteral(" inherited") + base + QStringLiteral("12:26-12:78"),
                heartbeat + QStringLiteral(" inherited") + base + QStringLiteral("16:26-16:71"),
                QStringLiteral("subscriber temperature sensor_msgs/msg/Temperature "
                               "cb=on_temperature literal") +
                    temp + QStringLiteral("11:9-11:86")}));

        // two levels down; the status topic comes from the keyword it passes up
        const AtomicNode *cpu =
            node(a, QStringLiteral("py_inherit_demo.temperature.CpuTemperatureMonitor"));
        QVERIFY(cpu);
        QCOMPARE(cpu->nodeName, QStringLiteral("cpu_temperature"));
        QVERIFY(!cpu->lifecycle);
        QCOMPARE(
            portLines(*cpu),
            (QStringList{
                QStringLiteral("publisher cpu_status std_msgs/msg/String cb= local "
                               "expr=status_topic inherited") +
                    base + QStringLiteral("11:27-11:74"),
                reset + QStringLiteral(" inherited") + base + QStringLiteral("12:26-12:78"),
                heartbeat + QStringLiteral(" inherited") + base + QStringLiteral("16:26-16:71"),
                QStringLiteral("subscriber temperature sensor_msgs/msg/Temperature "
                               "cb=on_temperature literal inherited") +
                    temp + QStringLiteral("11:9-11:86"),
                QStringLiteral(
                    "publisher cpu_temperature_max sensor_msgs/msg/Temperature cb= literal") +
                    temp + QStringLiteral("21:9-21:69")}));
    }

    void syntaxErrorKeepsTheRest()
    {
        const LanguageAnalysis a = analyzeFixture(QStringLiteral("py_syntax_error"));
        QCOMPARE(qualifiedNames(a), (QStringList{QStringLiteral("py_broken_demo.broken.After"),
                                                 QStringLiteral("py_broken_demo.broken.Before")}));
        const AtomicNode *after = node(a, QStringLiteral("py_broken_demo.broken.After"));
        QCOMPARE(range(after->evidence),
                 QStringLiteral("src/py_broken_demo/py_broken_demo/broken.py:17:1-24:13"));
        QCOMPARE(portLines(*after),
                 QStringList{
                     QStringLiteral("subscriber after_topic std_msgs/msg/String cb=on_msg literal "
                                    "@src/py_broken_demo/py_broken_demo/broken.py:21:9-21:73")});
        QVERIFY(!a.diagnostics.isEmpty());
        for (const Diagnostic &d : a.diagnostics) {
            QCOMPARE(d.code, QStringLiteral("syntax-error"));
            QCOMPARE(d.evidence.file,
                     QStringLiteral("src/py_broken_demo/py_broken_demo/broken.py"));
            QVERIFY2(d.evidence.line == 13 || d.evidence.line == 14, qPrintable(d.message));
        }
        QCOMPARE(a.entryPoints.size(), 1);
        QCOMPARE(a.entryPoints.first().instantiatedClasses,
                 QStringList{QStringLiteral("py_broken_demo.broken.After")});
    }

    void handBuiltWorkspaceAndUnreadableFile()
    {
        Workspace ws;
        ws.root = dataDir(QStringLiteral("py_basic/ws"));
        SourceFile talker;
        talker.path = QStringLiteral("src/py_basic_demo/py_basic_demo/talker.py");
        talker.package = QStringLiteral("py_basic_demo");
        talker.language = SourceFile::Language::Python;
        SourceFile missing = talker;
        missing.path = QStringLiteral("src/py_basic_demo/py_basic_demo/missing.py");
        SourceFile notPython = talker;
        notPython.path = QStringLiteral("src/py_basic_demo/setup.py");
        notPython.language = SourceFile::Language::SetupPy;
        ws.files = {missing, notPython, talker};
        const LanguageAnalysis a = PythonNodeAnalyzer(ws).analyze();
        // no __init__.py and no package folder known: the module is named by its path
        QCOMPARE(qualifiedNames(a),
                 QStringList{QStringLiteral("src.py_basic_demo.py_basic_demo.talker.Talker")});
        QCOMPARE(a.nodes.first().packageName, QStringLiteral("py_basic_demo"));
        QCOMPARE(a.diagnostics.size(), 1);
        QCOMPARE(a.diagnostics.first().code, QStringLiteral("unreadable-file"));
        QCOMPARE(a.diagnostics.first().evidence.file, missing.path);
    }

    void progressAndCancellation()
    {
        const Workspace ws = WorkspaceScanner::scan(dataDir(QStringLiteral("py_basic/ws")));
        int pythonFiles = 0;
        for (const SourceFile &f : ws.files)
            pythonFiles += f.language == SourceFile::Language::Python ? 1 : 0;
        QCOMPARE(pythonFiles, 8);
        QList<int> done;
        StageControl control;
        control.progressed = [&](int d, int total, const QString &) {
            QCOMPARE(total, pythonFiles);
            done << d;
        };
        PythonNodeAnalyzer(ws).analyze(control);
        QCOMPARE(done, (QList<int>{0, 1, 2, 3, 4, 5, 6, 7, 8}));

        // Files are analysed in parallel: each polls once before it starts, and the result is
        // dropped once the run is canceled.
        std::atomic<int> polls = 0;
        control.progressed = {};
        control.canceled = [&] { return ++polls > 2; };
        const LanguageAnalysis canceled = PythonNodeAnalyzer(ws).analyze(control);
        QVERIFY(canceled.nodes.isEmpty());
        QVERIFY(canceled.entryPoints.isEmpty());
        QVERIFY(canceled.diagnostics.isEmpty());
        QVERIFY2(polls > 2 && polls <= pythonFiles + 1, qPrintable(QString::number(polls)));
    }

    void deterministic()
    {
        for (const QString &fixture :
             {QStringLiteral("py_basic"), QStringLiteral("py_inherit"),
              QStringLiteral("py_helpers"), QStringLiteral("py_behaviour_tree")}) {
            const LanguageAnalysis first = analyzeFixture(fixture);
            const LanguageAnalysis second = analyzeFixture(fixture);
            QCOMPARE(first.nodes, second.nodes);
            QCOMPARE(first.entryPoints, second.entryPoints);
        }
    }

    // In a long-lived process the analysis is reused while every file's key is the same; an
    // edited, added or removed file, or one skipped, analyses again: always what a fresh run gives.
    void keptAnalysisFollowsEdits()
    {
        QTemporaryDir temp;
        QVERIFY(temp.isValid());
        const QString root = temp.filePath(QStringLiteral("ws"));
        test::copyTree(test::dataDir(QStringLiteral("compose_system/ws")), root);
        AnalysisCache cache(temp.filePath(QStringLiteral("cache")), AnalysisCache::kDefaultMaxBytes,
                            0);
        StageControl control;
        control.cache = &cache;
        const auto kept = [&] {
            return PythonNodeAnalyzer(WorkspaceScanner::scan(root, control)).analyze(control);
        };
        const auto fresh = [&] {
            AnalysisCache off{QString()};
            StageControl plain = control;
            plain.cache = &off;
            return PythonNodeAnalyzer(WorkspaceScanner::scan(root, plain)).analyze(plain);
        };
        const auto topics = [](const LanguageAnalysis &a) {
            QStringList out;
            for (const AtomicNode &n : a.nodes)
                for (const Port &p : n.ports)
                    out << n.className + QLatin1Char(' ') + p.name;
            return out;
        };
        const auto same = [&](const LanguageAnalysis &a, const LanguageAnalysis &b) {
            return a.nodes == b.nodes && a.entryPoints == b.entryPoints &&
                   a.registrations == b.registrations && a.diagnostics == b.diagnostics;
        };
        const LanguageAnalysis first = kept();
        QVERIFY(same(first, fresh()));
        QVERIFY(topics(first).contains(QStringLiteral("Planner cmd_vel")));
        QVERIFY(same(kept(), first));

        const QString planner = root + QStringLiteral("/src/planning/planning/planner.py");
        QByteArray text = test::readFile(planner);
        text.replace("'cmd_vel'", "'cmd_vel_out'");
        test::writeFile(planner, text);
        QVERIFY(topics(kept()).contains(QStringLiteral("Planner cmd_vel_out")));
        QVERIFY(same(kept(), fresh()));
        test::writeFile(root + QStringLiteral("/src/planning/planning/extra.py"),
                        "from rclpy.node import Node\n\n\nclass Extra(Node):\n"
                        "    def __init__(self):\n        super().__init__('extra')\n"
                        "        self.create_publisher(Empty, 'extra_topic', 1)\n");
        QVERIFY(topics(kept()).contains(QStringLiteral("Extra extra_topic")));
        QVERIFY(same(kept(), fresh()));
        QVERIFY(QFile::remove(root + QStringLiteral("/src/planning/planning/extra.py")));
        QVERIFY(!topics(kept()).contains(QStringLiteral("Extra extra_topic")));
        QVERIFY(same(kept(), fresh()));
        control.skipped.insert(QStringLiteral("src/planning/planning/planner.py"),
                               QStringLiteral("crashed"));
        QVERIFY(!topics(kept()).contains(QStringLiteral("Planner cmd_vel_out")));
        QVERIFY(same(kept(), fresh()));
    }
};

QTEST_GUILESS_MAIN(TestPythonNodeAnalyzer)
#include "tst_pythonnodeanalyzer.moc"
