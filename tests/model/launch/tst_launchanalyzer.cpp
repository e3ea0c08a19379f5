// Stage 2 semantics on hand-built launch descriptions (readers are tested separately), the
// substitution evaluator, and the same system in three formats read from fixture files.
#include "launchexecutor.h"
#include "launchsupport.h"
#include "recovery.h"
#include "substitutionevaluator.h"
#include "testsupport.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;
using rosarch::test::launch::var;

namespace {

Substitution lit(const QString &s)
{
    return Substitution::literal(s);
}

Substitution share(const QString &pkg, const QString &rest)
{
    Substitution s;
    s.kind = Substitution::Kind::FindPackageShare;
    s.parts << lit(pkg);
    Substitution join;
    join.kind = Substitution::Kind::PathJoin;
    join.parts << s << lit(rest);
    return join;
}

Evidence at(const QString &file, int line)
{
    return Evidence{file, line, 1, line, 10};
}

LaunchAction node(const QString &pkg, const QString &exe, const QString &name, int line)
{
    LaunchAction a;
    a.kind = LaunchAction::Kind::Node;
    a.package = lit(pkg);
    a.executable = lit(exe);
    a.name = lit(name);
    a.evidence = at(QStringLiteral("x"), line);
    return a;
}

LaunchAction declare(const QString &name, const QString *value)
{
    LaunchAction a;
    a.kind = LaunchAction::Kind::DeclareArgument;
    a.name = lit(name);
    if (value) {
        a.value = lit(*value);
        a.hasValue = true;
    }
    return a;
}

LaunchAction include(const Substitution &path, QList<QPair<Substitution, Substitution>> args = {})
{
    LaunchAction a;
    a.kind = LaunchAction::Kind::Include;
    a.path = path;
    a.arguments = std::move(args);
    return a;
}

/// A workspace folder with real files (include resolution checks them) and hand-built readers.
struct Fixture
{
    QTemporaryDir dir;
    Workspace ws;
    AtomicNodeList nodes;
    QMap<QString, LaunchFileDescription> files;

    Fixture()
    {
        ws.root = dir.path();
        RosPackage pkg;
        pkg.name = QStringLiteral("bringup");
        pkg.path = QStringLiteral("bringup");
        pkg.buildType = QStringLiteral("ament_cmake");
        ws.packages << pkg;
        AtomicNode talker;
        talker.id = QStringLiteral("arc_1");
        talker.className = QStringLiteral("Talker");
        talker.nodeName = QStringLiteral("talker_in_code");
        talker.packageName = QStringLiteral("demo");
        talker.executables << QStringLiteral("talker");
        talker.compileType = AtomicNode::CompileType::Python;
        AtomicNode filter;
        filter.id = QStringLiteral("arc_2");
        filter.className = QStringLiteral("Filter");
        filter.nodeName = QStringLiteral("filter");
        filter.packageName = QStringLiteral("demo");
        filter.plugins << QStringLiteral("demo::Filter");
        nodes.nodes << talker << filter;
    }

    void add(const QString &path, QList<LaunchAction> actions)
    {
        QDir(dir.path()).mkpath(QFileInfo(path).path());
        QFile f(dir.filePath(path));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("# launch\n");
        SourceFile sf;
        sf.path = path;
        sf.package = QStringLiteral("bringup");
        sf.language = SourceFile::Language::Python;
        ws.files << sf;
        LaunchFileDescription d;
        d.file = path;
        d.actions = std::move(actions);
        files.insert(path, d);
    }

