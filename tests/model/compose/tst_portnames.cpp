// Stage 3's port names per instance, on hand-built classes and instances: parameter-derived
// names, empty parameters, and the ports of the plugins an instance loads.
#include "composer.h"
#include "guifixture.h"

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
};

QTEST_GUILESS_MAIN(TestPortNames)
#include "tst_portnames.moc"
