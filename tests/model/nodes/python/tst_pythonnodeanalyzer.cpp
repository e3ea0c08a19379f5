#include "pythonnodeanalyzer.h"
#include "syntaxtree.h"
#include "testsupport.h"
#include "workspacescanner.h"

#include <QtTest>

using namespace rosarch;
using rosarch::test::dataDir;

namespace {

QString range(const Evidence &e)
{
    return QStringLiteral("%1:%2:%3-%4:%5")
        .arg(e.file)
        .arg(e.line)
        .arg(e.column)
        .arg(e.endLine)
        .arg(e.endColumn);
}

/// Every field of a port on one line, so that a comparison shows exactly what differs.
QString portLine(const Port &p)
{
    QStringList s{portKindName(p.kind), p.name, p.type, QStringLiteral("cb=") + p.callback,
                  nameOriginName(p.nameOrigin)};
    if (!p.nameExpression.isEmpty())
        s << QStringLiteral("expr=") + p.nameExpression;
    if (!p.parameter.isEmpty())
        s << QStringLiteral("param=") + p.parameter;
    if (!p.guard.isEmpty())
        s << QStringLiteral("guard=[%1]").arg(p.guard);
    if (!p.guardParameter.isEmpty())
        s << QStringLiteral("guard_param=") + p.guardParameter;
    if (!p.via.isEmpty())
        s << QStringLiteral("via=") + p.via;
    if (p.inherited)
        s << QStringLiteral("inherited");
    s << QStringLiteral("@") + range(p.evidence);
    return s.join(QLatin1Char(' '));
}

QStringList portLines(const AtomicNode &n)
{
    QStringList out;
    for (const Port &p : n.ports)
        out << portLine(p);
    return out;
}

LanguageAnalysis analyzeFixture(const QString &name)
{
    const Workspace ws = WorkspaceScanner::scan(dataDir(name + QStringLiteral("/ws")));
    return PythonNodeAnalyzer(ws).analyze();
}

const AtomicNode *node(const LanguageAnalysis &a, const QString &qualifiedName)
{
    for (const AtomicNode &n : a.nodes)
        if (n.qualifiedName == qualifiedName)
            return &n;
    return nullptr;
}

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

QStringList qualifiedNames(const LanguageAnalysis &a)
{
    QStringList out;
    for (const AtomicNode &n : a.nodes)
        out << n.qualifiedName;
    return out;
}

} // namespace

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
                QStringLiteral("publisher self.get_name() + '/debug' std_msgs/msg/String cb= "
                               "expression expr=self.get_name() + '/debug'") +
                    f + QStringLiteral("31:9-31:70"),
                QStringLiteral("publisher f'{self.get_name()}/formatted' std_msgs/msg/String cb= "
                               "expression expr=f'{self.get_name()}/formatted'") +
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
        QVERIFY(!n->ports.at(6).isResolved());
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
        QCOMPARE(monitor->nodeName, QStringLiteral("name")); // never instantiated: the expression
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

        int polls = 0;
        control.progressed = {};
        control.canceled = [&] { return ++polls > 2; };
        const LanguageAnalysis canceled = PythonNodeAnalyzer(ws).analyze(control);
        QVERIFY(canceled.nodes.isEmpty());
        QVERIFY(canceled.entryPoints.isEmpty());
        QCOMPARE(polls, 3);
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
};

QTEST_GUILESS_MAIN(TestPythonNodeAnalyzer)
#include "tst_pythonnodeanalyzer.moc"
