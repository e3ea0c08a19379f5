#include "document/document.h"
#include "launchtreesample.h"
#include "project/project.h"
#include "support/documentchanges.h"
#include "support/guifixture.h"
#include "support/testsupport.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreetext.h"
#include "widgets/nodefilterproxymodel.h"

#include <QAbstractItemModelTester>
#include <QFont>
#include <QGuiApplication>
#include <QIcon>
#include <QPalette>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QtTest>

#include <functional>

using namespace rosarch;
using namespace rosarch::test::launchtree;

class TestLaunchTreeModel : public QObject
{
    Q_OBJECT
private Q_SLOTS:

    void passesTheModelTester()
    {
        Document document;
        LaunchTreeModel model(&document);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(model.rowCount(), 0);
        document.setLaunchDependencies(sample());
        QCOMPARE(model.rowCount(), 1);
        // a full reset (stage 1 + 2) and an empty one keep the model consistent
        document.setRecovery({AtomicNodeList(), sample(), {}});
        QCOMPARE(model.rowCount(), 1);
        document.setAtomicNodes(AtomicNodeList());
        QCOMPARE(model.rowCount(), 0);
        document.setLaunchDependencies(test::gui::handBuiltLaunch());
        QCOMPARE(model.rowCount(), 1);
    }

    void treeFollowsIncludesNamespacesAndContainers()
    {
        Document document;
        document.setLaunchDependencies(sample());
        LaunchTreeModel model(&document);

        const QModelIndex root = model.index(0, 0);
        QCOMPARE(root.data().toString(), QStringLiteral("robot.launch.py"));
        QCOMPARE(model.kind(root), LaunchTreeModel::ItemKind::LaunchFile);
        // in file order; namespace scopes appear where their first member stands
        QCOMPARE(childNames(&model, root),
                 (QStringList{QStringLiteral("map_server"), QStringLiteral("/robot"),
                              QStringLiteral("/robot2"),
                              QStringLiteral("OpaqueFunction(function=setup)"),
                              QStringLiteral("navigation_launch.py"),
                              QStringLiteral("(unresolved include)")}));
        const QModelIndex robotNs = model.index(1, 0, root);
        QCOMPARE(model.kind(robotNs), LaunchTreeModel::ItemKind::Namespace);
        QCOMPARE(childNames(&model, robotNs), (QStringList{QStringLiteral("sensors.launch.xml"),
                                                           QStringLiteral("/robot/sensors")}));
        const QModelIndex sensorsNs = model.index(1, 0, robotNs);
        // the container holds the composables it loads, by id and by name; the one for a
        // container this file does not start stays in the scope
        QCOMPARE(childNames(&model, sensorsNs),
                 (QStringList{QStringLiteral("camera_container"), QStringLiteral("debayer")}));
        const QModelIndex container = model.index(0, 0, sensorsNs);
        QCOMPARE(container, model.nodeIndex(QStringLiteral("n2")));
        QCOMPARE(childNames(&model, container),
                 (QStringList{QStringLiteral("camera"), QStringLiteral("rectify")}));
        QCOMPARE(model.parent(model.nodeIndex(QStringLiteral("n4"))), container);

        // the same file included twice gives two rows with their own node instances
        const QModelIndex first = model.launchFileIndex(QStringLiteral("lf2"));
        const QModelIndex second = model.launchFileIndex(QStringLiteral("lf3"));
        QCOMPARE(first.parent(), robotNs);
        QCOMPARE(second.parent(), model.index(2, 0, root));
        QCOMPARE(model.nodeIndex(QStringLiteral("n5")).parent(), first);
        QCOMPARE(model.nodeIndex(QStringLiteral("n6")).parent(), second);
        QCOMPARE(model.launchFile(model.nodeIndex(QStringLiteral("n6")))->id,
                 QStringLiteral("lf3"));
        QCOMPARE(model.rowCount(model.launchFileIndex(QStringLiteral("lf4"))), 0);
    }

