// Which root launch file the composed diagram starts on: a remembered choice first, then the
// only root, a file named like a system's entry point, the root that includes the most, and
// otherwise no choice (the panel asks). Also the counts the root picker lists.
#include "diagram/rootchoice.h"

#include <QtTest>

using namespace rosarch;

namespace {

QList<Unresolved> unresolvedList(int count)
{
    Unresolved u;
    u.kind = QStringLiteral("substitution");
    return QList<Unresolved>(count, u);
}

LaunchRoot root(const QString &id, const QString &file, int includes = 0, int unresolved = 0)
{
    QString stem = file.section(QLatin1Char('/'), -1);
    for (const char *suffix : {".launch.py", "_launch.py", ".launch.xml", ".launch.yaml"})
        if (stem.endsWith(QLatin1String(suffix)))
            stem.chop(int(qstrlen(suffix)));
    LaunchRoot r;
    r.instanceId = id;
    r.file = file;
    r.stem = stem;
    r.includes = includes;
    r.unresolved = unresolved;
    return r;
}

} // namespace

class TestRootChoice : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void choose_data();
    void choose();
    void rememberedMissingFallsBack();
    void rootsCountIncludesNodesAndUnresolved();
};

void TestRootChoice::choose_data()
{
    QTest::addColumn<QList<LaunchRoot>>("roots");
    QTest::addColumn<QString>("remembered");
    QTest::addColumn<QString>("expected");
    QTest::addColumn<int>("reason");
    using R = RootChoice::Reason;

    QTest::newRow("none") << QList<LaunchRoot>{} << QString() << QString() << int(R::None);
    QTest::newRow("only") << QList<LaunchRoot>{root("lf1", "a/launch/demo.launch.py")} << QString()
                          << "lf1" << int(R::Only);
    // The alphabetically first root is a multi-robot simulation: bringup wins anyway.
    QTest::newRow("exact stem") << QList<LaunchRoot>{root("lf1", "b/launch/cloned_multi.py", 9),
                                                     root("lf2", "b/launch/bringup_launch.py", 3),
                                                     root("lf3", "b/launch/rviz_launch.py")}
                                << QString() << "lf2" << int(R::Name);
    QTest::newRow("exact before contains")
        << QList<LaunchRoot>{root("lf1", "p/launch/robot_state.launch.py"),
                             root("lf2", "p/launch/deep/er/system.launch.xml")}
        << QString() << "lf2" << int(R::Name);
    QTest::newRow("shallower path") << QList<LaunchRoot>{root("lf1", "x/y/launch/robot.launch.py"),
                                                         root("lf2", "x/launch/robot.launch.py")}
                                    << QString() << "lf2" << int(R::Name);
    QTest::newRow("fewer unresolved")
        << QList<LaunchRoot>{root("lf1", "x/launch/bringup.launch.py", 0, 4),
                             root("lf2", "y/launch/bringup.launch.py", 0, 1)}
        << QString() << "lf2" << int(R::Name);
    QTest::newRow("not a test")
        << QList<LaunchRoot>{root("lf1", "sys/test/bringup.launch.py"),
                             root("lf2", "sys/launch/deeper/robot_bringup.launch.py")}
        << QString() << "lf2" << int(R::Name);
    // nav2: the bringup package's roots have plain names; its benchmarks are named bringup.
    QTest::newRow("bringup folder")
        << QList<LaunchRoot>{root("lf1", "tools/bench/planning_benchmark_bringup.py", 1),
                             root("lf2", "nav_bringup/launch/slam_launch.py", 2),
                             root("lf3", "nav_bringup/launch/multi_sim_launch.py", 9),
                             root("lf4", "nav_system_tests/src/test_system_launch.py", 12),
                             root("lf5", "nav_commander/launch/demo_launch.py", 4)}
        << QString() << "lf3" << int(R::Name);
    QTest::newRow("system before a named benchmark")
        << QList<LaunchRoot>{root("lf1", "tools/bench/planning_benchmark_bringup.py", 1),
                             root("lf2", "pkg/launch/everything.launch.py", 3)}
        << QString() << "lf2" << int(R::Includes);
    QTest::newRow("only auxiliary") << QList<LaunchRoot>{root("lf1", "pkg/test/a_launch.py"),
                                                         root("lf2", "pkg/test/robot_launch.py")}
                                    << QString() << "lf2" << int(R::Name);
    QTest::newRow("case-insensitive")
        << QList<LaunchRoot>{root("lf1", "a/launch/talker.launch.py"),
                             root("lf2", "a/launch/MyRobot.launch.xml")}
        << QString() << "lf2" << int(R::Name);
    QTest::newRow("most includes")
        << QList<LaunchRoot>{root("lf1", "a/launch/talker.launch.py", 1),
                             root("lf2", "a/launch/everything.launch.py", 4),
                             root("lf3", "a/launch/listener.launch.py", 0)}
        << QString() << "lf2" << int(R::Includes);
    QTest::newRow("tie asks") << QList<LaunchRoot>{root("lf1", "a/launch/one.launch.py", 2),
                                                   root("lf2", "a/launch/two.launch.py", 2)}
                              << QString() << QString() << int(R::Ask);
    QTest::newRow("no includes asks") << QList<LaunchRoot>{root("lf1", "a/launch/one.launch.py"),
                                                           root("lf2", "a/launch/two.launch.py")}
                                      << QString() << QString() << int(R::Ask);
    QTest::newRow("remembered wins") << QList<LaunchRoot>{root("lf1", "a/launch/bringup.launch.py"),
                                                          root("lf2", "a/launch/two.launch.py")}
                                     << "a/launch/two.launch.py"
                                     << "lf2" << int(R::Remembered);
}

