#include "analysistext.h"
#include "launch/python/pythonlaunchreader.h"
#include "support/testsupport.h"

#include <QElapsedTimer>
#include <QtTest>

using namespace rosarch;
using K = LaunchAction::Kind;

namespace {

LaunchFileDescription readSource(const char *source)
{
    return PythonLaunchReader::read(QByteArray(source),
                                    QStringLiteral("pkg/launch/test_launch.py"));
}

QStringList read(const char *source)
{
    return AnalysisText::actions(readSource(source).actions);
}

/// A fixture of tests/data/pylaunch_reader, read as the file "pylaunch_reader/<name>".
LaunchFileDescription readFixture(const char *name)
{
    const QString file = QStringLiteral("pylaunch_reader/") + QLatin1String(name);
    return PythonLaunchReader::read(test::readFile(test::dataDir(file)), file);
}

QStringList readFixtureDump(const char *name)
{
    return AnalysisText::actions(readFixture(name).actions);
}

} // namespace

class TestPythonLaunchReader : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void detectsLaunchFilesByContent();
    void nodesParametersRemappings();
    void rewrittenYamlAndNodeRenames();
    void actionsThroughVariablesAndLists();
    void legacyAndLifecycleNodes();
    void composableNodes();
    void includes();
    void scopes();
    void substitutions();
    void conditions();
    void decidedAndUndecidedIfs();
    void undecidedNamesAndReturns();
    void anActionBothReturnsHoldRunsOnce();
    void loopsComprehensionsAndHelpers();
    void opaqueFunctions();
    void unknownAndHarmlessActions();
    void syntaxErrorsStillRead();
    void boundedOnPathologicalInput();
    void notALaunchDescription();
};

void TestPythonLaunchReader::detectsLaunchFilesByContent()
{
    QVERIFY(PythonLaunchReader::isLaunchFile(
        "from launch import LaunchDescription\n\n"
        "def generate_launch_description():\n    return LaunchDescription([])\n"));
    QVERIFY(PythonLaunchReader::isLaunchFile(
        "import launch\n@decorator\n"
        "def generate_launch_description():\n    return launch.LaunchDescription()\n"));
    // a helper module under launch/ that only mentions the function is not a launch file
    QVERIFY(
        !PythonLaunchReader::isLaunchFile("# call generate_launch_description() from the bringup\n"
                                          "def make_nodes():\n    return []\n"));
    QVERIFY(!PythonLaunchReader::isLaunchFile(
        "class Helper:\n    def generate_launch_description(self):\n        pass\n"));
    QVERIFY(!PythonLaunchReader::isLaunchFile(
        "def outer():\n    def generate_launch_description():\n        pass\n"));
    QVERIFY(!PythonLaunchReader::isLaunchFile(QByteArray()));
    static const char binary[] = "\x00\x01\x02generate_launch_description\xff";
    QVERIFY(!PythonLaunchReader::isLaunchFile(QByteArray(binary, sizeof(binary) - 1)));
}

void TestPythonLaunchReader::nodesParametersRemappings()
{
    const LaunchFileDescription desc = readFixture("nodes_launch.py");
    QCOMPARE(desc.file, QStringLiteral("pylaunch_reader/nodes_launch.py"));
    QCOMPARE(desc.format, LaunchFileDescription::Format::Python);
    QVERIFY(desc.diagnostics.isEmpty());
    QCOMPARE(AnalysisText::actions(desc.actions),
             (QStringList{
                 QStringLiteral("Arg name=use_sim_time value=false desc=Use sim time @10"),
                 QStringLiteral("Node pkg=demo_nodes_cpp exe=talker name=talker ns=$(var ns|robot) "
                                "remap:chatter->/chat remap:/tf->tf "
                                "param:use_sim_time=$(var use_sim_time) param:rate=10 "
                                "param:gains=[1.0, 2.5] param:debug=true "
                                "param:pid.p=0.5 paramfile:/etc/params.yaml @11"),
                 QStringLiteral("Node pkg=demo_nodes_py exe=listener remap:chatter->/chat @14")}));
    // Evidence of the node, its remaps and parameters: the call expression.
    const LaunchAction &talker = desc.actions.at(1);
    const Evidence call{QStringLiteral("pylaunch_reader/nodes_launch.py"), 11, 9, 13, 63};
    QCOMPARE(talker.evidence, call);
    QCOMPARE(talker.remaps.first().evidence, call);
    QCOMPARE(talker.parameters.last().evidence, call);
    QCOMPARE(talker.parameters.first().value.kind, Substitution::Kind::LaunchConfiguration);
    QCOMPARE(talker.nameSpace.parts,
             QList<Substitution>{Substitution::literal(QStringLiteral("robot"))});
    QCOMPARE(talker.nameSpace.describe(), QStringLiteral("$(var ns)"));
    QVERIFY(!talker.lifecycle);
    QVERIFY(!talker.condition.isSet());
}

