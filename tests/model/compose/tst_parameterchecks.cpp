// The parameter checks (blueprint §1, "Parameters of a class"; docs/checks.md): what an
// instance is given against what its class and plugins declare, on the params_checks
// (rclcpp, nav2_util and rclpy declarations, a follower plugin), params_generated
// (generate_parameter_library) and params_handler (a handler's getter, critics) fixtures.
#include "core/parameter.h"
#include "core/parameterview.h"
#include "nodes/generatedparameters.h"
#include "pipeline/recovery.h"
#include "support/recoverytest.h"
#include "support/testsupport.h"

#include <QtTest>

using namespace rosarch;

namespace {

/// "code file:line parameter" of each parameter finding, sorted.
QStringList findings(const Recovery &r)
{
    QStringList out;
    for (const Diagnostic &d : r.architecture.diagnostics)
        if (d.code.startsWith(QLatin1String("parameter-")))
            out << QStringLiteral("%1 %2:%3 %4")
                       .arg(d.code, d.evidence.file.section(u'/', -1))
                       .arg(d.evidence.line)
                       .arg(d.message.section(QStringLiteral("parameter '"), 1)
                                .section(u'\'', 0, 0));
    out.sort();
    return out;
}

const NodeInstance *instance(const Recovery &r, const QString &name)
{
    for (const NodeInstance &n : r.launch.nodes)
        if (n.nodeName == name)
            return &n;
    return nullptr;
}

} // namespace

