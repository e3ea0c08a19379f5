// How the launch tree shows what it holds: columns, icons, tooltips, inactive rows greyed.
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
#include <QTimer>
#include <QtTest>

#include <functional>

using namespace rosarch;
using namespace rosarch::test::launchtree;

class TestLaunchTreePresentation : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void columnsShowWhatAnInstanceIs()
    {
        Document document;
        AtomicNodeList workspace;
        RosPackage sensing;
        sensing.name = QStringLiteral("robot_sensing");
        workspace.packages = {sensing};
        LaunchDependencies launch = sample();
        launch.nodes[6].package = sensing.name; // debayer: a workspace package without the class
        document.setRecovery({workspace, launch, {}});
        LaunchTreeModel model(&document);
        const auto cell = [&](const QString &nodeId, int column) {
            return model.nodeIndex(nodeId, column).data().toString();
        };
        QCOMPARE(cell(QStringLiteral("n5"), LaunchTreeModel::NamespaceColumn),
                 QStringLiteral("/robot"));
        QCOMPARE(cell(QStringLiteral("n5"), LaunchTreeModel::ExecutableColumn),
                 QStringLiteral("robot_sensing/lidar_filter"));
        QCOMPARE(cell(QStringLiteral("n5"), LaunchTreeModel::ClassColumn),
                 QStringLiteral("LidarFilter"));
        const QString details = cell(QStringLiteral("n5"), LaunchTreeModel::DetailsColumn);
        QVERIFY2(details.contains(QStringLiteral("remap: scan→/robot/scan_raw")),
                 qPrintable(details));
        QVERIFY2(details.contains(QStringLiteral("config/lidar.yaml")), qPrintable(details));
        QVERIFY2(details.contains(QStringLiteral("range_max=30.0")), qPrintable(details));
        QCOMPARE(cell(QStringLiteral("n3"), LaunchTreeModel::ExecutableColumn),
                 QStringLiteral("robot_sensing::CameraDriver")); // a plugin, no package prefix
        QCOMPARE(cell(QStringLiteral("n4"), LaunchTreeModel::ClassColumn),
                 QStringLiteral("(external)")); // image_proc is not in the workspace
        QCOMPARE(cell(QStringLiteral("n7"), LaunchTreeModel::ClassColumn),
                 QStringLiteral("(not found)"));
        QVERIFY(model.nodeIndex(QStringLiteral("n7"))
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("not found in the workspace")));
        QVERIFY(model.nodeIndex(QStringLiteral("n4"), LaunchTreeModel::ClassColumn)
                    .data(Qt::FontRole)
                    .value<QFont>()
                    .italic());
        QCOMPARE(cell(QStringLiteral("n1"), LaunchTreeModel::NamespaceColumn), QStringLiteral("/"));
        QVERIFY(cell(QStringLiteral("n2"), LaunchTreeModel::DetailsColumn)
                    .contains(QStringLiteral("container of 2 components")));
        QCOMPARE(
            model.nodeIndex(QStringLiteral("n3")).data(LaunchTreeModel::ClassIdRole).toString(),
            QStringLiteral("arc_1"));
        QCOMPARE(
            model.nodeIndex(QStringLiteral("n3")).data(LaunchTreeModel::InstanceIdRole).toString(),
            QStringLiteral("n3"));

        const QModelIndex root = model.launchFileIndex(QStringLiteral("lf1"));
        QVERIFY(root.data(Qt::FontRole).value<QFont>().bold());
        QCOMPARE(root.siblingAtColumn(LaunchTreeModel::ExecutableColumn).data().toString(),
                 QStringLiteral("robot_bringup"));
        QVERIFY(root.siblingAtColumn(LaunchTreeModel::DetailsColumn)
                    .data()
                    .toString()
                    .contains(QStringLiteral("second:=false")));
        const QModelIndex sensors = model.launchFileIndex(QStringLiteral("lf2"));
        QVERIFY(sensors.siblingAtColumn(LaunchTreeModel::DetailsColumn)
                    .data()
                    .toString()
                    .contains(QStringLiteral("frame:=base_link")));
    }

    void iconsMarkKinds()
    {
        Document document;
        document.setLaunchDependencies(sample());
        LaunchTreeModel model(&document);
        QVERIFY(sameIcon(model.launchFileIndex(QStringLiteral("lf1")).data(Qt::DecorationRole),
                         Icons::launchFile()));
        QVERIFY(sameIcon(model.launchFileIndex(QStringLiteral("lf2")).data(Qt::DecorationRole),
                         Icons::include()));
        QVERIFY(sameIcon(model.launchFileIndex(QStringLiteral("lf4")).data(Qt::DecorationRole),
                         Icons::externalInclude()));
        QVERIFY(sameIcon(model.launchFileIndex(QStringLiteral("lf5")).data(Qt::DecorationRole),
                         Icons::unresolved()));
        QVERIFY(sameIcon(model.nodeIndex(QStringLiteral("n1")).data(Qt::DecorationRole),
                         Icons::nodeInstance()));
        QVERIFY(sameIcon(model.nodeIndex(QStringLiteral("n2")).data(Qt::DecorationRole),
                         Icons::container()));
        QVERIFY(sameIcon(model.nodeIndex(QStringLiteral("n3")).data(Qt::DecorationRole),
                         Icons::composable()));
        const QModelIndex robotNs = model.index(1, 0, model.index(0, 0));
        QVERIFY(sameIcon(robotNs.data(Qt::DecorationRole), Icons::nameSpace()));
        // unresolved parts of a node: a mark in the details column
        QVERIFY(sameIcon(model.nodeIndex(QStringLiteral("n4"), LaunchTreeModel::DetailsColumn)
                             .data(Qt::DecorationRole),
                         Icons::unresolved()));
        QVERIFY(!model.nodeIndex(QStringLiteral("n3"), LaunchTreeModel::DetailsColumn)
                     .data(Qt::DecorationRole)
                     .isValid());
        const QModelIndex opaque = model.index(3, 0, model.index(0, 0));
        QCOMPARE(model.kind(opaque), LaunchTreeModel::ItemKind::Unresolved);
        QVERIFY(sameIcon(opaque.data(Qt::DecorationRole), Icons::unresolved()));
    }

    // The icons are rendered ahead of the first result one per event-loop turn, not all at
    // once when the window is made, and the warm-up ends on its own.
    void iconsWarmUpOnePerTurn()
    {
        QObject window;
        Icons::warmUp(&window);
        QCOMPARE(window.findChildren<QTimer *>().size(), 1);
        QTRY_VERIFY(window.findChildren<QTimer *>().isEmpty());
        QVERIFY(!Icons::nodeInstance().pixmap(QSize(16, 16)).isNull());
    }

    void tooltipsSayWhatAndWhere()
    {
        Document document;
        AtomicNodeList nodes;
        AtomicNode cls;
        cls.id = QStringLiteral("arc_2");
        cls.className = QStringLiteral("LidarFilter");
        cls.evidence = at(QStringLiteral("src/robot_sensing/src/lidar_filter.cpp"), 12, 80);
        nodes.nodes = {cls};
        document.setRecovery({nodes, sample(), {}});
        LaunchTreeModel model(&document);

        const QString lidar =
            model.nodeIndex(QStringLiteral("n5")).data(Qt::ToolTipRole).toString();
        QVERIFY2(lidar.contains(QStringLiteral("/robot/lidar_filter")), qPrintable(lidar));
        QVERIFY2(lidar.contains(QStringLiteral("src/robot_sensing/src/lidar_filter.cpp:12")),
                 qPrintable(lidar));
        QVERIFY2(lidar.contains(QStringLiteral("scan → /robot/scan_raw")), qPrintable(lidar));
        QVERIFY2(lidar.contains(QStringLiteral("file config/lidar.yaml")), qPrintable(lidar));
        QVERIFY2(lidar.contains(kSensors + QStringLiteral(":3")), qPrintable(lidar));

        const QString rectify =
            model.nodeIndex(QStringLiteral("n4")).data(Qt::ToolTipRole).toString();
        QVERIFY2(rectify.contains(QStringLiteral("$(env CAMERA_MODEL)")), qPrintable(rectify));
        QVERIFY2(rectify.contains(QStringLiteral("pinhole")), qPrintable(rectify));
        QVERIFY2(rectify.contains(QStringLiteral("package image_proc is not in the workspace")),
                 qPrintable(rectify));

        const QString opaque =
            model.index(3, 0, model.index(0, 0)).data(Qt::ToolTipRole).toString();
        QVERIFY2(opaque.contains(QStringLiteral("OpaqueFunction(function=setup)")),
                 qPrintable(opaque));
        QVERIFY2(opaque.contains(kRobot + QStringLiteral(":40")), qPrintable(opaque));
        const QString unresolvedInclude =
            model.launchFileIndex(QStringLiteral("lf5")).data(Qt::ToolTipRole).toString();
        QVERIFY2(unresolvedInclude.contains(QStringLiteral("$(var extra_launch)")),
                 qPrintable(unresolvedInclude));
        const QString external =
            model.launchFileIndex(QStringLiteral("lf4")).data(Qt::ToolTipRole).toString();
        QVERIFY2(external.contains(QStringLiteral("nav2_bringup is not in the workspace")),
                 qPrintable(external));
        QVERIFY(model.launchFileIndex(QStringLiteral("lf4"))
                    .data(Qt::FontRole)
                    .value<QFont>()
                    .italic());
        const QString second =
            model.launchFileIndex(QStringLiteral("lf3")).data(Qt::ToolTipRole).toString();
        QVERIFY2(second.contains(QStringLiteral("$(var second)")) &&
                     second.contains(QStringLiteral("not included")),
                 qPrintable(second));
        // the root's own unresolved include stays on the include, not on the root
        QVERIFY(!model.launchFileIndex(QStringLiteral("lf1"), LaunchTreeModel::DetailsColumn)
                     .data(Qt::DecorationRole)
                     .isValid());
    }

    void inactiveInstancesAreGreyed()
    {
        Document document;
        document.setLaunchDependencies(sample());
        LaunchTreeModel model(&document);
        const QBrush grey = QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        const QModelIndex second = model.launchFileIndex(QStringLiteral("lf3"));
        QVERIFY(!model.isActive(second));
        QCOMPARE(second.data(Qt::ForegroundRole).value<QBrush>(), grey);
        // its node is active on its own, but not started: the include is off
        const QModelIndex lidar2 =
            model.nodeIndex(QStringLiteral("n6"), LaunchTreeModel::ClassColumn);
        QVERIFY(document.launchDependencies().node(QStringLiteral("n6"))->active);
        QVERIFY(!lidar2.data(LaunchTreeModel::ActiveRole).toBool());
        QCOMPARE(lidar2.data(Qt::ForegroundRole).value<QBrush>(), grey);
        QVERIFY(lidar2.data(Qt::ToolTipRole).toString().contains(QStringLiteral("not included")));
        const QModelIndex lidar = model.nodeIndex(QStringLiteral("n5"));
        QVERIFY(model.isActive(lidar));
        QVERIFY(!lidar.data(Qt::ForegroundRole).isValid());
    }
};

QTEST_MAIN(TestLaunchTreePresentation)
#include "tst_launchtreepresentation.moc"