    void parametersInEffectAreRowsUnderTheNode()
    {
        Document document;
        document.setLaunchDependencies(sample());
        LaunchTreeModel model(&document);
        const QModelIndex map = model.nodeIndex(QStringLiteral("n1"));
        QCOMPARE(childNames(&model, map), QStringList{QStringLiteral("Parameters")});
        const QModelIndex group = model.index(0, 0, map);
        QCOMPARE(model.kind(group), LaunchTreeModel::ItemKind::Parameters);
        QCOMPARE(group.parent(), map);
        QCOMPARE(model.index(0, LaunchTreeModel::DetailsColumn, map).data().toString(),
                 QStringLiteral("3 in effect"));
        QCOMPARE(childNames(&model, group),
                 (QStringList{QStringLiteral("frame_id"), QStringLiteral("topic"),
                              QStringLiteral("yaml_filename")}));
        const QModelIndex frame = model.index(0, 0, group);
        QCOMPARE(model.kind(frame), LaunchTreeModel::ItemKind::Parameter);
        QCOMPARE(frame.parent(), group);
        QCOMPARE(model.rowCount(frame), 0);
        QVERIFY(model.flags(frame) & Qt::ItemNeverHasChildren);
        QCOMPARE(model.parameter(frame)->value, QStringLiteral("map"));
        // each row says where the value comes from, and leads there
        QCOMPARE(model.index(0, LaunchTreeModel::DetailsColumn, group).data().toString(),
                 QStringLiteral("map · map.yaml:4"));
        QCOMPARE(model.index(1, LaunchTreeModel::DetailsColumn, group).data().toString(),
                 QStringLiteral("map · default in code"));
        QCOMPARE(model.index(2, LaunchTreeModel::DetailsColumn, group).data().toString(),
                 QStringLiteral("map.yaml · launch file"));
        QCOMPARE(model.evidence(frame).file, QStringLiteral("robot/config/map.yaml"));
        QCOMPARE(model.evidence(frame).line, 4);
        QVERIFY(frame.data(Qt::ToolTipRole).toString().contains(QLatin1String("parameter file")));
        QCOMPARE(frame.data(LaunchTreeModel::InstanceIdRole).toString(), QStringLiteral("n1"));
        // a node without parameters in effect has no such row
        QCOMPARE(model.rowCount(model.nodeIndex(QStringLiteral("n5"))), 0);
        QVERIFY(!model.parameter(map));
    }

    void indexAtFindsTheInnermostItem()
    {
        Document document;
        document.setLaunchDependencies(sample());
        LaunchTreeModel model(&document);
        QCOMPARE(model.indexAt(kRobot, 11), model.nodeIndex(QStringLiteral("n1")));
        QCOMPARE(model.indexAt(kRobot, 21), model.launchFileIndex(QStringLiteral("lf2")));
        QCOMPARE(model.indexAt(kRobot, 54), model.nodeIndex(QStringLiteral("n3")));
        QCOMPARE(model.kind(model.indexAt(kRobot, 40)), LaunchTreeModel::ItemKind::Unresolved);
        QCOMPARE(model.indexAt(kRobot, 50), model.launchFileIndex(QStringLiteral("lf5")));
        QCOMPARE(model.indexAt(kRobot, 5), model.launchFileIndex(QStringLiteral("lf1")));
        QVERIFY(!model.indexAt(QStringLiteral("src/other.py"), 5).isValid());
        // the file included twice: the instance near the current row wins
        QCOMPARE(model.indexAt(kSensors, 4), model.nodeIndex(QStringLiteral("n5")));
        QCOMPARE(model.indexAt(kSensors, 4, model.nodeIndex(QStringLiteral("n6"))),
                 model.nodeIndex(QStringLiteral("n6")));
        QCOMPARE(model.indexAt(kSensors, 4, model.launchFileIndex(QStringLiteral("lf3"))),
                 model.nodeIndex(QStringLiteral("n6")));
        // a line outside every node belongs to the file instance
        QCOMPARE(model.indexAt(kSensors, 1, model.nodeIndex(QStringLiteral("n6"))),
                 model.launchFileIndex(QStringLiteral("lf3")));
        QCOMPARE(model.indexAt(kSensors, 1), model.launchFileIndex(QStringLiteral("lf2")));
        // evidence of rows
        QCOMPARE(model.evidence(model.nodeIndex(QStringLiteral("n5"))), at(kSensors, 3, 6));
        QCOMPARE(model.evidence(model.launchFileIndex(QStringLiteral("lf3"))), at(kRobot, 30, 32));
        QVERIFY(!model.evidence(model.index(1, 0, model.index(0, 0))).isValid()); // a namespace
    }