void TestPythonLaunchReader::rewrittenYamlAndNodeRenames()
{
    const LaunchFileDescription desc = readFixture("renamed_launch.py");
    QVERIFY(desc.diagnostics.isEmpty());
    QCOMPARE(AnalysisText::actions(desc.actions),
             (QStringList{QStringLiteral("Node pkg=planner exe=plan name=global_planner ns=/nav "
                                         "paramfile:RewrittenYaml(join[$(find-pkg-share "
                                         "planner_bringup), config, p.yaml], $(var robot), "
                                         "use_sim_time, $(var sim), rate, 5, =ZONE, on) @22"),
                          QStringLiteral("Node pkg=planner exe=plan name=kept ns=/fleet "
                                         "remap:map->/map @24")}));
    const Substitution &file = desc.actions.at(0).parameters.at(0).value;
    QCOMPARE(file.kind, Substitution::Kind::RewrittenYaml);
    QCOMPARE(file.parts.size(), 8);
}

void TestPythonLaunchReader::actionsThroughVariablesAndLists()
{
    QCOMPARE(
        readFixtureDump("variables_launch.py"),
        (QStringList{QStringLiteral("Arg name=a @11"), QStringLiteral("Arg name=b value=1 @11"),
                     QStringLiteral("Node pkg=demo exe=talker @6"),
                     QStringLiteral("Node pkg=demo exe=listener @8"),
                     QStringLiteral("Node pkg=demo exe=relay @9"),
                     QStringLiteral("Node pkg=demo exe=echo @10")}));

    QCOMPARE(
        readFixtureDump("splat_launch.py"),
        (QStringList{QStringLiteral("Arg name=x @8"), QStringLiteral("Node pkg=demo exe=e @9")}));
}

void TestPythonLaunchReader::legacyAndLifecycleNodes()
{
    QCOMPARE(readFixtureDump("legacy_launch.py"),
             (QStringList{QStringLiteral("Node pkg=old exe=talker name=old_talker ns=legacy @7"),
                          QStringLiteral("Node pkg=lc exe=lc_talker name=lc_talker lifecycle @8"),
                          QStringLiteral(
                              "Node pkg=lc exe=lc_listener name=lc_listener ns=ns lifecycle @9")}));
}

void TestPythonLaunchReader::composableNodes()
{
    QCOMPARE(
        readFixtureDump("composable_launch.py"),
        (QStringList{
            QStringLiteral("Container pkg=rclcpp_components exe=component_container "
                           "name=my_container ns=$(var namespace) @9"),
            QStringLiteral("  Composable pkg=composition plugin=composition::Talker name=talker "
                           "remap:chatter->talk param:rate=2 @12"),
            QStringLiteral("Load target=cat[$(var namespace), /my_container] @16"),
            QStringLiteral(
                "  Composable pkg=composition plugin=composition::Listener name=listener @18"),
            QStringLiteral("Load target=my_container @19"),
            QStringLiteral("  Composable pkg=composition plugin=composition::Server ns=srv @20")}));
}

void TestPythonLaunchReader::includes()
{
    const LaunchFileDescription desc = readFixture("includes_launch.py");
    QCOMPARE(
        AnalysisText::actions(desc.actions),
        (QStringList{
            QStringLiteral("Include path=join[$(find-pkg-share nav2_bringup), launch, "
                           "rviz_launch.py] arg:namespace=robot1 "
                           "arg:use_sim_time=true if($(var use_rviz)) @18"),
            QStringLiteral(
                "Include path=cat[$(dirname), /state_publisher.launch.py] arg:model=burger @21"),
            QStringLiteral("Include path=join[$(find-pkg-share demo), launch, x.launch.xml] "
                           "arg:a=1 arg:b=$(var use_rviz) @23"),
            QStringLiteral("Include path=/opt/ros/y.launch.yaml @25"),
            QStringLiteral("Include path=/plain/path_launch.py @26")}));
    QCOMPARE(desc.actions.first().condition.text, QStringLiteral("IfCondition(use_rviz)"));
    QCOMPARE(desc.actions.first().path.describe(),
             QStringLiteral("$(find-pkg-share nav2_bringup)/launch/rviz_launch.py"));
}

