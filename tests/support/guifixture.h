#pragma once

// tests/data/gui_ws built by hand, so GUI tests do not depend on the analyzers.
#include "core/atomicnodelist.h"
#include "core/launchdependencies.h"
#include "pipeline/recovery.h"
#include "support/testsupport.h"

#include <QObject>

namespace rosarch::test {

/// The one T in `window`'s object tree (the one named `objectName` when given): tests reach
/// the main window's panels, docks, actions, models and controllers this way, so the window
/// keeps no getters for them. Stops the test when there is none, or several without a name.
template <typename T> T *child(const QObject &window, const QString &objectName = {})
{
    const QList<T *> found = window.findChildren<T *>(objectName);
    if (found.size() != 1)
        qFatal("%lld objects of type %s named \"%s\" in the window, expected one",
               qlonglong(found.size()), T::staticMetaObject.className(), qPrintable(objectName));
    return found.first();
}

// tests/data/gui_ws: a Python talker, a C++ listener and launch files that start them.
namespace gui {

inline const QString kTalker = QStringLiteral("src/py_talker/py_talker/talker.py");
inline const QString kListener = QStringLiteral("src/cpp_listener/src/listener.cpp");
inline const QString kDemoLaunch = QStringLiteral("src/py_talker/launch/demo.launch.py");
inline const QString kListenerLaunch =
    QStringLiteral("src/cpp_listener/launch/listener.launch.xml");
inline const QString kExtraLaunch = QStringLiteral("src/cpp_listener/launch/extra.launch.yaml");

inline QString fixture()
{
    return QFileInfo(dataDir(QStringLiteral("gui_ws"))).canonicalFilePath();
}

inline Port port(const QString &id, PortKind kind, const QString &name, const QString &type,
                 const QString &callback, const Evidence &evidence)
{
    Port p;
    p.id = id;
    p.kind = kind;
    p.name = name;
    p.type = type;
    p.callback = callback;
    p.evidence = evidence;
    return p;
}

/// What stage 1 should recover from gui_ws, written by hand with the fixture's real lines,
/// so the traceability tests do not depend on the analyzers.
inline AtomicNodeList handBuiltNodes()
{
    AtomicNodeList list;
    list.workspaceRoot = fixture();
    RosPackage py;
    py.name = QStringLiteral("py_talker");
    py.buildType = QStringLiteral("ament_python");
    py.path = QStringLiteral("src/py_talker");
    RosPackage cpp;
    cpp.name = QStringLiteral("cpp_listener");
    cpp.buildType = QStringLiteral("ament_cmake");
    cpp.path = QStringLiteral("src/cpp_listener");
    list.packages = {cpp, py};

    AtomicNode listener;
    listener.id = QStringLiteral("arc_1");
    listener.className = QStringLiteral("Listener");
    listener.packageName = cpp.name;
    listener.nodeName = QStringLiteral("listener");
    listener.executables = {QStringLiteral("listener")};
    listener.evidence = {kListener, 11, 1, 41, 3};
    listener.ports = {port(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("chatter"),
                           QStringLiteral("std_msgs/msg/String"), QStringLiteral("on_message"),
                           {kListener, 17, 21, 18, 87}),
                      port(QStringLiteral("ps1"), PortKind::ServiceServer, QStringLiteral("reset"),
                           QStringLiteral("std_srvs/srv/Trigger"), QStringLiteral("on_reset"),
                           {kListener, 19, 16, 20, 98})};
    AtomicNode talker;
    talker.id = QStringLiteral("arc_2");
    talker.className = QStringLiteral("Talker");
    talker.packageName = py.name;
    talker.executables = {QStringLiteral("talker")};
    talker.compileType = AtomicNode::CompileType::Python;
    talker.evidence = {kTalker, 6, 1, 21, 40};
    talker.ports = {port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("chatter"),
                         QStringLiteral("std_msgs/msg/String"), {}, {kTalker, 11, 26, 11, 70}),
                    port(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("echo"),
                         QStringLiteral("std_msgs/msg/String"), QStringLiteral("on_echo"),
                         {kTalker, 12, 29, 12, 88})};
    list.nodes = {listener, talker};
    Diagnostic d;
    d.code = QStringLiteral("test");
    d.message = QStringLiteral("A diagnostic about the service.");
    d.evidence = {kListener, 19, 5, 19, 20};
    list.diagnostics = {d};
    return list;
}

inline NodeInstance nodeInstance(const QString &id, const QString &launchFileId,
                                 const QString &package, const QString &exec,
                                 const QString &className, const QString &classId,
                                 const QString &name, const QString &nameSpace,
                                 const Evidence &evidence)
{
    NodeInstance n;
    n.id = id;
    n.launchFileId = launchFileId;
    n.nodeKind =
        package == QLatin1String("py_talker") ? QStringLiteral("python") : QStringLiteral("cpp");
    n.package = package;
    n.execName = exec;
    n.className = className;
    n.classId = classId;
    n.nodeName = name;
    n.nameSpace = nameSpace;
    n.evidence = evidence;
    return n;
}

/// What stage 2 recovers from gui_ws with the default options, written by hand.
inline LaunchDependencies handBuiltLaunch()
{
    LaunchDependencies d;
    d.launchFiles = {kExtraLaunch, kListenerLaunch, kDemoLaunch};

    LaunchFileInstance demo;
    demo.id = QStringLiteral("lf1");
    demo.type = QStringLiteral("demo.launch.py");
    demo.file = kDemoLaunch;
    demo.package = QStringLiteral("py_talker");
    demo.format = QStringLiteral("python");
    demo.nodes = {QStringLiteral("n1"), QStringLiteral("n4")};
    demo.includedLaunchFiles = {QStringLiteral("lf2")};
    demo.namespaces = {{QStringLiteral("/"), {QStringLiteral("n1"), QStringLiteral("n4")}},
                       {QStringLiteral("/robot1"), {QStringLiteral("lf2")}}};
    demo.evidence = {kDemoLaunch, 1, 1, 1, 1}; // a root: the file itself

    LaunchFileInstance listener;
    listener.id = QStringLiteral("lf2");
    listener.type = QStringLiteral("listener.launch.xml");
    listener.file = kListenerLaunch;
    listener.package = QStringLiteral("cpp_listener");
    listener.format = QStringLiteral("xml");
    listener.parentId = demo.id;
    listener.nodes = {QStringLiteral("n2")};
    listener.includedLaunchFiles = {QStringLiteral("lf3"), QStringLiteral("lf4")};
    listener.namespaces = {{QStringLiteral("/robot1"),
                            {QStringLiteral("n2"), QStringLiteral("lf3"), QStringLiteral("lf4")}}};
    listener.arguments = {{QStringLiteral("topic"), QStringLiteral("speech")}};
    listener.evidence = {kDemoLaunch, 23, 13, 26, 62};

    LaunchFileInstance extra;
    extra.id = QStringLiteral("lf3");
    extra.type = QStringLiteral("extra.launch.yaml");
    extra.file = kExtraLaunch;
    extra.package = QStringLiteral("cpp_listener");
    extra.format = QStringLiteral("yaml");
    extra.parentId = listener.id;
    extra.nodes = {QStringLiteral("n3")};
    extra.namespaces = {{QStringLiteral("/robot1/extra"), {QStringLiteral("n3")}}};
    extra.evidence = {kListenerLaunch, 6, 3, 6, 76};

    LaunchFileInstance external;
    external.id = QStringLiteral("lf4");
    external.type = QStringLiteral("talker.launch.py");
    external.package = QStringLiteral("demo_nodes_cpp");
    external.format = QStringLiteral("python");
    external.parentId = listener.id;
    external.external = true;
    external.evidence = {kListenerLaunch, 7, 3, 7, 77};

    d.instances = {demo, listener, extra, external};

    NodeInstance talker =
        nodeInstance(QStringLiteral("n1"), demo.id, QStringLiteral("py_talker"),
                     QStringLiteral("talker"), QStringLiteral("Talker"), QStringLiteral("arc_2"),
                     QStringLiteral("talker"), QStringLiteral("/"), {kDemoLaunch, 18, 9, 20, 41});
    talker.remaps = {{QStringLiteral("chatter"), QStringLiteral("speech")}};
    talker.parameters = {{QStringLiteral("rate"), QStringLiteral("2.0")}};
    NodeInstance listenerNode = nodeInstance(
        QStringLiteral("n2"), listener.id, QStringLiteral("cpp_listener"),
        QStringLiteral("listener"), QStringLiteral("Listener"), QStringLiteral("arc_1"),
        QStringLiteral("listener"), QStringLiteral("/robot1"), {kListenerLaunch, 3, 3, 5, 10});
    listenerNode.remaps = {{QStringLiteral("chatter"), QStringLiteral("speech")}};
    NodeInstance second = nodeInstance(
        QStringLiteral("n3"), extra.id, QStringLiteral("cpp_listener"), QStringLiteral("listener"),
        QStringLiteral("Listener"), QStringLiteral("arc_1"), QStringLiteral("second_listener"),
        QStringLiteral("/robot1/extra"), {kExtraLaunch, 2, 3, 6, 21});
    NodeInstance echo = nodeInstance(QStringLiteral("n4"), demo.id, QStringLiteral("py_talker"),
                                     QStringLiteral("talker"), QStringLiteral("Talker"),
                                     QStringLiteral("arc_2"), QStringLiteral("echo_talker"),
                                     QStringLiteral("/"), {kDemoLaunch, 28, 9, 29, 46});
    echo.condition = QStringLiteral("IfCondition(use_echo)");
    echo.active = false;
    d.nodes = {talker, listenerNode, second, echo};

    LaunchArgument robot;
    robot.name = QStringLiteral("robot");
    robot.defaultValue = QStringLiteral("robot1");
    robot.hasDefault = true;
    robot.description = QStringLiteral("Namespace of the robot");
    robot.launchFile = kDemoLaunch;
    robot.evidence = {kDemoLaunch, 14, 9, 15, 68};
    LaunchArgument useEcho;
    useEcho.name = QStringLiteral("use_echo");
    useEcho.defaultValue = QStringLiteral("false");
    useEcho.hasDefault = true;
    useEcho.description = QStringLiteral("Also start a talker that echoes");
    useEcho.launchFile = kDemoLaunch;
    useEcho.evidence = {kDemoLaunch, 16, 9, 17, 77};
    d.arguments = {robot, useEcho};
    return d;
}

inline Recovery handBuiltRecovery()
{
    return {handBuiltNodes(), handBuiltLaunch(), {}};
}

} // namespace gui

} // namespace rosarch::test