    LaunchDependencies run(const QString &root, const QMap<QString, QString> &args = {})
    {
        LaunchDependencies out;
        LaunchExecutor exec(
            ws, nodes,
            [this](const QString &f) -> const LaunchFileDescription * {
                const auto it = files.constFind(f);
                return it == files.constEnd() ? nullptr : &*it;
            },
            &out);
        exec.runRoot(root, args);
        return out;
    }
};

/// "name=value (source line)" for each effective parameter of `n`.
QStringList effective(const NodeInstance &n)
{
    QStringList out;
    for (const ParameterSetting &p : n.effectiveParameters)
        out << QStringLiteral("%1=%2 (%3 %4)").arg(p.name, p.value, p.source).arg(p.evidence.line);
    return out;
}

LaunchParameter parameterFile(const Substitution &path)
{
    return LaunchParameter{Substitution(), path, true, at(QStringLiteral("x"), 9)};
}

LaunchParameter value(const QString &name, const QString &v)
{
    return LaunchParameter{lit(name), lit(v), false, at(QStringLiteral("x"), 8)};
}

QStringList summary(const LaunchDependencies &d)
{
    QStringList out;
    for (const NodeInstance &n : d.nodes) {
        QStringList remaps;
        for (const auto &[f, t] : n.remaps)
            remaps << f + QStringLiteral("->") + t;
        QStringList params;
        for (const auto &[k, v] : n.parameters)
            params << k + QLatin1Char('=') + v;
        out << QStringLiteral("%1 %2 %3 class=%4 kind=%5 active=%6 remaps=[%7] params=[%8]")
                   .arg(n.nameSpace, n.nodeName, n.execName, n.className, n.nodeKind)
                   .arg(n.active)
                   .arg(remaps.join(','), params.join(','));
    }
    return out;
}

} // namespace

