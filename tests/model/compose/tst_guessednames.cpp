// Stage 3 and names built on a guessed launch value (an argument nobody sets): which port names
// rest on the guess (a remapping onto it, a relative name under a guessed namespace, a private
// name under a guessed namespace or node name), and whom such a name is wired to.
#include "compose/composer.h"
#include "support/guifixture.h"

#include <QtTest>

using namespace rosarch;

namespace {

const QString kTwist = QStringLiteral("geometry_msgs/msg/Twist");

AtomicNode nodeClass(const QString &id, const QString &name, const QList<Port> &ports)
{
    AtomicNode n;
    n.id = id;
    n.className = name;
    n.nodeName = name.toLower();
    n.ports = ports;
    return n;
}

NodeInstance instanceOf(const QString &id, const AtomicNode &cls, bool guessedNamespace)
{
    NodeInstance n;
    n.id = id;
    n.launchFileId = QStringLiteral("lf1");
    n.className = cls.className;
    n.classId = cls.id;
    n.nodeName = cls.nodeName;
    n.nameSpace = QStringLiteral("/"); // the guess '' leaves the namespace at the root
    n.guessedNamespace = guessedNamespace;
    return n;
}

const Channel *channelNamed(const Composite &c, const QString &name)
{
    for (const Channel &ch : c.channels)
        if (ch.name == name)
            return &ch;
    return nullptr;
}

} // namespace