void TestPythonLaunchReader::scopes()
{
    QCOMPARE(
        readFixtureDump("scopes_launch.py"),
        (QStringList{QStringLiteral("Group scoped @8"), QStringLiteral("  PushNs ns=robot @9"),
                     QStringLiteral("  PushNs ns=arm @10"),
                     QStringLiteral("  SetRemap remap:/tf->tf @11"),
                     QStringLiteral("  SetParam param:use_sim_time=true @12"),
                     QStringLiteral("  Node pkg=p exe=e @13"), QStringLiteral("Group unscoped @15"),
                     QStringLiteral("  Let name=mode value=fast @15"),
                     QStringLiteral("SetRemap remap:a->b @16"), QStringLiteral("Group scoped @17"),
                     QStringLiteral("  Let name=level value=debug @17"),
                     QStringLiteral("  Node pkg=p exe=f @17")}));
}

void TestPythonLaunchReader::substitutions()
{
    const LaunchFileDescription desc = readFixture("substitutions_launch.py");
    QStringList got;
    for (const LaunchAction &a : desc.actions) {
        QCOMPARE(a.kind, K::DeclareArgument);
        QCOMPARE(a.evidence.line, 12); // the call inside the helper
        got << a.name.text + QLatin1Char('=') + AnalysisText::substitution(a.value);
    }
    QCOMPARE(
        got,
        (QStringList{
            QStringLiteral("env=$(env HOME|/root)"),
            QStringLiteral("prefix=$(find-pkg-prefix demo)"),
            QStringLiteral("joined=join[$(find-pkg-share demo), config, waffle.yaml]"),
            QStringLiteral("eval=$(eval not  ~ $(var ns) ~  == \"x\")"),
            QStringLiteral("text=plain"), QStringLiteral("fstring=cat[waffle_, $(var ns)]"),
            QStringLiteral("concat=cat[$(var ns), /cmd_vel]"), QStringLiteral("plus=robot_waffle"),
            QStringLiteral("percent=model_waffle_3"), QStringLiteral("format=waffle/base"),
            QStringLiteral("str=waffle2\t"), QStringLiteral("dir=join[$(dirname), params.yaml]"),
            QStringLiteral("env2=$(env MODEL|burger)"), QStringLiteral("env3=$(env LDS)"),
            QStringLiteral("this=$(dirname)"), QStringLiteral("unknown=?{some_module.compute(ns)}"),
            QStringLiteral("join=/waffle/base")}));
    QCOMPARE(desc.actions.at(3).value.describe(), QStringLiteral("$(eval not $(var ns) == \"x\")"));
}

void TestPythonLaunchReader::conditions()
{
    const LaunchFileDescription desc = readFixture("conditions_launch.py");
    QCOMPARE(
        AnalysisText::actions(desc.actions),
        (QStringList{
            QStringLiteral("Node pkg=p exe=a if($(var use_a)) @9"),
            QStringLiteral("Node pkg=p exe=b unless($(eval ' ~ $(var mode) ~ ' == 'sim')) @10"),
            QStringLiteral("Node pkg=p exe=c if($(eval ' ~ $(var mode) ~ ' == 'real')) @11"),
            QStringLiteral("Node pkg=p exe=d if($(eval ' ~ $(var mode) ~ ' != 'real')) @12"),
            QStringLiteral("Node pkg=p exe=e if(?{custom_condition}) @13")}));
    QCOMPARE(desc.actions.at(0).condition.text,
             QStringLiteral("IfCondition(LaunchConfiguration('use_a'))"));
    QCOMPARE(desc.actions.at(2).condition.text,
             QStringLiteral("LaunchConfigurationEquals('mode', 'real')"));
    QCOMPARE(desc.actions.at(2).condition.expression.describe(),
             QStringLiteral("$(eval '$(var mode)' == 'real')"));
}