void TestRootChoice::choose()
{
    QFETCH(QList<LaunchRoot>, roots);
    QFETCH(QString, remembered);
    QFETCH(QString, expected);
    QFETCH(int, reason);
    const RootChoice choice = RootChoice::choose(roots, remembered);
    QCOMPARE(choice.instanceId, expected);
    QCOMPARE(int(choice.reason), reason);
}

void TestRootChoice::rememberedMissingFallsBack()
{
    // A remembered file that is no longer a root (renamed, deleted) is ignored.
    const QList<LaunchRoot> roots{root("lf1", "a/launch/bringup.launch.py"),
                                  root("lf2", "a/launch/two.launch.py")};
    const RootChoice choice = RootChoice::choose(roots, QStringLiteral("a/launch/gone.launch.py"));
    QCOMPARE(choice.instanceId, QStringLiteral("lf1"));
    QCOMPARE(choice.reason, RootChoice::Reason::Name);
}

void TestRootChoice::rootsCountIncludesNodesAndUnresolved()
{
    // lf1 includes lf2, which includes lf3; lf4 is a second root on its own.
    LaunchDependencies launch;
    const auto instance = [](const QString &id, const QString &parent, int unresolved) {
        LaunchFileInstance lf;
        lf.id = id;
        lf.parentId = parent;
        lf.unresolved = unresolvedList(unresolved);
        return lf;
    };
    launch.instances = {instance("lf1", {}, 1), instance("lf2", "lf1", 0),
                        instance("lf3", "lf2", 2), instance("lf4", {}, 0)};
    const auto node = [](const QString &id, const QString &lf, int unresolved) {
        NodeInstance n;
        n.id = id;
        n.launchFileId = lf;
        n.unresolved = unresolvedList(unresolved);
        return n;
    };
    launch.nodes = {node("n1", "lf1", 0), node("n2", "lf3", 1), node("n3", "lf3", 0),
                    node("n4", "lf4", 0)};
    Architecture architecture;
    const auto composite = [&launch](const QString &id, const QString &parent,
                                     const QString &file) {
        Composite c;
        c.instanceId = id;
        c.parentId = parent;
        c.file = file;
        c.stem = file.section(QLatin1Char('/'), -1).section(QLatin1Char('.'), 0, 0);
        for (const NodeInstance &n : launch.nodes)
            if (n.launchFileId == id) {
                RosNodePart part;
                part.id = QStringLiteral("part_") + n.id;
                part.instanceId = n.id;
                c.parts << part;
            }
        for (const LaunchFileInstance &lf : launch.instances)
            if (lf.parentId == id) {
                RosNodePart part;
                part.kind = RosNodePart::Kind::Launch;
                part.instanceId = lf.id;
                c.parts << part; // an include is not a node
            }
        return c;
    };
    architecture.composites = {composite("lf1", {}, "a/launch/top.launch.py"),
                               composite("lf2", "lf1", "a/launch/mid.launch.py"),
                               composite("lf3", "lf2", "a/launch/leaf.launch.py"),
                               composite("lf4", {}, "a/launch/alone.launch.py")};
    const QList<LaunchRoot> roots = RootChoice::roots(architecture, launch);
    QCOMPARE(roots.size(), 2);
    QCOMPARE(roots[0], (LaunchRoot{"lf1", "top", "a/launch/top.launch.py", 2, 3, 4}));
    QCOMPARE(roots[1], (LaunchRoot{"lf4", "alone", "a/launch/alone.launch.py", 0, 1, 0}));
    // top includes the most: it is chosen when no name says more.
    QCOMPARE(RootChoice::choose(roots).instanceId, QStringLiteral("lf1"));
    // Without stage 2's result the counts come from the architecture alone.
    const QList<LaunchRoot> bare = RootChoice::roots(architecture, {});
    QCOMPARE(bare[0], (LaunchRoot{"lf1", "top", "a/launch/top.launch.py", 2, 3, 0}));
}

QTEST_GUILESS_MAIN(TestRootChoice)
#include "tst_rootchoice.moc"