class TestLaunchAnalyzer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void namespacesAndScopes()
    {
        Fixture fx;
        LaunchAction push;
        push.kind = LaunchAction::Kind::PushNamespace;
        push.nameSpace = var(QStringLiteral("ns"));
        LaunchAction group;
        group.kind = LaunchAction::Kind::Group;
        group.children << push
                       << node(QStringLiteral("demo"), QStringLiteral("talker"), QString(), 3);
        LaunchAction absolute =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("abs"), 4);
        absolute.nameSpace = lit(QStringLiteral("/fixed"));
        group.children << absolute;
        const QString ns = QStringLiteral("robot");
        fx.add(
            QStringLiteral("bringup/launch/a.launch.py"),
            {declare(QStringLiteral("ns"), &ns), group,
             node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("after"), 5)});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/a.launch.py"));
        QCOMPARE(
            summary(d),
            (QStringList{"/robot talker_in_code talker class=Talker kind=python active=1 remaps=[] "
                         "params=[]",
                         "/fixed abs talker class=Talker kind=python active=1 remaps=[] params=[]",
                         "/ after talker class=Talker kind=python active=1 remaps=[] params=[]"}));
        QCOMPARE(d.instances.size(), 1);
        QCOMPARE(d.instances[0].namespaces.value(QStringLiteral("/robot")), QStringList{"n1"});
        QCOMPARE(d.instances[0].namespaces.value(QStringLiteral("/")), QStringList{"n3"});
        QCOMPARE(d.arguments.size(), 1);
        QCOMPARE(d.arguments[0].defaultValue, QStringLiteral("robot"));

        // The person's value wins over the default.
        const LaunchDependencies d2 =
            fx.run(QStringLiteral("bringup/launch/a.launch.py"), {{"ns", "other"}});
        QCOMPARE(d2.nodes[0].nameSpace, QStringLiteral("/other"));
    }

    void includesPassArgumentsAndResolveThroughPackages()
    {
        Fixture fx;
        LaunchAction remap;
        remap.kind = LaunchAction::Kind::SetRemap;
        remap.remaps << LaunchRemap{lit(QStringLiteral("a")), lit(QStringLiteral("b")), {}};
        LaunchAction child =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("t"), 2);
        LaunchParameter p{lit(QStringLiteral("rate")), var(QStringLiteral("rate")), false, {}};
        child.parameters << p;
        fx.add(QStringLiteral("bringup/launch/child.launch.py"),
               {declare(QStringLiteral("rate"), nullptr), child});
        LaunchAction ext =
            include(share(QStringLiteral("not_here"), QStringLiteral("launch/x.launch.py")));
        fx.add(QStringLiteral("bringup/launch/root.launch.py"),
               {remap,
                include(share(QStringLiteral("bringup"), QStringLiteral("launch/child.launch.py")),
                        {{lit(QStringLiteral("rate")), lit(QStringLiteral("10"))}}),
                include(share(QStringLiteral("bringup"), QStringLiteral("launch/child.launch.py"))),
                ext});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/root.launch.py"));
        QCOMPARE(d.instances.size(), 4); // root, child twice, external
        QCOMPARE(d.instances[0].includedLaunchFiles, (QStringList{"lf2", "lf3", "lf4"}));
        QCOMPARE(d.instances[1].file, QStringLiteral("bringup/launch/child.launch.py"));
        QCOMPARE(d.instances[1].parentId, QStringLiteral("lf1"));
        QCOMPARE(d.instances[2].file, QStringLiteral("bringup/launch/child.launch.py"));
        QVERIFY(d.instances[3].external);
        QCOMPARE(d.instances[3].package, QStringLiteral("not_here"));
        QCOMPARE(summary(d),
                 (QStringList{
                     "/ t talker class=Talker kind=python active=1 remaps=[a->b] params=[rate=10]",
                     "/ t talker class=Talker kind=python active=1 remaps=[a->b] params=[rate=]"}));
        // The second include passes no value: recorded, not dropped.
        QCOMPARE(d.instances[2].unresolved.size(), 1);
        QCOMPARE(d.instances[2].unresolved[0].kind, QStringLiteral("argument"));
        QCOMPARE(d.nodes[1].unresolved.size(), 1);
        QCOMPARE(d.nodes[1].unresolved[0].kind, QStringLiteral("launch-configuration"));
    }

    void includeCyclesAreReported()
    {
        Fixture fx;
        fx.add(QStringLiteral("bringup/launch/a.launch.py"),
               {include(share(QStringLiteral("bringup"), QStringLiteral("launch/b.launch.py")))});
        fx.add(QStringLiteral("bringup/launch/b.launch.py"),
               {include(share(QStringLiteral("bringup"), QStringLiteral("launch/a.launch.py")))});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/a.launch.py"));
        QCOMPARE(d.instances.size(), 3);
        QCOMPARE(d.diagnostics.size(), 1);
        QCOMPARE(d.diagnostics[0].code, QStringLiteral("include-cycle"));
        QVERIFY(d.diagnostics[0].message.contains(QStringLiteral(
            "a.launch.py → bringup/launch/b.launch.py → bringup/launch/a.launch.py")));
        QCOMPARE(d.instances[2].unresolved.last().kind, QStringLiteral("cycle"));
    }

    void conditionsDecideOrAreMarked()
    {
        Fixture fx;
        LaunchAction off =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("off"), 2);
        off.condition.expression = var(QStringLiteral("flag"));
        off.condition.text = QStringLiteral("IfCondition(flag)");
        LaunchAction on = off;
        on.name = lit(QStringLiteral("on"));
        on.condition.unless = true;
        LaunchAction unknown =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("unknown"), 4);
        unknown.condition.expression = Substitution::unknown(QStringLiteral("context.perform()"));
        unknown.condition.text = QStringLiteral("context.perform()");
        LaunchAction eval =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("eval"), 5);
        eval.condition.expression.kind = Substitution::Kind::Eval;
        eval.condition.expression.parts << lit(QStringLiteral("'")) << var(QStringLiteral("flag"))
                                        << lit(QStringLiteral("' == 'false'"));
        eval.condition.text = QStringLiteral("PythonExpression");
        const QString flag = QStringLiteral("false");
        fx.add(QStringLiteral("bringup/launch/c.launch.py"),
               {declare(QStringLiteral("flag"), &flag), off, on, unknown, eval});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/c.launch.py"));
        QCOMPARE(d.nodes.size(), 4);
        QCOMPARE(d.nodes[0].active, false);
        QCOMPARE(d.nodes[1].active, true);
        QCOMPARE(d.nodes[2].active, true);
        QCOMPARE(d.nodes[2].unresolved.size(), 1);
        QCOMPARE(d.nodes[2].unresolved[0].kind, QStringLiteral("condition"));
        QCOMPARE(d.nodes[2].unresolved[0].guess, QStringLiteral("true"));
        QCOMPARE(d.nodes[3].active, true);
        QVERIFY(d.nodes[3].unresolved.isEmpty());
    }

    void composableNodesAndContainers()
    {
        Fixture fx;
        LaunchAction container;
        container.kind = LaunchAction::Kind::ComposableContainer;
        container.package = lit(QStringLiteral("rclcpp_components"));
        container.executable = lit(QStringLiteral("component_container"));
        container.name = lit(QStringLiteral("box"));
        LaunchAction comp;
        comp.kind = LaunchAction::Kind::ComposableNode;
        comp.package = lit(QStringLiteral("demo"));
        comp.plugin = lit(QStringLiteral("demo::Filter"));
        container.children << comp;
        LaunchAction load;
        load.kind = LaunchAction::Kind::LoadComposableNodes;
        load.target = lit(QStringLiteral("box"));
        LaunchAction later = comp;
        later.name = lit(QStringLiteral("later"));
        load.children << later;
        fx.add(QStringLiteral("bringup/launch/k.launch.py"), {container, load});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/k.launch.py"));
        QCOMPARE(
            summary(d),
            (QStringList{
                "/ box component_container class= kind=cpp active=1 remaps=[] params=[]",
                "/ filter demo::Filter class=Filter kind=composable active=1 remaps=[] params=[]",
                "/ later demo::Filter class=Filter kind=composable active=1 remaps=[] params=[]"}));
        QCOMPARE(d.nodes[1].container, QStringLiteral("n1"));
        QCOMPARE(d.nodes[2].container, QStringLiteral("n1"));
    }

    void executableWithTwoNodesStartsBoth()
    {
        Fixture fx;
        AtomicNode a;
        a.id = QStringLiteral("arc_3");
        a.className = QStringLiteral("Driver");
        a.nodeName = QStringLiteral("driver");
        a.packageName = QStringLiteral("demo");
        a.executables << QStringLiteral("duo");
        AtomicNode b = a;
        b.id = QStringLiteral("arc_4");
        b.className = QStringLiteral("Odometry");
        b.nodeName = QStringLiteral("odometry");
        fx.nodes.nodes << a << b;
        fx.add(QStringLiteral("bringup/launch/d.launch.py"),
               {node(QStringLiteral("demo"), QStringLiteral("duo"), QString(), 2)});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/d.launch.py"));
        QCOMPARE(
            summary(d),
            (QStringList{"/ driver duo class=Driver kind=cpp active=1 remaps=[] params=[]",
                         "/ odometry duo class=Odometry kind=cpp active=1 remaps=[] params=[]"}));
        QCOMPARE(d.instances[0].nodes, (QStringList{"n1", "n2"}));
        QCOMPARE(d.nodes[1].evidence, d.nodes[0].evidence);
    }

    void executableBuiltByAnotherPackage()
    {
        // Package `drivers` installs its executable `lidar` under `bringup`'s name; the launch
        // file names it as bringup's. It is typed by the one class that builds it, with a note.
        // Before, the instance stayed untyped.
        Fixture fx;
        AtomicNode lidar;
        lidar.id = QStringLiteral("arc_7");
        lidar.className = QStringLiteral("LidarDriver");
        lidar.nodeName = QStringLiteral("lidar");
        lidar.packageName = QStringLiteral("drivers");
        lidar.executables << QStringLiteral("lidar");
        fx.nodes.nodes << lidar;
        fx.add(QStringLiteral("bringup/launch/l.launch.py"),
               {node(QStringLiteral("bringup"), QStringLiteral("lidar"), QString(), 3),
                node(QStringLiteral("bringup"), QStringLiteral("missing"), QString(), 4)});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/l.launch.py"));
        QCOMPARE(d.nodes.size(), 2);
        QCOMPARE(d.nodes[0].classId, QStringLiteral("arc_7"));
        QCOMPARE(d.nodes[0].className, QStringLiteral("LidarDriver"));
        QCOMPARE(d.nodes[0].package, QStringLiteral("bringup"));
        QCOMPARE(d.nodes[1].classId, QString()); // nobody builds it
        QStringList notes;
        for (const Diagnostic &diag : d.diagnostics)
            if (diag.code == QLatin1String("executable-in-other-package"))
                notes << diag.message;
        QCOMPARE(notes, QStringList{QStringLiteral(
                            "The executable lidar is started as part of package bringup, which "
                            "does not build it; package drivers of the workspace does, so the "
                            "instance is typed by its class.")});
    }

    void parameterFilesApplyAsRos2Does()
    {
        // Node keys by namespace and name, the /** wildcard before the node's own entry, later
        // sources over earlier ones, nested keys dotted, code defaults last (blueprint §1).
        Fixture fx;
        fx.nodes.nodes[0].ports << Port{};
        Port &named = fx.nodes.nodes[0].ports.last();
        named.id = QStringLiteral("p1");
        named.name = QStringLiteral("chatter");
        named.nameOrigin = NameOrigin::Parameter;
        named.parameter = QStringLiteral("topic_default_only");
        QDir(fx.dir.path()).mkpath(QStringLiteral("bringup/config"));
        QFile yaml(fx.dir.filePath(QStringLiteral("bringup/config/p.yaml")));
        QVERIFY(yaml.open(QIODevice::WriteOnly));
        yaml.write("/**:\n"                 // 1
                   "  ros__parameters:\n"   // 2
                   "    rate: 1\n"          // 3
                   "    topic: all\n"       // 4
                   "ns1:\n"                 // 5
                   "  talker:\n"            // 6
                   "    ros__parameters:\n" // 7
                   "      topic: mine\n"    // 8
                   "      nested:\n"        // 9
                   "        deep: [1, 2]\n" // 10
                   "/other:\n"              // 11
                   "  ros__parameters:\n"   // 12
                   "    topic: nope\n");    // 13
        yaml.close();
        const Substitution file = share(QStringLiteral("bringup"), QStringLiteral("config/p.yaml"));
        LaunchAction inNs =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("talker"), 3);
        inNs.nameSpace = lit(QStringLiteral("ns1"));
        inNs.parameters = {parameterFile(file), value(QStringLiteral("rate"), QStringLiteral("5"))};
        LaunchAction atRoot =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("talker"), 4);
        atRoot.parameters = {value(QStringLiteral("rate"), QStringLiteral("7")),
                             parameterFile(file)};
        fx.add(QStringLiteral("bringup/launch/p.launch.py"), {inNs, atRoot});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/p.launch.py"));
        QCOMPARE(d.nodes.size(), 2);
        QCOMPARE(
            effective(d.nodes[0]),
            (QStringList{QStringLiteral("nested.deep=[1, 2] (file 10)"),
                         QStringLiteral("rate=5 (launch 8)"), QStringLiteral("topic=mine (file 8)"),
                         QStringLiteral("topic_default_only=chatter (default 0)")}));
        QCOMPARE(
            effective(d.nodes[1]),
            (QStringList{QStringLiteral("rate=1 (file 3)"), QStringLiteral("topic=all (file 4)"),
                         QStringLiteral("topic_default_only=chatter (default 0)")}));
        QCOMPARE(d.nodes[0].effectiveParameters.first().file,
                 QStringLiteral("bringup/config/p.yaml"));
        QVERIFY(d.diagnostics.isEmpty());
    }

    void rewrittenYamlRewritesAndMovesUnderTheRootKey()
    {
        Fixture fx;
        QDir(fx.dir.path()).mkpath(QStringLiteral("bringup/config"));
        QFile yaml(fx.dir.filePath(QStringLiteral("bringup/config/base.yaml")));
        QVERIFY(yaml.open(QIODevice::WriteOnly));
        yaml.write("talker:\n  ros__parameters:\n    topic: base\n    use_sim_time: false\n"
                   "    other: kept\n    zone:\n      enabled: ZONE_ON\n");
        yaml.close();
        Substitution rewritten;
        rewritten.kind = Substitution::Kind::RewrittenYaml;
        rewritten.parts << share(QStringLiteral("bringup"), QStringLiteral("config/base.yaml"))
                        << var(QStringLiteral("namespace")) << lit(QStringLiteral("topic"))
                        << lit(QStringLiteral("rewritten")) << lit(QStringLiteral("missing"))
                        << lit(QStringLiteral("not added")) // value_rewrites: by value
                        << lit(QStringLiteral("=ZONE_ON")) << lit(QStringLiteral("true"));
        const QString robot = QStringLiteral("robot");
        LaunchAction talker =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("talker"), 3);
        talker.nameSpace = var(QStringLiteral("namespace"));
        talker.parameters = {parameterFile(rewritten)};
        LaunchAction plain = node(QStringLiteral("demo"), QStringLiteral("talker"),
                                  QStringLiteral("talker"), 4); // at the root: the key moved
        plain.parameters = {parameterFile(rewritten)};
        fx.add(QStringLiteral("bringup/launch/r.launch.py"),
               {declare(QStringLiteral("namespace"), &robot), talker, plain});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/r.launch.py"));
        QCOMPARE(d.nodes.size(), 2);
        QCOMPARE(d.nodes[0].nameSpace, QStringLiteral("/robot"));
        QCOMPARE(effective(d.nodes[0]),
                 (QStringList{QStringLiteral("other=kept (file 5)"),
                              QStringLiteral("topic=rewritten (launch 9)"),
                              QStringLiteral("use_sim_time=false (file 4)"),
                              QStringLiteral("zone.enabled=true (launch 9)")}));
        QCOMPARE(effective(d.nodes[1]), QStringList());
    }

    void pluginsAreNamedByParameters()
    {
        // pluginlib's convention: `<name>.plugin: "pkg::Class"` loads plugin <name>.
        Fixture fx;
        QDir(fx.dir.path()).mkpath(QStringLiteral("bringup/config"));
        QFile yaml(fx.dir.filePath(QStringLiteral("bringup/config/server.yaml")));
        QVERIFY(yaml.open(QIODevice::WriteOnly));
        yaml.write("talker:\n  ros__parameters:\n    controller_plugins: [\"Follow\"]\n"
                   "    Follow:\n      plugin: \"ctrl_pkg::Follower\"\n      speed: 0.5\n"
                   "    Checker:\n      plugin: ctrl_pkg/Checker\n"
                   "    NotAClass:\n      plugin: \"just words\"\n");
        yaml.close();
        LaunchAction a =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("talker"), 3);
        a.parameters = {
            parameterFile(share(QStringLiteral("bringup"), QStringLiteral("config/server.yaml")))};
        fx.add(QStringLiteral("bringup/launch/s.launch.py"), {a});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/s.launch.py"));
        QCOMPARE(d.nodes.size(), 1);
        QStringList plugins;
        for (const ParameterSetting &p : d.nodes[0].plugins)
            plugins << QStringLiteral("%1=%2 @%3").arg(p.name, p.value).arg(p.evidence.line);
        QCOMPARE(plugins, (QStringList{QStringLiteral("Checker=ctrl_pkg/Checker @8"),
                                       QStringLiteral("Follow=ctrl_pkg::Follower @5")}));
    }

    void parameterFileProblemsAreSaid()
    {
        Fixture fx;
        QDir(fx.dir.path()).mkpath(QStringLiteral("bringup/config"));
        QFile broken(fx.dir.filePath(QStringLiteral("bringup/config/broken.yaml")));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("talker:\n  ros__parameters:\n    rate: [1, 2\n");
        broken.close();
        QFile flat(fx.dir.filePath(QStringLiteral("bringup/config/flat.yaml")));
        QVERIFY(flat.open(QIODevice::WriteOnly));
        flat.write("rate: 3\n");
        flat.close();
        LaunchAction a =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("talker"), 3);
        a.parameters = {
            parameterFile(share(QStringLiteral("bringup"), QStringLiteral("config/missing.yaml"))),
            parameterFile(share(QStringLiteral("bringup"), QStringLiteral("config/broken.yaml"))),
            parameterFile(share(QStringLiteral("bringup"), QStringLiteral("config/flat.yaml"))),
            parameterFile(share(QStringLiteral("elsewhere"), QStringLiteral("p.yaml")))};
        fx.add(QStringLiteral("bringup/launch/b.launch.py"), {a});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/b.launch.py"));
        QStringList codes;
        for (const Diagnostic &diag : d.diagnostics)
            codes << diag.code + QLatin1Char(' ') + diag.evidence.file;
        QCOMPARE(codes,
                 (QStringList{QStringLiteral("no-such-parameter-file x"),
                              QStringLiteral("malformed-yaml bringup/config/broken.yaml"),
                              QStringLiteral("parameter-file-unused bringup/config/flat.yaml"),
                              QStringLiteral("no-such-parameter-file x")}));
        QVERIFY(d.diagnostics.last().message.contains(QLatin1String("elsewhere")));
        QCOMPARE(d.nodes.size(), 1);
    }

    void parameterFileNodeKeys_data()
    {
        QTest::addColumn<QString>("pattern");
        QTest::addColumn<QString>("fqn");
        QTest::addColumn<bool>("matches");
        QTest::newRow("exact") << "/ns/talker"
                               << "/ns/talker" << true;
        QTest::newRow("other namespace") << "/ns/talker"
                                         << "/talker" << false;
        QTest::newRow("everything") << "/**"
                                    << "/a/b/c" << true;
        QTest::newRow("one segment") << "/*/talker"
                                     << "/ns/talker" << true;
        QTest::newRow("one segment, not none") << "/*/talker"
                                               << "/talker" << false;
        QTest::newRow("any depth") << "/**/talker"
                                   << "/a/b/talker" << true;
        QTest::newRow("any depth, also none") << "/**/talker"
                                              << "/talker" << true;
        QTest::newRow("prefix") << "/robot/**"
                                << "/robot/x/y" << true;
        QTest::newRow("prefix, other") << "/robot/**"
                                       << "/rover/x" << false;
    }

    void parameterFileNodeKeys()
    {
        QFETCH(QString, pattern);
        QFETCH(QString, fqn);
        QFETCH(bool, matches);
        QCOMPARE(ParameterFile::matches(pattern, fqn), matches);
    }

    void aParameterFileBombIsCut()
    {
        // Aliases that double at every level stand for 2^40 nodes in a few hundred bytes.
        QByteArray yaml = "a0: &a0 [x, x]\n";
        for (int i = 1; i < 40; ++i)
            yaml += QStringLiteral("a%1: &a%1 [*a%2, *a%2]\n").arg(i).arg(i - 1).toUtf8();
        yaml += "talker:\n  ros__parameters:\n    big: *a39\n";
        const ParameterFile f = ParameterFile::read(yaml, QStringLiteral("bomb.yaml"));
        QStringList codes;
        for (const Diagnostic &d : f.diagnostics)
            codes << d.code;
        QCOMPARE(codes, QStringList{QStringLiteral("launch-evaluation-limit")});
    }

    void pythonExpressions_data()
    {
        QTest::addColumn<QString>("expression");
        QTest::addColumn<QString>("value");
        QTest::newRow("eq") << "'a' == 'a'"
                            << "true";
        QTest::newRow("neq") << "'a' != 'a'"
                             << "false";
        QTest::newRow("not") << "not true"
                             << "false";
        QTest::newRow("and-or") << "('x' == 'y') or (True and not False)"
                                << "true";
        QTest::newRow("in") << "'b' in ['a', 'b']"
                            << "true";
        QTest::newRow("not in") << "'c' not in ['a', 'b']"
                                << "true";
        QTest::newRow("number") << "2 == 2.0"
                                << "true";
    }

    void pythonExpressions()
    {
        QFETCH(QString, expression);
        QFETCH(QString, value);
        QString out;
        QVERIFY(SubstitutionEvaluator::evaluatePython(expression, &out));
        QCOMPARE(out, value);
    }

    void pythonExpressionsBeyondTheSubsetAreRefused()
    {
        QString out;
        QVERIFY(!SubstitutionEvaluator::evaluatePython(QStringLiteral("os.environ['X']"), &out));
        QVERIFY(!SubstitutionEvaluator::evaluatePython(QStringLiteral("'a' =="), &out));
    }

    void sameSystemInThreeFormats()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("launch_formats/ws")));
        QCOMPARE(r.launch.launchFiles.size(), 3);
        QMap<QString, QStringList> byFormat;
        for (const LaunchFileInstance &i : r.launch.instances) {
            LaunchDependencies one;
            for (const NodeInstance &n : r.launch.nodes)
                if (n.launchFileId == i.id)
                    one.nodes << n;
            byFormat.insert(i.format, summary(one));
        }
        QCOMPARE(byFormat.size(), 3);
        QCOMPARE(byFormat.value(QStringLiteral("xml")), byFormat.value(QStringLiteral("python")));
        QCOMPARE(byFormat.value(QStringLiteral("yaml")), byFormat.value(QStringLiteral("python")));
        QCOMPARE(byFormat.value(QStringLiteral("python")),
                 (QStringList{"/chat talker talker class=Talker kind=python active=1 "
                              "remaps=[chatter->conversation] params=[]",
                              "/chat listener listener class=Listener kind=python active=1 "
                              "remaps=[chatter->conversation] params=[rate=5]"}));
    }
};

QTEST_GUILESS_MAIN(TestLaunchAnalyzer)
#include "tst_launchanalyzer.moc"