void TestPythonLaunchReader::decidedAndUndecidedIfs()
{
    const LaunchFileDescription desc = readFixture("ifs_launch.py");
    QCOMPARE(AnalysisText::actions(desc.actions),
             (QStringList{
                 QStringLiteral("Node pkg=sim exe=decided @12"),
                 QStringLiteral("Group unscoped if(?{os.environ.get('ROBOT') == 'real'}) @15"),
                 QStringLiteral("  Node pkg=hw exe=driver @16"),
                 QStringLiteral("  Node pkg=hw exe=imu @17"),
                 QStringLiteral("Group unscoped unless(?{os.environ.get('ROBOT') == 'real'}) @18"),
                 QStringLiteral("  Node pkg=sim exe=fake @19")}));
    const LaunchAction &group = desc.actions.at(1);
    QCOMPARE(group.condition.text, QStringLiteral("os.environ.get('ROBOT') == 'real'"));
    QCOMPARE(group.evidence.endLine, 17);              // the `if` branch
    QCOMPARE(desc.actions.at(2).evidence.endLine, 21); // the elif/else chain
}

void TestPythonLaunchReader::undecidedNamesAndReturns()
{
    // Names keep the first branch's value (the best guess); returns in branches become groups.
    QCOMPARE(readFixtureDump("undecided_launch.py"),
             (QStringList{QStringLiteral("Group unscoped if(?{len(sys.argv) > 2}) @15"),
                          QStringLiteral("  Node pkg=p exe=first name=x @14"),
                          QStringLiteral("Group unscoped unless(?{len(sys.argv) > 2}) @15"),
                          QStringLiteral("  Node pkg=p exe=fallback @17")}));
}

void TestPythonLaunchReader::anActionBothReturnsHoldRunsOnce()
{
    // `if c: return [simulator]` ... `return [simulator, converter]`: the simulator runs
    // whichever return is taken, so it is one action, not one per branch.
    QCOMPARE(readFixtureDump("shared_returns_launch.py"),
             (QStringList{QStringLiteral("Unresolved expr=OpaqueFunction(setup) @18"),
                          QStringLiteral("Group unscoped @18"),
                          QStringLiteral("  Node pkg=sim exe=simulator name=simulator @10"),
                          QStringLiteral("  Group unscoped unless(?{'no_converter' in sys.argv}) "
                                         "@11"),
                          QStringLiteral("    Node pkg=sim exe=converter name=converter @13")}));
}

void TestPythonLaunchReader::loopsComprehensionsAndHelpers()
{
    QCOMPARE(readFixtureDump("loops_launch.py"),
             (QStringList{
                 QStringLiteral("Node pkg=sim exe=spawn name=r1_spawner param:x=0.0 @8"),
                 QStringLiteral("Node pkg=sim exe=spawn name=r2_spawner param:x=1.5 @8"),
                 QStringLiteral("Node pkg=e exe=x @24"),
                 QStringLiteral("Group unscoped if(?{for unknown in robots_from_yaml()}) @25"),
                 QStringLiteral("  Node pkg=u exe=per_robot name=?{unknown} @26"),
                 QStringLiteral("Node pkg=drv exe=driver ns=a remap:cmd_vel->/a/cmd_vel @20")}));
}

void TestPythonLaunchReader::opaqueFunctions()
{
    QCOMPARE(
        readFixtureDump("opaque_launch.py"),
        (QStringList{QStringLiteral("Arg name=model value=burger @19"),
                     QStringLiteral("Unresolved expr=OpaqueFunction(launch_setup) @20"),
                     QStringLiteral("Group unscoped @20"),
                     QStringLiteral("  Node pkg=p exe=a ns=$(var namespace) param:model=$(var "
                                    "model) param:rate=$(var rate|10) @11"),
                     QStringLiteral("  Group unscoped if(?{model == 'burger'}) @12"),
                     QStringLiteral("    Node pkg=p exe=burger_only @13"),
                     QStringLiteral("Unresolved expr=OpaqueFunction(undefined_elsewhere) @21")}));
}

