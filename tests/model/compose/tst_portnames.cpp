// Stage 3's port names per instance, on hand-built classes and instances: parameter-derived
// names, empty parameters, and the ports of the plugins an instance loads.
#include "compose/composer.h"
#include "compose/itemports.h"
#include "support/guifixture.h"

#include <QtTest>

using namespace rosarch;

class TestPortNames : public QObject
{
    Q_OBJECT

private slots:
    void launchValuesOverrideParameterDerivedNames()
    {
        AtomicNode node;
        node.nodeName = QStringLiteral("rectifier");
        Port out =
            test::gui::port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("image_rect"),
                            QStringLiteral("sensor_msgs/msg/Image"), QString(), {});
        out.nameOrigin = NameOrigin::Parameter;
        out.parameter = QStringLiteral("output_topic");
        Port guarded = test::gui::port(
            QStringLiteral("ps1"), PortKind::ServiceServer, QStringLiteral("~/reset"),
            QStringLiteral("std_srvs/srv/Trigger"), QStringLiteral("on_reset"), {});
        guarded.guard = QStringLiteral("enable_reset");
        guarded.guardParameter = QStringLiteral("enable_reset");
        guarded.guardDefault = QStringLiteral("false");
        node.ports = {out, guarded};

        NodeInstance instance;
        instance.nodeName = QStringLiteral("rect");
        instance.nameSpace = QStringLiteral("/cam");
        QList<PartPort> ports = Composer::resolvePorts(node, instance, nullptr);
        QCOMPARE(ports.at(0).name, QStringLiteral("/cam/image_rect"));
        QVERIFY(ports.at(0).parameterDerived);
        QVERIFY(!ports.at(1).active); // the declared default is false
        QCOMPARE(ports.at(1).name, QStringLiteral("/cam/rect/reset"));