class TestParameterChecks : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void valueTypes()
    {
        QCOMPARE(parameterValueType(QStringLiteral("10")), QStringLiteral("integer"));
        QCOMPARE(parameterValueType(QStringLiteral("10"), true), QStringLiteral("string"));
        QCOMPARE(parameterValueType(QStringLiteral("1e-3")), QStringLiteral("double"));
        QCOMPARE(parameterValueType(QStringLiteral("True")), QStringLiteral("bool"));
        QCOMPARE(parameterValueType(QStringLiteral("[0.5, 1.0]")), QStringLiteral("double_array"));
        QCOMPARE(parameterValueType(QStringLiteral("[]")), QString());
        QCOMPARE(parameterValueType(QStringLiteral("$(var rate)")), QString());
        QCOMPARE(parameterTypeOfWritten(QStringLiteral("std::vector<std::string>")),
                 QStringLiteral("string_array"));
        QCOMPARE(parameterTypeOfWritten(QStringLiteral("int64_t")), QStringLiteral("integer"));
        QCOMPARE(parameterTypeOfWritten(QStringLiteral("rclcpp::ParameterType::PARAMETER_DOUBLE")),
                 QStringLiteral("double"));
        QVERIFY(!parameterTypeAccepts(QStringLiteral("double"), QStringLiteral("integer")));
        QVERIFY(
            parameterNameMatches(QStringLiteral("{source}.topic"), QStringLiteral("scan.topic")));
        QVERIFY(
            !parameterNameMatches(QStringLiteral("{source}.topic"), QStringLiteral("scan.type")));
    }

    void misconfiguredValuesAreFound()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("params_checks/ws")));
        QCOMPARE(findings(r),
                 (QStringList{
                     QStringLiteral("parameter-missing drive.launch.py:12 wheel_base"),
                     QStringLiteral("parameter-range drive_params.yaml:12 scale_velocities"),
                     QStringLiteral("parameter-type drive_params.yaml:11 window"),
                     QStringLiteral("parameter-type drive_params.yaml:13 odom_duration"),
                     QStringLiteral("parameter-type drive_params.yaml:37 rate"),
                     QStringLiteral("parameter-undeclared drive_params.yaml:18 limits.max_acel"),
                     QStringLiteral("parameter-undeclared drive_params.yaml:32 "
                                    "FollowPath.lookahead_distance"),
                     QStringLiteral("parameter-undeclared drive_params.yaml:8 smoothing_frequncy"),
                 }));
        // The misspelt key names the declared one it was meant to be.
        QStringList hints;
        for (const Diagnostic &d : r.architecture.diagnostics)
            if (d.message.contains(QLatin1String("Did you mean")))
                hints
                    << d.message.section(QStringLiteral("Did you mean '"), 1).section(u'\'', 0, 0);
        hints.sort();
        QCOMPARE(hints, (QStringList{QStringLiteral("FollowPath.lookahead_dist"),
                                     QStringLiteral("limits.max_accel"),
                                     QStringLiteral("smoothing_frequency")}));
        // what a free function (a prefix it is handed) and a helper class declare is the node's
        const ParameterView view(r.nodes);
        QStringList declared;
        for (const InstanceParameter &p : view.of(*instance(r, QStringLiteral("speed_limiter"))))
            if (p.declared && (p.name.startsWith(QLatin1String("sources.")) ||
                               p.name.startsWith(QLatin1String("feedback_gain"))))
                declared << p.name + u'=' + p.value;
        QCOMPARE(declared, (QStringList{QStringLiteral("feedback_gain=0.5"),
                                        QStringLiteral("sources.scan=true")}));
    }

    void instanceParametersJoinDeclarationAndValue()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("params_checks/ws")));
        const NodeInstance *follow = instance(r, QStringLiteral("follow_server"));
        QVERIFY(follow);
        const ParameterView view(r.nodes);
        QStringList rows;
        for (const InstanceParameter &p : view.of(*follow))
            rows << QStringLiteral("%1|%2|%3|%4|%5|%6")
                        .arg(p.name, p.plugin, p.type, p.value, p.source,
                             p.declared ? QStringLiteral("declared") : QStringLiteral("-"));
        QCOMPARE(
            rows,
            (QStringList{
                QStringLiteral("FollowPath.desired_linear_vel|FollowPath|double|0.5|file|declared"),
                QStringLiteral("FollowPath.lookahead_dist|FollowPath|double|0.6|default|declared"),
                QStringLiteral("FollowPath.lookahead_distance|||0.6|file|-"),
                QStringLiteral(
                    "FollowPath.plugin||string|drive_plugins::PurePursuit|file|declared"),
                QStringLiteral(
                    "FollowPath.use_rotate_to_heading|FollowPath|bool|true|file|declared"),
                QStringLiteral("controller_frequency||double|15.0|launch|declared"),
                QStringLiteral("follower_plugins||string_array|[FollowPath]|file|declared"),
                QStringLiteral("log_level|||info|file|-"),
                QStringLiteral("use_sim_time|||false|file|declared"),
            }));
    }

    void generatedDefinitionsPastTheirBoundSaySo()
    {
        QByteArray yaml = "gen:\n";
        QByteArray indent = "  ";
        for (int i = 0; i < 40; ++i, indent += "  ")
            yaml += indent + "level" + QByteArray::number(i) + ":\n";
        yaml += indent + "deepest:\n" + indent + "  type: double\n";
        QList<Diagnostic> diagnostics;
        const QList<ParameterDeclaration> read =
            GeneratedParameters::read(yaml, QStringLiteral("src/p/params.yaml"), &diagnostics);
        QVERIFY(read.isEmpty());
        QCOMPARE(diagnostics.size(), 1);
        QCOMPARE(diagnostics.first().code, QStringLiteral("evaluation-limit"));
        QCOMPARE(diagnostics.first().evidence.file, QStringLiteral("src/p/params.yaml"));
    }

    void generatedDefinitionsAreDeclarations()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("params_generated/ws")));
        QCOMPARE(findings(r),
                 (QStringList{
                     QStringLiteral("parameter-missing gripper.launch.xml:2 command_topic"),
                     QStringLiteral("parameter-range gripper.yaml:4 speed"),
                     QStringLiteral("parameter-range gripper.yaml:6 mode"),
                     QStringLiteral("parameter-type gripper.yaml:5 max_effort"),
                     QStringLiteral("parameter-undeclared gripper.yaml:13 gains.finger_right.d"),
                     QStringLiteral("parameter-undeclared gripper.yaml:7 gripper_frame"),
                 }));
    }

    // A handler's getter declares under the controller plugin's name, and the critics the
    // controller loads by class name declare under theirs: only the misspelt key is found.
    void handlerGetterDeclaresPerPluginInstance()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("params_handler/ws")));
        QCOMPARE(findings(r), (QStringList{QStringLiteral(
                                  "parameter-undeclared floor.yaml:13 Sweep.SpeedCritic.wieght")}));
        bool guessed = false;
        for (const Diagnostic &d : r.architecture.diagnostics)
            guessed = guessed || d.message.contains(QLatin1String("'Sweep.SpeedCritic.weight'"));
        QVERIFY(guessed);
        const NodeInstance *server = instance(r, QStringLiteral("floor_server"));
        QVERIFY(server);
        const ParameterView view(r.nodes);
        QHash<QString, QString> plugins;
        for (const auto &[name, cls] : view.loadedPlugins(*server))
            plugins.insert(name, cls->className);
        QCOMPARE(plugins.value(QStringLiteral("Sweep")), QStringLiteral("Sweeper"));
        QCOMPARE(plugins.value(QStringLiteral("Sweep.EdgeCritic")), QStringLiteral("EdgeCritic"));
        QCOMPARE(plugins.value(QStringLiteral("Sweep.SpeedCritic")), QStringLiteral("SpeedCritic"));
        QStringList declared;
        for (const ParameterDeclaration &d : view.declarationsOf(*server))
            declared << d.name;
        QVERIFY(declared.contains(QStringLiteral("Sweep.lane_width"))); // the member planner's
        QVERIFY(declared.contains(QStringLiteral("Sweep.EdgeCritic.margin")));
        QVERIFY(declared.contains(QStringLiteral("control_rate")));         // an empty namespace
        QVERIFY(declared.contains(QStringLiteral("floor_server.verbose"))); // the node's name
    }
};

QTEST_GUILESS_MAIN(TestParameterChecks)
#include "tst_parameterchecks.moc"