void TestPythonLaunchReader::unknownAndHarmlessActions()
{
    QCOMPARE(
        readFixtureDump("unknown_actions_launch.py"),
        (QStringList{
            QStringLiteral(
                "Unresolved expr=ExecuteProcess(cmd=['ros2', 'bag', 'record', '-a']) @14"),
            QStringLiteral("Node pkg=controller_manager exe=spawner @9"),
            QStringLiteral(
                "Unresolved expr=RegisterEventHandler(OnProcessExit(target_action=spawner, "
                "on_exit=[rviz])) @16"),
            QStringLiteral("Group unscoped @16"), QStringLiteral("  Node pkg=rviz2 exe=rviz2 @10"),
            QStringLiteral("Group unscoped @17"), QStringLiteral("  Node pkg=late exe=starter @17"),
            QStringLiteral("Unresolved expr=make_custom_action() @18")}));
}

void TestPythonLaunchReader::syntaxErrorsStillRead()
{
    const LaunchFileDescription desc = readFixture("syntax_error_launch.py");
    QVERIFY(!desc.diagnostics.isEmpty());
    QCOMPARE(desc.diagnostics.first().code, QStringLiteral("syntax-error"));
    QCOMPARE(desc.diagnostics.first().severity, Diagnostic::Severity::Error);
    QCOMPARE(desc.diagnostics.first().evidence.line, 7);
    QCOMPARE(AnalysisText::actions(desc.actions),
             (QStringList{QStringLiteral("Node pkg=p exe=talker @6"),
                          QStringLiteral("Node pkg=p exe=listener @8")}));
}

void TestPythonLaunchReader::boundedOnPathologicalInput()
{
    QElapsedTimer timer;
    timer.start();
    // unbounded recursion, an endless loop, lists and strings that double, deep nesting
    const LaunchFileDescription desc = readFixture("pathological_launch.py");
    QVERIFY(timer.elapsed() < 5000);
    QCOMPARE(desc.actions.size() > 2, true);
    QCOMPARE(desc.actions.at(0).kind, K::Unresolved);
    QCOMPARE(desc.actions.at(0).expression, QStringLiteral("forever(n + 1)"));
    QCOMPARE(desc.actions.at(1).executable.kind, Substitution::Kind::Unknown);
    QVERIFY(desc.actions.size() > 1000); // 2^30 nodes are cut by the walk budget
    QVERIFY(desc.actions.size() < 30000);

    QByteArray deep = "from launch import LaunchDescription\n\ndef "
                      "generate_launch_description():\n    return LaunchDescription(";
    deep += QByteArray(3000, '[') + QByteArray(3000, ']') + ")\n";
    const LaunchFileDescription nested =
        PythonLaunchReader::read(deep, QStringLiteral("deep_launch.py"));
    QVERIFY(nested.actions.size() <= 1);

    // the evaluation budget: nested loops multiply, the reader stops and says so
    const LaunchFileDescription busy = readFixture("budget_launch.py");
    QVERIFY(busy.actions.isEmpty());
    QStringList codes;
    for (const Diagnostic &diag : busy.diagnostics)
        codes << QStringLiteral("%1@%2").arg(diag.code).arg(diag.evidence.line);
    QCOMPARE(codes, (QStringList{QStringLiteral("launch-loop-limit@8"),
                                 QStringLiteral("launch-loop-limit@7"),
                                 QStringLiteral("launch-evaluation-limit@9")})); // where it stopped
    QVERIFY(timer.elapsed() < 10000);
}

void TestPythonLaunchReader::notALaunchDescription()
{
    const LaunchFileDescription none = readSource("def main():\n    pass\n");
    QVERIFY(none.actions.isEmpty());
    QCOMPARE(none.diagnostics.size(), 1);
    QCOMPARE(none.diagnostics.first().code, QStringLiteral("no-launch-description"));

    const LaunchFileDescription nothing =
        readSource("def generate_launch_description():\n    x = 1\n");
    QVERIFY(nothing.actions.isEmpty());
    QCOMPARE(nothing.diagnostics.size(), 1);
    QCOMPARE(nothing.diagnostics.first().code, QStringLiteral("launch-description-unknown"));
    QCOMPARE(nothing.diagnostics.first().evidence.line, 1);

    // launch_testing files return a tuple; the description inside is read
    QCOMPARE(read("import launch\nimport launch_ros.actions\n\ndef generate_launch_description():\n"
                  "    node = launch_ros.actions.Node(package='p', executable='e')\n"
                  "    return launch.LaunchDescription([node]), {'node': node}\n"),
             QStringList{QStringLiteral("Node pkg=p exe=e @5")});
}

QTEST_GUILESS_MAIN(TestPythonLaunchReader)
#include "tst_pythonlaunchreader.moc"