        instance.effectiveParameters = {{QStringLiteral("enable_reset"),
                                         QStringLiteral("true"),
                                         QStringLiteral("launch"),
                                         {},
                                         {}},
                                        {QStringLiteral("output_topic"),
                                         QStringLiteral("/custom"),
                                         QStringLiteral("launch"),
                                         {},
                                         {}}};
        NodeInstance container;
        container.remaps = {{QStringLiteral("/custom"), QStringLiteral("/final")}};
        ports = Composer::resolvePorts(node, instance, &container);
        QCOMPARE(ports.at(0).name, QStringLiteral("/final"));
        QVERIFY(ports.at(0).remapped);
        QVERIFY(ports.at(1).active);
    }

    // A parameter declared with "" and never set leaves the port's name unknown: it is not a
    // topic "/" that every such port would meet on.
    void anEmptyParameterNameIsUnresolved()
    {
        AtomicNode node;
        node.nodeName = QStringLiteral("limiter");
        Port limit = test::gui::port(QStringLiteral("s1"), PortKind::Subscriber, QString(),
                                     QStringLiteral("nav2_msgs/msg/SpeedLimit"), QString(), {});
        limit.nameOrigin = NameOrigin::Parameter;
        limit.parameter = QStringLiteral("speed_limit_topic");
        limit.nameExpression = QStringLiteral("params_->speed_limit_topic");
        node.ports = {limit};
        NodeInstance instance;
        instance.nodeName = QStringLiteral("limiter");
        QList<PartPort> ports = Composer::resolvePorts(node, instance, nullptr);
        QVERIFY(!ports.at(0).resolved);
        QCOMPARE(ports.at(0).name, QStringLiteral("params_->speed_limit_topic"));

        instance.effectiveParameters = {{QStringLiteral("speed_limit_topic"),
                                         QStringLiteral("speed_limit"),
                                         QStringLiteral("file"),
                                         {},
                                         {}}};
        ports = Composer::resolvePorts(node, instance, nullptr);
        QVERIFY(ports.at(0).resolved); // a value set for the instance names it
        QCOMPARE(ports.at(0).name, QStringLiteral("/speed_limit"));
    }

    // A plugin's ports are its own: a port added to the instance by a correction, or given by
    // an interface model, belongs to the node once, not once more per loaded plugin.
    void pluginPortsAreThePluginsOwn()
    {
        AtomicNode follower;
        follower.qualifiedName = QStringLiteral("nav::Follower");
        Port speed = test::gui::port(QStringLiteral("s1"), PortKind::Subscriber,
                                     QStringLiteral("speed_limit"),
                                     QStringLiteral("std_msgs/msg/Float64"), QString(), {});
        speed.nameOrigin = NameOrigin::Parameter;
        speed.parameter = QStringLiteral("{plugin}.speed_topic");
        speed.parameterPrefix = QStringLiteral("{parent_namespace}/");
        speed.name = QStringLiteral("{parent_namespace}/speed_limit");
        follower.ports = {speed};
        const QHash<QString, const AtomicNode *> plugins{{follower.qualifiedName, &follower}};

        NodeInstance server;
        server.nodeName = QStringLiteral("follow_server");
        server.nameSpace = QStringLiteral("/robot/control");
        server.plugins = {{QStringLiteral("Fast"), QStringLiteral("nav::Follower"), {}, {}, {}},
                          {QStringLiteral("Slow"), QStringLiteral("nav/Follower"), {}, {}, {}}};
        server.effectiveParameters = {{QStringLiteral("Slow.speed_topic"),
                                       QStringLiteral("crawl"),
                                       QStringLiteral("file"),
                                       {},
                                       {}}};
        server.addedPorts = {test::gui::port(QStringLiteral("c1_p"), PortKind::Publisher,
                                             QStringLiteral("heartbeat"),
                                             QStringLiteral("std_msgs/msg/Empty"), QString(), {})};
        server.removedPorts = {QStringLiteral("Fast_missing")};
        const QList<PartPort> ports = Composer::pluginPorts(plugins, server, nullptr);
        QStringList ids, names;
        for (const PartPort &p : ports) {
            ids << p.id;
            names << p.name;
        }
        QCOMPARE(ids, (QStringList{QStringLiteral("Fast_s1"), QStringLiteral("Slow_s1")}));
        // joined one namespace above the node's own; the instance's value where it sets one
        QCOMPARE(names, (QStringList{QStringLiteral("/robot/speed_limit"),
                                     QStringLiteral("/robot/crawl")}));

        server.removedPorts = {QStringLiteral("Slow_s1")}; // a correction removed it
        QCOMPARE(Composer::pluginPorts(plugins, server, nullptr).size(), 1);
    }

    // `layer->getName() + "_raw"` in a loop over loaded layers, cast to `GridLayer`: one port
    // per loaded plugin of that lineage (through a base the model knows), none for the others;
    // a plugin whose class is outside the workspace may be one, and its port says so.
    void portsPerLoadedPluginFollowTheLineage()
    {
        auto pluginClass = [](const QString &qualified, const QStringList &bases) {
            AtomicNode n;
            n.qualifiedName = qualified;
            n.className = qualified.section(QLatin1String("::"), -1);
            n.baseClasses = bases;
            n.pluginInterface = QStringLiteral("grid::Layer");
            return n;
        };
        const AtomicNode obstacle =
            pluginClass(QStringLiteral("grid::ObstacleLayer"), {QStringLiteral("grid::GridLayer")});
        const AtomicNode voxel =
            pluginClass(QStringLiteral("grid::VoxelLayer"), {QStringLiteral("ObstacleLayer")});
        const AtomicNode inflation =
            pluginClass(QStringLiteral("grid::InflationLayer"), {QStringLiteral("Layer")});
        const QHash<QString, const AtomicNode *> plugins{{obstacle.qualifiedName, &obstacle},
                                                         {voxel.qualifiedName, &voxel},
                                                         {inflation.qualifiedName, &inflation}};
        Port raw = test::gui::port(QStringLiteral("p2"), PortKind::Publisher,
                                   QStringLiteral("{plugin:GridLayer}_raw"),
                                   QStringLiteral("grid_msgs/msg/Grid"), QString(), {});
        raw.nameOrigin = NameOrigin::Parameter;
        raw.parameter = QStringLiteral("{plugin:GridLayer}");
        raw.parameterSuffix = QStringLiteral("_raw");
        raw.guard = QStringLiteral("grid_layer != nullptr");
        Port other = raw;
        other.id = QStringLiteral("p3");
        other.parameter = QStringLiteral("{plugin:Monitor}"); // no plugin class derives from it
        QCOMPARE(loadedPluginClass(raw), QStringLiteral("GridLayer"));
        QCOMPARE(loadedPluginClass(other), QStringLiteral("Monitor"));

        NodeInstance costmap;
        costmap.plugins = {
            {QStringLiteral("voxel"), QStringLiteral("grid::VoxelLayer"), {}, {}, {}},
            {QStringLiteral("inflate"), QStringLiteral("grid/InflationLayer"), {}, {}, {}},
            {QStringLiteral("outside"), QStringLiteral("ext::Layer"), {}, {}, {}}};
        QStringList seen;
        for (const Port &p : expandLoadedPlugins({raw, other}, costmap, plugins))
            seen << QStringLiteral("%1 %2 [%3]").arg(p.id, p.name, p.guard);
        QCOMPARE(seen, (QStringList{
                           QStringLiteral("p2_voxel voxel_raw []"),
                           QStringLiteral("p2_outside outside_raw [outside is a GridLayer]"),
                           QStringLiteral("p3 {plugin:GridLayer}_raw [grid_layer != nullptr]")}));

        costmap.plugins.clear(); // nothing loaded: the name is only known at run time
        const QList<Port> kept = expandLoadedPlugins({raw}, costmap, plugins);
        QCOMPARE(kept.size(), 1);
        QCOMPARE(kept.constFirst().parameter, raw.parameter);
    }

    // A list value names one port per item, up to a budget; the rest stay one port whose name
    // the list decides, undecided here.
    void aLongListIsExpandedWithinItsBudget()
    {
        Port feed =
            test::gui::port(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("{feeds}"),
                            QStringLiteral("std_msgs/msg/Bool"), QString(), {});
        feed.nameOrigin = NameOrigin::Parameter;
        feed.parameter = QStringLiteral("{feeds}");
        QStringList items;
        for (int i = 0; i < 300; ++i)
            items << QStringLiteral("f%1").arg(i);
        NodeInstance hub;
        hub.effectiveParameters = {{QStringLiteral("feeds"),
                                    QStringLiteral("[%1]").arg(items.join(QLatin1String(", "))),
                                    QStringLiteral("file"),
                                    {},
                                    {}}};
        QList<Port> out;
        expandItems(feed, hub, &out);
        QCOMPARE(out.size(), 257);
        QCOMPARE(out.at(255).name, QStringLiteral("f255"));
        QCOMPARE(out.at(255).id, QStringLiteral("s1_f255"));
        QCOMPARE(out.constLast().parameter, QStringLiteral("{feeds}"));

        // composed, the instance says that its list was not expanded in full
        AtomicNodeList nodes;
        AtomicNode hubClass;
        hubClass.id = QStringLiteral("arc_1");
        hubClass.className = QStringLiteral("Hub");
        hubClass.ports = {feed};
        nodes.nodes = {hubClass};
        LaunchDependencies launch;
        LaunchFileInstance lf;
        lf.id = QStringLiteral("lf1");
        lf.file = QStringLiteral("src/hub/launch/hub.launch.py");
        lf.type = QStringLiteral("hub.launch.py");
        lf.nodes = {QStringLiteral("n1")};
        launch.instances = {lf};
        hub.id = QStringLiteral("n1");
        hub.classId = hubClass.id;
        hub.nodeName = QStringLiteral("hub");
        hub.evidence = {lf.file, 7, 5, 7, 40};
        launch.nodes = {hub};
        Architecture arch = Composer::run(nodes, launch);
        QCOMPARE(arch.diagnostics.size(), 1);
        QCOMPARE(arch.diagnostics.constFirst().code, QStringLiteral("evaluation-limit"));
        QVERIFY2(arch.diagnostics.constFirst().message.contains(QLatin1String("feeds")),
                 qPrintable(arch.diagnostics.constFirst().message));
        QCOMPARE(arch.diagnostics.constFirst().evidence.line, 7);

        items.resize(3); // a short list says nothing
        launch.nodes[0].effectiveParameters[0].value =
            QStringLiteral("[%1]").arg(items.join(QLatin1String(", ")));
        arch = Composer::run(nodes, launch);
        QVERIFY(arch.diagnostics.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestPortNames)
#include "tst_portnames.moc"
