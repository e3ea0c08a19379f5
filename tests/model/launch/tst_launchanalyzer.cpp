// Stage 2 semantics on hand-built launch descriptions (readers are tested separately), the
// substitution evaluator, and the same system in three formats read from fixture files.
#include "executorfixture.h"
#include "launch/substitutionevaluator.h"
#include "pipeline/recovery.h"
#include "support/testsupport.h"

#include <QtTest>

using namespace rosarch;
using rosarch::test::launch::var;

using namespace rosarch::test::executor;

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

    // autoware's detection launch: an argument nobody sets reaches a remapping through an
    // include and a `let`. The guess ('') is used, and the mark follows it all the way.
    void aGuessedValueStaysUnresolvedThroughIncludesAndLets()
    {
        Fixture fx;
        Substitution target;
        target.kind = Substitution::Kind::Concat;
        target.parts = {lit(QStringLiteral("/detection/")), var(QStringLiteral("model_here")),
                        lit(QStringLiteral("/objects"))};
        LaunchAction let;
        let.kind = LaunchAction::Kind::SetLaunchConfiguration;
        let.name = lit(QStringLiteral("output"));
        let.value = target;
        LaunchAction detector =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("detector"), 4);
        detector.remaps
            << LaunchRemap{lit(QStringLiteral("~/in")), lit(QStringLiteral("/points")), {}}
            << LaunchRemap{lit(QStringLiteral("~/out")), var(QStringLiteral("output")), {}};
        LaunchAction chosen =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("chosen"), 5);
        chosen.condition.expression.kind = Substitution::Kind::Eval;
        chosen.condition.expression.parts = {lit(QStringLiteral("'")),
                                             var(QStringLiteral("model_here")),
                                             lit(QStringLiteral("' == 'centerpoint'"))};
        chosen.condition.text = QStringLiteral("$(eval '$(var model_here)' == 'centerpoint')");
        fx.add(QStringLiteral("bringup/launch/detector.launch.py"),
               {declare(QStringLiteral("model_here"), nullptr), let, detector, chosen});
        fx.add(
            QStringLiteral("bringup/launch/root.launch.py"),
            {declare(QStringLiteral("model"), nullptr),
             include(share(QStringLiteral("bringup"), QStringLiteral("launch/detector.launch.py")),
                     {{lit(QStringLiteral("model_here")), var(QStringLiteral("model"))}})});

        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/root.launch.py"));
        QCOMPARE(d.nodes.size(), 2);
        const NodeInstance &det = d.nodes[0];
        QCOMPARE(det.remaps.at(1).second, QStringLiteral("/detection//objects")); // the guess
        QCOMPARE(det.guessedRemaps, QList<int>{1}); // the first remapping is known
        QVERIFY(!det.unresolved.isEmpty());
        QCOMPARE(det.unresolved[0].kind, QStringLiteral("launch-configuration"));
        QCOMPARE(det.unresolved[0].expression, QStringLiteral("$(var output)"));
        QCOMPARE(det.unresolved[0].guess, QStringLiteral("/detection//objects"));
        // A condition on the guess cannot be decided: the node is kept, marked, as at the root.
        QCOMPARE(d.nodes[1].active, true);
        QCOMPARE(d.nodes[1].unresolved.size(), 1);
        QCOMPARE(d.nodes[1].unresolved[0].kind, QStringLiteral("condition"));

        // Given a value, nothing is a guess any more.
        const LaunchDependencies given =
            fx.run(QStringLiteral("bringup/launch/root.launch.py"), {{"model", "centerpoint"}});
        QCOMPARE(given.nodes[0].remaps.at(1).second,
                 QStringLiteral("/detection/centerpoint/objects"));
        QVERIFY(given.nodes[0].guessedRemaps.isEmpty());
        QVERIFY(given.nodes[0].unresolved.isEmpty());
        QCOMPARE(given.nodes[1].active, true);
        QVERIFY(given.nodes[1].unresolved.isEmpty());
        const LaunchDependencies other =
            fx.run(QStringLiteral("bringup/launch/root.launch.py"), {{"model", "apollo"}});
        QCOMPARE(other.nodes[1].active, false);
    }

    // A robot's namespace pushed from an argument nobody sets: the namespace the nodes get is a
    // guess, and so is the name of one that reads its name from such an argument.
    void aNamespaceOrNameFromAGuessMarksTheInstance()
    {
        Fixture fx;
        LaunchAction push;
        push.kind = LaunchAction::Kind::PushNamespace;
        push.nameSpace = var(QStringLiteral("robot"));
        LaunchAction reset; // an absolute namespace replaces the guess around it
        reset.kind = LaunchAction::Kind::PushNamespace;
        reset.nameSpace = lit(QStringLiteral("/fixed"));
        LaunchAction named =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QString(), 4); // name below
        named.name = var(QStringLiteral("who"));
        LaunchAction absolute =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("abs"), 5);
        absolute.nameSpace = lit(QStringLiteral("/known"));
        LaunchAction group;
        group.kind = LaunchAction::Kind::Group;
        group.children << push << named << absolute;
        LaunchAction later;
        later.kind = LaunchAction::Kind::Group;
        later.children << push << reset
                       << node(QStringLiteral("demo"), QStringLiteral("talker"),
                               QStringLiteral("after_reset"), 7);
        fx.add(
            QStringLiteral("bringup/launch/robot.launch.py"),
            {declare(QStringLiteral("robot"), nullptr), declare(QStringLiteral("who"), nullptr),
             group, later,
             node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("outside"), 8)});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/robot.launch.py"));
        QCOMPARE(d.nodes.size(), 4);
        QCOMPARE(d.nodes[0].guessedNamespace, true);
        QCOMPARE(d.nodes[0].guessedName, true);
        QCOMPARE(d.nodes[1].nameSpace, QStringLiteral("/known"));
        QCOMPARE(d.nodes[1].guessedNamespace, false);
        QCOMPARE(d.nodes[1].guessedName, false);
        QCOMPARE(d.nodes[2].nameSpace, QStringLiteral("/fixed"));
        QCOMPARE(d.nodes[2].guessedNamespace, false);
        QCOMPARE(d.nodes[3].guessedNamespace, false); // the group's namespace ended with it

        // Given values, nothing is a guess.
        const LaunchDependencies given = fx.run(QStringLiteral("bringup/launch/robot.launch.py"),
                                                {{"robot", "r1"}, {"who", "scout"}});
        QCOMPARE(given.nodes[0].nameSpace, QStringLiteral("/r1"));
        QCOMPARE(given.nodes[0].nodeName, QStringLiteral("scout"));
        QCOMPARE(given.nodes[0].guessedNamespace, false);
        QCOMPARE(given.nodes[0].guessedName, false);
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

    // autoware's perception launch: a node named from a part of an argument, and a node started
    // only when an argument, compared as a string, reaches a count.
    void evalNamesANodeAndDecidesACondition()
    {
        Fixture fx;
        LaunchAction named =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("x"), 2);
        named.name.kind = Substitution::Kind::Eval;
        named.name.parts = {lit(QStringLiteral("'")), var(QStringLiteral("model")),
                            lit(QStringLiteral("'.split('/')[1] if '/' in '")),
                            var(QStringLiteral("model")), lit(QStringLiteral("' else 'plain'"))};
        named.name.text.clear();
        LaunchAction counted =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("second"), 3);
        counted.condition.expression.kind = Substitution::Kind::Eval;
        counted.condition.expression.parts = {
            lit(QStringLiteral("'")), var(QStringLiteral("count")), lit(QStringLiteral("'>='2'"))};
        counted.condition.text = QStringLiteral("$(eval '$(var count)'>='2')");
        const QString model = QStringLiteral("centerpoint/tiny");
        const QString count = QStringLiteral("1");
        fx.add(QStringLiteral("bringup/launch/e.launch.py"),
               {declare(QStringLiteral("model"), &model), declare(QStringLiteral("count"), &count),
                named, counted});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/e.launch.py"));
        QCOMPARE(d.nodes.size(), 2);
        QCOMPARE(d.nodes[0].nodeName, QStringLiteral("tiny"));
        QVERIFY(d.nodes[0].unresolved.isEmpty());
        QCOMPARE(d.nodes[1].active, false);
        QVERIFY(d.nodes[1].unresolved.isEmpty());

        const LaunchDependencies other = fx.run(QStringLiteral("bringup/launch/e.launch.py"),
                                                {{"model", "pointpainting"}, {"count", "3"}});
        QCOMPARE(other.nodes[0].nodeName, QStringLiteral("plain"));
        QCOMPARE(other.nodes[1].active, true);
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
        // What autoware's XML launch files compute in $(eval ...), once $(var ...) is text.
        QTest::newRow("split index") << "'centerpoint/tiny'.split('/')[0]"
                                     << "centerpoint";
        QTest::newRow("split of nothing") << "''.split('/')[0]"
                                          << "";
        QTest::newRow("conditional") << "'a/b'.split('/')[1] if '/' in 'a/b' else ''"
                                     << "b";
        QTest::newRow("conditional else") << "'x'.split('/')[1] if '/' in 'x' else 'none'"
                                          << "none";
        QTest::newRow("default name") << "'transfusion' if ''=='' else ''"
                                      << "transfusion";
        QTest::newRow("concatenation") << "'ModuleA, ' + 'ModuleB, '"
                                       << "ModuleA, ModuleB, ";
        QTest::newRow("string order") << "'2'>='1'"
                                      << "true";
        QTest::newRow("list membership") << "'ndt' in ['ndt', 'yabloc']"
                                         << "true";
        QTest::newRow("substring") << "'ndt' in 'ndt_yabloc'"
                                   << "true";
        QTest::newRow("len") << "len(['a', 'b', 'c']) == 3"
                             << "true";
        QTest::newRow("last item") << "'a_b_c'.split('_')[-1]"
                                   << "c";
        QTest::newRow("methods") << "' Fast '.strip().lower().replace('f', 'v')"
                                 << "vast";
        QTest::newRow("or gives an operand") << "'' or 'default'"
                                             << "default";
        QTest::newRow("or short-circuits") << "'x' or 'a'.split('/')[5]"
                                           << "x";
        QTest::newRow("and short-circuits") << "'' and 'a'.split('/')[5]"
                                            << "";
        QTest::newRow("list text") << "'a b'.split()"
                                   << "['a', 'b']";
        QTest::newRow("arithmetic") << "2 + 3 - 1"
                                    << "4";
        QTest::newRow("chained comparison") << "1 < 2 < 3"
                                            << "true";
        QTest::newRow("launch booleans") << "true and not false"
                                         << "true";
        QTest::newRow("str of a boolean") << "str(1 == 1)"
                                          << "True";
        QTest::newRow("format") << "'{}-{}'.format('a', 1)"
                                << "a-1";
        QTest::newRow("blanks around") << "  'a' + 'b' "
                                       << "ab";
        QTest::newRow("sorted numbers") << "sorted([3, 1, 2])"
                                        << "[1, 2, 3]";
        QTest::newRow("tuple and dict") << "[(1,), {'a': None}]"
                                        << "[(1,), {'a': None}]";
    }

    void pythonExpressions()
    {
        QFETCH(QString, expression);
        QFETCH(QString, value);
        QString out;
        QVERIFY(SubstitutionEvaluator::evaluatePython(expression, &out));
        QCOMPARE(out, value);
    }

    // What Python would raise on, what is unknown without a runtime, a guess between
    // alternatives, a value a bound cut short, and what is no one expression have no value.
    void pythonExpressionsWithoutAValue_data()
    {
        QTest::addColumn<QString>("expression");
        const char *const rows[][2] = {
            {"environment", "os.environ['X']"},
            {"syntax error", "'a' =="},
            {"index past the end", "'a'.split('/')[1]"},
            {"unknown method", "'a'.zfill(3)"},
            {"empty separator", "'a'.split('')"},
            {"string less than number", "'a' < 1"},
            {"order of a set", "list(set('a_b'.split('_')))"},
            {"undecided condition", "'a' if os.getcwd() else 'b'"},
            {"undecided or", "x or True"},
            {"range cut short", "len(range(1000))"},
            {"repetition cut short", "len('ab' * 100)"},
            {"two statements", "1\n2"},
            {"assignment", "x = 1"},
            {"import", "import os"},
            {"function", "lambda: 1"},
        };
        for (const auto &[name, expression] : rows)
            QTest::newRow(name) << QString::fromUtf8(expression);
    }

    void pythonExpressionsWithoutAValue()
    {
        QFETCH(QString, expression);
        QString out;
        QVERIFY(!SubstitutionEvaluator::evaluatePython(expression, &out));
    }

    void deepPythonExpressionsSaySo()
    {
        QString out;
        // Deep nesting is refused, not a stack overflow.
        const QString deep = QString(100000, QLatin1Char('(')) + QStringLiteral("1") +
                             QString(100000, QLatin1Char(')'));
        QVERIFY(!SubstitutionEvaluator::evaluatePython(deep, &out));
        // and says so where the expression is evaluated: a kind of its own among the unresolved.
        Substitution eval;
        eval.kind = Substitution::Kind::Eval;
        eval.parts << lit(deep);
        const QMap<QString, QString> none;
        const SubstitutionEvaluator::Result r =
            SubstitutionEvaluator(none, QString()).evaluate(eval);
        QCOMPARE(r.unresolved.size(), 1);
        QCOMPARE(r.unresolved[0].kind, QStringLiteral("eval-too-deep"));
        QList<Unresolved> asCondition;
        QVERIFY(SubstitutionEvaluator(none, QString()).isTrue(eval, &asCondition));
        QCOMPARE(asCondition.size(), 1);
        QCOMPARE(asCondition[0].kind, QStringLiteral("eval-too-deep"));
        QCOMPARE(asCondition[0].guess, QStringLiteral("true"));
        eval.parts = {lit(QStringLiteral("os.getcwd()"))};
        QCOMPARE(SubstitutionEvaluator(none, QString()).evaluate(eval).unresolved[0].kind,
                 QStringLiteral("eval"));
        QVERIFY(!SubstitutionEvaluator::evaluatePython(
            QString(100000, QLatin1Char('-')) + QStringLiteral("1"), &out));
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
