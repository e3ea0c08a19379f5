// The launch tree model's tests build on: a hand-built stage 2 result (two launch files, an
// include, namespaces, a container, parameters, an inactive node) and small item-model helpers.
#pragma once

#include "core/launchdependencies.h"
#include "widgets/icons.h"

#include <QAbstractItemModel>
#include <QIcon>
#include <QVariant>

namespace rosarch::test::launchtree {

inline const QString kRobot = QStringLiteral("src/robot_bringup/launch/robot.launch.py");
inline const QString kSensors = QStringLiteral("src/robot_sensing/launch/sensors.launch.xml");

inline Evidence at(const QString &file, int line, int endLine)
{
    return Evidence{file, line, 1, endLine, 1};
}

inline NodeInstance node(const QString &id, const QString &launchFileId, const QString &name,
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
inline LaunchDependencies sample()
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

inline QStringList childNames(const QAbstractItemModel *model, const QModelIndex &parent)
{
    QStringList names;
    for (int r = 0; r < model->rowCount(parent); ++r)
        names << model->index(r, 0, parent).data().toString();
    return names;
}

inline bool sameIcon(const QVariant &decoration, const QIcon &expected)
{
    const QIcon icon = decoration.value<QIcon>();
    return !icon.isNull() && icon.pixmap(16, 16).toImage() == expected.pixmap(16, 16).toImage();
}

} // namespace rosarch::test::launchtree