class TestGuessedNames : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    // A remapping onto a guessed launch value (an argument nobody sets) names the port with the
    // guess and marks it; the container's process-wide rules count as well.
    void aRemapOntoAGuessMarksThePort()
    {
        AtomicNode node;
        node.nodeName = QStringLiteral("relay");
        node.ports = {
            test::gui::port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("out"),
                            QStringLiteral("std_msgs/msg/String"), QString(), {}),
            test::gui::port(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("in"),
                            QStringLiteral("std_msgs/msg/String"), QString(), {})};
        NodeInstance instance;
        instance.nodeName = QStringLiteral("relay");
        instance.remaps = {{QStringLiteral("out"), QStringLiteral("//cmd")},
                           {QStringLiteral("other"), QStringLiteral("/known")}};
        instance.guessedRemaps = {0};
        NodeInstance container;
        container.remaps = {{QStringLiteral("/in"), QStringLiteral("/points")},
                            {QStringLiteral("/unused"), QStringLiteral("/x")}};
        QList<PartPort> ports = Composer::resolvePorts(node, instance, &container);
        QCOMPARE(ports.at(0).name, QStringLiteral("//cmd"));
        QVERIFY(ports.at(0).guessed);
        QVERIFY(ports.at(0).resolved); // wired under the guess, unlike an expression in code
        QCOMPARE(ports.at(1).name, QStringLiteral("/points"));
        QVERIFY(!ports.at(1).guessed);

        container.guessedRemaps = {0};
        ports = Composer::resolvePorts(node, instance, &container);
        QVERIFY(ports.at(1).guessed);
        instance.guessedRemaps.clear();
        ports = Composer::resolvePorts(node, instance, &container);
        QVERIFY(!ports.at(0).guessed);
    }

    // Under a guessed namespace, relative and private names are guesses; absolute names are
    // not, and neither is a relative name remapped onto an absolute one.
    void aGuessedNamespaceOrNameMarksTheNamesBuiltOnIt()
    {
        AtomicNode node;
        node.nodeName = QStringLiteral("driver");
        const QString type = QStringLiteral("std_msgs/msg/String");
        node.ports = {test::gui::port(QStringLiteral("p1"), PortKind::Publisher,
                                      QStringLiteral("odom"), type, QString(), {}),
                      test::gui::port(QStringLiteral("p2"), PortKind::Publisher,
                                      QStringLiteral("~/state"), type, QString(), {}),
                      test::gui::port(QStringLiteral("p3"), PortKind::Publisher,
                                      QStringLiteral("/tf"), type, QString(), {}),
                      test::gui::port(QStringLiteral("s1"), PortKind::Subscriber,
                                      QStringLiteral("cmd"), type, QString(), {}),
                      test::gui::port(QStringLiteral("s2"), PortKind::Subscriber,
                                      QStringLiteral("/clock"), type, QString(), {})};
        NodeInstance instance;
        instance.nodeName = QStringLiteral("driver");
        instance.nameSpace = QStringLiteral("/"); // the guess was ''
        instance.remaps = {{QStringLiteral("cmd"), QStringLiteral("/cmd_vel")},
                           {QStringLiteral("/clock"), QStringLiteral("sim_clock")}};
        instance.guessedNamespace = true;
        QList<PartPort> ports = Composer::resolvePorts(node, instance, nullptr);
        QCOMPARE(ports.size(), 5);
        QVERIFY(ports.at(0).guessed);         // odom
        QVERIFY(ports.at(1).guessed);         // ~/state
        QVERIFY(!ports.at(2).guessed);        // /tf
        QVERIFY(!ports.at(3).guessed);        // cmd -> /cmd_vel
        QVERIFY(ports.at(4).guessed);         // /clock -> sim_clock
        QCOMPARE(ports.at(0).resolved, true); // still wired under the guess
        QCOMPARE(ports.at(0).name, QStringLiteral("/odom"));

        instance.guessedNamespace = false;
        instance.guessedName = true; // only the private name rests on the node's name
        ports = Composer::resolvePorts(node, instance, nullptr);
        QVERIFY(!ports.at(0).guessed);
        QVERIFY(ports.at(1).guessed);
        QVERIFY(!ports.at(2).guessed);
        QVERIFY(!ports.at(4).guessed);
    }

    // Under the guess '' a relative "cmd" reads as the decided "/cmd"; under any real value of
    // the argument it would not: the two are not wired. Two names under the same guess are.
    void aGuessedNameMeetsOnlyGuessedNames()
    {
        AtomicNodeList nodes;
        nodes.nodes << nodeClass(QStringLiteral("c1"), QStringLiteral("Teleop"),
                                 {test::gui::port(QStringLiteral("p1"), PortKind::Publisher,
                                                  QStringLiteral("/cmd"), kTwist, {}, {})})
                    << nodeClass(QStringLiteral("c2"), QStringLiteral("Relay"),
                                 {test::gui::port(QStringLiteral("s1"), PortKind::Subscriber,
                                                  QStringLiteral("cmd"), kTwist, {}, {}),
                                  test::gui::port(QStringLiteral("p1"), PortKind::Publisher,
                                                  QStringLiteral("out"), kTwist, {}, {})})
                    << nodeClass(QStringLiteral("c3"), QStringLiteral("Base"),
                                 {test::gui::port(QStringLiteral("s1"), PortKind::Subscriber,
                                                  QStringLiteral("out"), kTwist, {}, {})});
        LaunchDependencies launch;
        LaunchFileInstance lf;
        lf.id = QStringLiteral("lf1");
        lf.type = QStringLiteral("robot.launch.xml");
        lf.nodes = {QStringLiteral("n1"), QStringLiteral("n2"), QStringLiteral("n3")};
        lf.namespaces.insert(QStringLiteral("/"), lf.nodes);
        launch.instances << lf;
        launch.nodes << instanceOf(QStringLiteral("n1"), nodes.nodes[0], false)
                     << instanceOf(QStringLiteral("n2"), nodes.nodes[1], true)
                     << instanceOf(QStringLiteral("n3"), nodes.nodes[2], true);
        const Architecture arch = Composer::run(nodes, launch, {});
        QCOMPARE(arch.composites.size(), 1);
        const Composite &c = arch.composites[0];
        QVERIFY(!channelNamed(c, QStringLiteral("/cmd"))); // teleop and relay stay apart
        const Channel *out = channelNamed(c, QStringLiteral("/out"));
        QVERIFY(out); // relay and base: both under the guess
        int onOut = 0;
        for (const Connection &conn : c.connections)
            onOut += conn.targetId == out->id ? 1 : 0;
        QCOMPARE(onOut, 2);
        // Both sides of /cmd are promoted, and the relay's keeps its mark.
        QCOMPARE(c.boundary.size(), 2);
        for (const BoundaryPort &b : c.boundary) {
            QCOMPARE(b.name, QStringLiteral("/cmd"));
            QCOMPARE(b.guessed, b.isInput());
        }

        // Decided, the same names meet.
        launch.nodes[1].guessedNamespace = false;
        launch.nodes[2].guessedNamespace = false;
        const Architecture decided = Composer::run(nodes, launch, {});
        QVERIFY(channelNamed(decided.composites[0], QStringLiteral("/cmd")));
        QVERIFY(decided.composites[0].boundary.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestGuessedNames)
#include "tst_guessednames.moc"