    void rowsAreMadeWhenFirstAskedFor()
    {
        Document document;
        document.setLaunchDependencies(sample());
        // Every row, depth first, as the names from the root: the whole tree.
        const auto dump = [](const QAbstractItemModel *m) {
            QStringList out;
            std::function<void(const QModelIndex &, const QString &)> walk =
                [&](const QModelIndex &parent, const QString &path) {
                    for (int r = 0; r < m->rowCount(parent); ++r) {
                        const QModelIndex i = m->index(r, 0, parent);
                        if (i.data(LaunchTreeModel::KindRole).toInt() ==
                            int(LaunchTreeModel::ItemKind::Parameters))
                            continue; // made by the model on demand, not laid out
                        out << path + i.data().toString();
                        walk(i, path + i.data().toString() + u'/');
                    }
                };
            walk({}, {});
            return out;
        };
        LaunchTreeModel fresh(&document);
        // only the root is made: its rows wait until a view opens it or a lookup needs them
        QCOMPARE(fresh.rowsMade(), 1);
        QVERIFY(fresh.hasChildren(fresh.index(0, 0)));
        QCOMPARE(fresh.rowsMade(), 1);
        // a lookup makes the rows on the way to the row it finds, and only those
        const QModelIndex n6 = fresh.nodeIndex(QStringLiteral("n6"));
        QCOMPARE(n6.data().toString(), QStringLiteral("lidar_filter"));
        QCOMPARE(fresh.launchFile(n6)->id, QStringLiteral("lf3"));
        QVERIFY(fresh.rowsMade() > 1);
        LaunchTreeModel bySourceLine(&document);
        QCOMPARE(
            bySourceLine.indexAt(kSensors, 4, bySourceLine.launchFileIndex(QStringLiteral("lf3"))),
            bySourceLine.nodeIndex(QStringLiteral("n6")));
        // whatever was made first, the tree is the same as one made in order
        LaunchTreeModel inOrder(&document);
        const QStringList all = dump(&inOrder);
        QVERIFY(all.size() > 10);
        QCOMPARE(dump(&fresh), all);
        QCOMPARE(dump(&bySourceLine), all);
        QCOMPARE(inOrder.rowsMade(), int(all.size()));
    }

