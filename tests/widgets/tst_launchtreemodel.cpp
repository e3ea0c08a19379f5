#include "document.h"
#include "documentchanges.h"
#include "guifixture.h"
#include "icons.h"
#include "launchtreemodel.h"
#include "launchtreetext.h"
#include "nodefilterproxymodel.h"
#include "project.h"
#include "testsupport.h"

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

namespace {

const QString kRobot = QStringLiteral("src/robot_bringup/launch/robot.launch.py");
const QString kSensors = QStringLiteral("src/robot_sensing/launch/sensors.launch.xml");

Evidence at(const QString &file, int line, int endLine)
{
    return Evidence{file, line, 1, endLine, 1};
}

NodeInstance node(const QString &id, const QString &launchFileId, const QString &name,
                  const QString &nameSpace, const Evidence &evidence)
{
    NodeInstance n;
    n.id = id;
    n.launchFileId = launchFileId;
    n.nodeName = name;
    n.nameSpace = nameSpace;
    n.nodeKind = QStringLiteral("cpp");
    n.evidence = evidence;
    return n;
}

LaunchFileInstance launchFile(const QString &id, const QString &file, const QString &parentId,
                              const Evidence &evidence)
{
    LaunchFileInstance i;
    i.id = id;
    i.file = file;
    i.type = file.section(QLatin1Char('/'), -1);
    i.package = file.section(QLatin1Char('/'), 1, 1);
    i.format =
        file.endsWith(QLatin1String(".xml")) ? QStringLiteral("xml") : QStringLiteral("python");
    i.parentId = parentId;
    i.evidence = evidence;
    return i;
}

/// robot.launch.py starts a map server, includes sensors.launch.xml twice (in /robot, and
/// in /robot2 under a false condition), calls an OpaqueFunction, includes an external and
/// an unresolvable file, and starts a camera container with composable nodes in
/// /robot/sensors, one of them for a container it does not start.
LaunchDependencies sample()
{
    LaunchDependencies d;
    d.launchFiles = {kRobot, kSensors};

    LaunchFileInstance robot = launchFile(QStringLiteral("lf1"), kRobot, {}, at(kRobot, 1, 60));
    robot.nodes = {QStringLiteral("n1"), QStringLiteral("n2"), QStringLiteral("n3"),
                   QStringLiteral("n4"), QStringLiteral("n7")};
    robot.includedLaunchFiles = {QStringLiteral("lf2"), QStringLiteral("lf3"),
                                 QStringLiteral("lf4"), QStringLiteral("lf5")};
    robot.namespaces = {
        {QStringLiteral("/"), {QStringLiteral("n1")}},
        {QStringLiteral("/robot"),
         {QStringLiteral("lf2"), QStringLiteral("n2"), QStringLiteral("n3"), QStringLiteral("n4"),
          QStringLiteral("n7")}},
        {QStringLiteral("/robot/sensors"),
         {QStringLiteral("n2"), QStringLiteral("n3"), QStringLiteral("n4"), QStringLiteral("n7")}},
        {QStringLiteral("/robot2"), {QStringLiteral("lf3")}}};
    robot.arguments = {{QStringLiteral("second"), QStringLiteral("false")}};
    Unresolved opaque{QStringLiteral("opaque-function"),
                      QStringLiteral("OpaqueFunction(function=setup)"),
                      {},
                      at(kRobot, 40, 40)};
    Unresolved extraPath{
        QStringLiteral("include"), QStringLiteral("$(var extra_launch)"), {}, at(kRobot, 50, 50)};
    robot.unresolved = {opaque, extraPath};

    LaunchFileInstance sensors =
        launchFile(QStringLiteral("lf2"), kSensors, robot.id, at(kRobot, 20, 22));
    sensors.nodes = {QStringLiteral("n5")};
    // the scope it was included in, inherited: no second "/robot" row inside it
    sensors.namespaces = {{QStringLiteral("/robot"), {QStringLiteral("n5")}}};
    sensors.arguments = {{QStringLiteral("frame"), QStringLiteral("base_link")}};
    LaunchFileInstance second =
        launchFile(QStringLiteral("lf3"), kSensors, robot.id, at(kRobot, 30, 32));
    second.nodes = {QStringLiteral("n6")};
    second.condition = QStringLiteral("$(var second)");
    second.active = false;
    LaunchFileInstance nav = launchFile(QStringLiteral("lf4"), {}, robot.id, at(kRobot, 45, 45));
    nav.type = QStringLiteral("navigation_launch.py");
    nav.package = QStringLiteral("nav2_bringup");
    nav.external = true;
    LaunchFileInstance extra = launchFile(QStringLiteral("lf5"), {}, robot.id, at(kRobot, 50, 50));
    extra.type = QString();
    extra.unresolved = {extraPath};
    d.instances = {robot, sensors, second, nav, extra};

    NodeInstance map = node(QStringLiteral("n1"), robot.id, QStringLiteral("map_server"),
                            QStringLiteral("/"), at(kRobot, 10, 12));
    map.package = QStringLiteral("nav2_map_server");
    map.execName = QStringLiteral("map_server");
    map.parameters = {{QStringLiteral("yaml_filename"), QStringLiteral("map.yaml")},
                      {QString(), QStringLiteral("$(find-pkg-share robot)/config/map.yaml")}};
    map.effectiveParameters = {{QStringLiteral("frame_id"), QStringLiteral("map"),
                                QStringLiteral("file"), QStringLiteral("robot/config/map.yaml"),
                                at(QStringLiteral("robot/config/map.yaml"), 4, 4)},
                               {QStringLiteral("topic"), QStringLiteral("map"),
                                QStringLiteral("default"), QString(),
                                at(QStringLiteral("nav/src/map_server.cpp"), 30, 30)},
                               {QStringLiteral("yaml_filename"), QStringLiteral("map.yaml"),
                                QStringLiteral("launch"), QString(), at(kRobot, 10, 12)}};
    NodeInstance container =
        node(QStringLiteral("n2"), robot.id, QStringLiteral("camera_container"),
             QStringLiteral("/robot/sensors"), at(kRobot, 52, 53));
    container.package = QStringLiteral("rclcpp_components");
    container.execName = QStringLiteral("component_container");
    NodeInstance camera = node(QStringLiteral("n3"), robot.id, QStringLiteral("camera"),
                               QStringLiteral("/robot/sensors"), at(kRobot, 54, 54));
    camera.nodeKind = QStringLiteral("composable");
    camera.package = QStringLiteral("robot_sensing");
    camera.execName = QStringLiteral("robot_sensing::CameraDriver");
    camera.className = QStringLiteral("CameraDriver");
    camera.classId = QStringLiteral("arc_1");
    camera.container = QStringLiteral("n2");
    NodeInstance rectify = node(QStringLiteral("n4"), robot.id, QStringLiteral("rectify"),
                                QStringLiteral("/robot/sensors"), at(kRobot, 56, 56));
    rectify.nodeKind = QStringLiteral("composable");
    rectify.package = QStringLiteral("image_proc");
    rectify.execName = QStringLiteral("image_proc::RectifyNode");
    rectify.container = QStringLiteral("camera_container"); // by name
    rectify.unresolved = {{QStringLiteral("substitution"), QStringLiteral("$(env CAMERA_MODEL)"),
                           QStringLiteral("pinhole"), at(kRobot, 56, 56)}};
    NodeInstance foreign = node(QStringLiteral("n7"), robot.id, QStringLiteral("debayer"),
                                QStringLiteral("/robot/sensors"), at(kRobot, 58, 58));
    foreign.nodeKind = QStringLiteral("composable");
    foreign.execName = QStringLiteral("image_proc::DebayerNode");
    foreign.container = QStringLiteral("/robot/other_container");
    NodeInstance lidar = node(QStringLiteral("n5"), sensors.id, QStringLiteral("lidar_filter"),
                              QStringLiteral("/robot"), at(kSensors, 3, 6));
    lidar.package = QStringLiteral("robot_sensing");
    lidar.execName = QStringLiteral("lidar_filter");
    lidar.className = QStringLiteral("LidarFilter");
    lidar.classId = QStringLiteral("arc_2");
    lidar.remaps = {{QStringLiteral("scan"), QStringLiteral("/robot/scan_raw")}};
    lidar.parameters = {{QString(), QStringLiteral("config/lidar.yaml")},
                        {QStringLiteral("range_max"), QStringLiteral("30.0")}};
    NodeInstance lidar2 = lidar;
    lidar2.id = QStringLiteral("n6");
    lidar2.launchFileId = second.id;
    lidar2.nameSpace = QStringLiteral("/robot2");
    lidar2.remaps = {{QStringLiteral("scan"), QStringLiteral("/robot2/scan_raw")}};
    d.nodes = {map, container, camera, rectify, lidar, lidar2, foreign};

    LaunchArgument arg;
    arg.name = QStringLiteral("second");
    arg.defaultValue = QStringLiteral("false");
    arg.hasDefault = true;
    arg.launchFile = kRobot;
    d.arguments = {arg};
    return d;
}

QStringList childNames(const QAbstractItemModel *model, const QModelIndex &parent)
{
    QStringList names;
    for (int r = 0; r < model->rowCount(parent); ++r)
        names << model->index(r, 0, parent).data().toString();
    return names;
}

bool sameIcon(const QVariant &decoration, const QIcon &expected)
{
    const QIcon icon = decoration.value<QIcon>();
    return !icon.isNull() && icon.pixmap(16, 16).toImage() == expected.pixmap(16, 16).toImage();
}

} // namespace

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
        document.setNodeDescription(QStringLiteral("arc_1"), QStringLiteral("Drives a camera."));
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
        document.setLaunchOptions(options);
        QCOMPARE(changed.count(), 1);
        QVERIFY(changed.first().at(0).value<DocumentChange>().has(DocumentChange::LaunchOptions));
        QCOMPARE(document.launchOptions(), options);
        document.setLaunchOptions(options); // no change, no signal
        QCOMPARE(changed.count(), 1);
        // stage results do not touch them
        document.setRecovery({AtomicNodeList(), sample(), {}});
        document.setLaunchDependencies({});
        QCOMPARE(document.launchOptions(), options);
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
    }
};

QTEST_MAIN(TestLaunchTreeModel)
#include "tst_launchtreemodel.moc"
