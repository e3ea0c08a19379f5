// Findings stage 2 makes while it runs the launch files (blueprint §1, "Checks run on entry
// points"): a namespace that an included file pushes again (tests/data/check_namespaces).
#include "pipeline/recovery.h"
#include "support/recoverytest.h"
#include "support/testsupport.h"

#include <QtTest>

using namespace rosarch;

class TestLaunchFindings : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void namespacePushedTwiceIsOneFindingAtTheFirstPush()
    {
        // check_namespaces: fleet.launch.py pushes each robot's namespace and passes it down;
        // stack.launch.py pushes it again (a group's push, a node's namespace). single.launch.xml
        // does it right twice, and repeats a namespace within one file by design.
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("check_namespaces/ws")));
        QStringList found;
        for (const Diagnostic &d : r.launch.diagnostics + r.architecture.diagnostics)
            if (d.code == QLatin1String("namespace-doubled")) {
                QStringList related;
                for (const Diagnostic::Related &rel : d.related)
                    related << QStringLiteral("%1 %2:%3")
                                   .arg(rel.message, rel.evidence.file)
                                   .arg(rel.evidence.line);
                found << QStringLiteral("%1:%2 | %3 | %4 | %5")
                             .arg(d.evidence.file)
                             .arg(d.evidence.line)
                             .arg(d.message, related.join(u','), d.contexts.join(u','));
            }
        QCOMPARE(found,
                 QStringList{QStringLiteral(
                     "src/fleet/launch/fleet.launch.py:20 | The namespace scout or hauler pushed "
                     "here is pushed again by src/robot_stack/launch/stack.launch.py:13 (and 1 "
                     "more places), a file this one includes, so its nodes run in /scout/scout "
                     "or /hauler/hauler: ROS 2 nests pushed namespaces. Push it once: drop this "
                     "push, or stop passing the namespace down as an argument. | pushes scout "
                     "again src/robot_stack/launch/stack.launch.py:13,pushes scout again "
                     "src/robot_stack/launch/stack.launch.py:17 | "
                     "src/fleet/launch/fleet.launch.py")});
        // Where the nodes run, as ROS 2 would run them.
        QStringList where;
        for (const NodeInstance &n : r.launch.nodes)
            where << n.nodeName + QLatin1Char(' ') + n.nameSpace;
        where.sort();
        QCOMPARE(where,
                 (QStringList{QStringLiteral("driver /hauler/hauler"),
                              QStringLiteral("driver /scout/scout"), QStringLiteral("driver /solo"),
                              QStringLiteral("driver /spare"),
                              QStringLiteral("imu_driver /sensors/sensors"),
                              QStringLiteral("planner /hauler/hauler"),
                              QStringLiteral("planner /scout/scout"),
                              QStringLiteral("planner /solo"), QStringLiteral("planner /spare")}));
    }
};

QTEST_GUILESS_MAIN(TestLaunchFindings)
#include "tst_launchfindings.moc"