    void filterFindsNodesThroughTheTree()
    {
        Document document;
        document.setLaunchDependencies(sample());
        LaunchTreeModel model(&document);
        NodeFilterProxyModel proxy;
        proxy.setFilterColumns({LaunchTreeModel::NameColumn, LaunchTreeModel::NamespaceColumn,
                                LaunchTreeModel::ExecutableColumn, LaunchTreeModel::ClassColumn});
        proxy.setSourceModel(&model);
        QAbstractItemModelTester tester(&proxy,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        proxy.setFilterRegularExpression(QStringLiteral("CameraDriver"));
        QCOMPARE(proxy.rowCount(), 1);
        const QModelIndex root = proxy.index(0, 0);
        QCOMPARE(childNames(&proxy, root), QStringList{QStringLiteral("/robot")});
        const QModelIndex container = proxy.index(0, 0, proxy.index(0, 0, proxy.index(0, 0, root)));
        QCOMPARE(container.data().toString(), QStringLiteral("camera_container"));
        QCOMPARE(childNames(&proxy, container), QStringList{QStringLiteral("camera")});
        proxy.setFilterRegularExpression(QStringLiteral("/robot2"));
        QCOMPARE(childNames(&proxy, proxy.index(0, 0)), QStringList{QStringLiteral("/robot2")});
        proxy.setFilterRegularExpression(QStringLiteral("no such thing"));
        QCOMPARE(proxy.rowCount(), 0);
    }

    void relaunchKeepsAtomicNodesAndUndo()
    {
        // the description below is a correction the document keeps in the project of /ws
        QStandardPaths::setTestModeEnabled(true);
        QFile::remove(ProjectFile::locate(QStringLiteral("/ws")));
        QFile::remove(ProjectFile::autosavePath(ProjectFile::locate(QStringLiteral("/ws"))));
        Document document;
        AtomicNodeList nodes;
        AtomicNode cls;
        cls.id = QStringLiteral("arc_1");
        cls.className = QStringLiteral("CameraDriver");
        nodes.nodes = {cls};
        nodes.workspaceRoot = QStringLiteral("/ws");
        document.setAtomicNodes(nodes);
        document.session()->setNodeDescription(QStringLiteral("arc_1"),
                                               QStringLiteral("Drives a camera."));
        QCOMPARE(document.undoStack()->count(), 1);
        QSignalSpy changed(&document, &Document::changed);
        document.setLaunchDependencies(sample());
        QCOMPARE(test::changesOf(changed, DocumentChange::Launch).size(), 1);
        QCOMPARE(test::changesOf(changed, DocumentChange::Model).size(), 0);
        QCOMPARE(document.undoStack()->count(), 1);
        QCOMPARE(document.atomicNodes().nodes.first().description,
                 QStringLiteral("Drives a camera."));
        QCOMPARE(document.launchDependencies().nodes.size(), 7);
        // a full result replaces both and starts a fresh history
        document.setRecovery({nodes, {}, {}});
        QCOMPARE(test::changesOf(changed, DocumentChange::Model).size(), 1);
        QCOMPARE(document.undoStack()->count(), 0);
        QVERIFY(document.launchDependencies().nodes.isEmpty());
    }

    void documentKeepsLaunchOptions()
    {
        Document document;
        QSignalSpy changed(&document, &Document::changed);
        LaunchOptions options;
        options.rootFile = kRobot;
        options.arguments = {{QStringLiteral("second"), QStringLiteral("true")}};
        document.session()->setLaunchOptions(options);
        QCOMPARE(changed.count(), 1);
        QVERIFY(changed.first().at(0).value<DocumentChange>().has(DocumentChange::LaunchOptions));
        QCOMPARE(document.session()->launchOptions(), options);
        document.session()->setLaunchOptions(options); // no change, no signal
        QCOMPARE(changed.count(), 1);
        // stage results do not touch them
        document.setRecovery({AtomicNodeList(), sample(), {}});
        document.setLaunchDependencies({});
        QCOMPARE(document.session()->launchOptions(), options);
    }

    void textHelpers()
    {
        NodeInstance n;
        n.nodeName = QStringLiteral("talker");
        n.nameSpace = QStringLiteral("/robot1");
        QCOMPARE(LaunchTreeText::fullyQualifiedName(n), QStringLiteral("/robot1/talker"));
        n.nameSpace = QStringLiteral("/");
        QCOMPARE(LaunchTreeText::fullyQualifiedName(n), QStringLiteral("/talker"));
        n.nameSpace.clear();
        QCOMPARE(LaunchTreeText::fullyQualifiedName(n), QStringLiteral("/talker"));
        n.package = QStringLiteral("demo");
        n.execName = QStringLiteral("talker");
        QCOMPARE(LaunchTreeText::nodeExecutable(n), QStringLiteral("demo/talker"));
        n.condition = QStringLiteral("$(var on)");
        QCOMPARE(LaunchTreeText::nodeDetails(n, 0), QStringLiteral("if: $(var on)"));
        QCOMPARE(LaunchTreeText::unresolvedKindLabel(QStringLiteral("opaque-function")),
                 QStringLiteral("Opaque function"));

        // A remapping onto a guess and an undecidable condition say so in the tooltip.
        n.remaps = {{QStringLiteral("out"), QStringLiteral("//cmd")},
                    {QStringLiteral("in"), QStringLiteral("/points")}};
        n.guessedRemaps = {0};
        n.unresolved = {{QStringLiteral("condition"), n.condition, QStringLiteral("true"), {}}};
        const QString tip = LaunchTreeText::nodeToolTip(n, nullptr, true, true);
        QVERIFY2(tip.contains(QStringLiteral(
                     "out → //cmd (a guess: built from a launch value nobody sets)")),
                 qPrintable(tip));
        QVERIFY(tip.contains(QStringLiteral("in → /points</li>")));
        QVERIFY(
            tip.contains(QStringLiteral("Condition: $(var on) (undecidable: kept, as if true)")));
        QVERIFY(!tip.contains(QStringLiteral("Namespace")));

        // A namespace and a name from guesses: the tooltip says which names that makes guesses.
        n.guessedNamespace = true;
        QVERIFY(LaunchTreeText::nodeToolTip(n, nullptr, true, true)
                    .contains(QStringLiteral("Namespace: a guess, built from a launch value nobody "
                                             "sets; so are the relative and private names")));
        n.guessedName = true;
        QVERIFY(LaunchTreeText::nodeToolTip(n, nullptr, true, true)
                    .contains(QStringLiteral("Namespace and name: guesses")));
        n.guessedNamespace = false;
        QVERIFY(LaunchTreeText::nodeToolTip(n, nullptr, true, true)
                    .contains(QStringLiteral("Name: a guess, built from a launch value nobody "
                                             "sets; so are the private names of its ports")));

        // A child node says where its parent's code creates it.
        n.parentNode = QStringLiteral("n1");
        n.evidence = {QStringLiteral("src/planner/src/planner_server.cpp"), 53, 18, 55, 54};
        QVERIFY(LaunchTreeText::nodeDetails(n, 0).startsWith(
            QStringLiteral("child node, created in code · if: $(var on)")));
        QVERIFY(LaunchTreeText::nodeToolTip(n, nullptr, true, true)
                    .contains(QStringLiteral(
                        "Child node: created in code at src/planner/src/planner_server.cpp:53")));
    }
};

QTEST_MAIN(TestLaunchTreeModel)
#include "tst_launchtreemodel.moc"
