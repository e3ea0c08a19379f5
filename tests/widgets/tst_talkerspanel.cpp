// The Talkers panel counts node instances, not ports: a node with several ports on one name is
// one row with its ports under it, and a copy whose launch condition is false is listed greyed
// and counted apart, not as one more publisher.
#include "widgets/talkerspanel.h"

#include <QTreeWidget>
#include <QtTest>

using namespace rosarch;

namespace {

Talker talker(const QString &instance, const QString &node, PortKind kind, const QString &port,
              bool active = true)
{
    Talker t;
    t.instanceId = instance;
    t.nodeName = node;
    t.className = QStringLiteral("Planner");
    t.active = active;
    t.port.id = port;
    t.port.kind = kind;
    t.port.nameAsWritten = QStringLiteral("plan");
    t.port.name = QStringLiteral("/plan");
    t.port.active = active;
    return t;
}

} // namespace

class TestTalkersPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void countsNodeInstancesWithTheirPortsUnderThem()
    {
        TalkerGroup group;
        group.family = QStringLiteral("topic");
        group.name = QStringLiteral("/plan");
        group.type = QStringLiteral("nav_msgs/msg/Path");
        // the planner publishes /plan from two ports (a plugin's and its own); its inactive copy
        // (another launch condition) has the same two; one controller subscribes
        group.talkers = {
            talker(QStringLiteral("n1"), QStringLiteral("/planner"), PortKind::Publisher,
                   QStringLiteral("p1")),
            talker(QStringLiteral("n1"), QStringLiteral("/planner"), PortKind::Publisher,
                   QStringLiteral("p2")),
            talker(QStringLiteral("n2"), QStringLiteral("/planner_sim"), PortKind::Publisher,
                   QStringLiteral("p1"), false),
            talker(QStringLiteral("n2"), QStringLiteral("/planner_sim"), PortKind::Publisher,
                   QStringLiteral("p2"), false),
            talker(QStringLiteral("n3"), QStringLiteral("/controller"), PortKind::Subscriber,
                   QStringLiteral("s1")),
        };
        TalkersPanel panel;
        panel.showTalkers(QStringLiteral("topic /plan"), QStringLiteral("system"), {group});
        QTreeWidget *tree = panel.tree();
        QCOMPARE(tree->topLevelItemCount(), 1);
        const QTreeWidgetItem *head = tree->topLevelItem(0);
        QCOMPARE(head->text(0),
                 QStringLiteral("topic /plan · nav_msgs/msg/Path · 1 publisher, 1 subscriber, "
                                "1 inactive"));
        QCOMPARE(head->childCount(), 3); // three node instances
        QTreeWidgetItem *planner = head->child(0);
        QCOMPARE(planner->text(0), QStringLiteral("/planner"));
        QCOMPARE(planner->text(1), QStringLiteral("publisher"));
        QCOMPARE(planner->text(2), QStringLiteral("2 ports"));
        QCOMPARE(planner->childCount(), 2);
        QVERIFY(planner->isExpanded());
        QCOMPARE(planner->child(1)->text(2), QStringLiteral("p2  plan"));
        QCOMPARE(planner->child(1)->data(0, TalkersPanel::PortIdRole).toString(),
                 QStringLiteral("p2"));
        const QTreeWidgetItem *copy = head->child(1);
        QCOMPARE(copy->text(0), QStringLiteral("/planner_sim"));
        QCOMPARE(copy->foreground(0).color(),
                 panel.palette().color(QPalette::Disabled, QPalette::Text));
        QCOMPARE(planner->foreground(0).color() ==
                     panel.palette().color(QPalette::Disabled, QPalette::Text),
                 false);
        QTreeWidgetItem *controller = head->child(2);
        QCOMPARE(controller->text(2), QStringLiteral("s1  plan")); // one port: on its row
        QCOMPARE(controller->childCount(), 1);

        // choosing an instance or one of its ports goes there
        QSignalSpy chosen(&panel, &TalkersPanel::talkerSelected);
        tree->setCurrentItem(planner->child(1));
        QCOMPARE(chosen.size(), 1);
        QCOMPARE(chosen.first(), (QVariantList{QStringLiteral("n1"), QStringLiteral("p2")}));
        tree->setCurrentItem(controller);
        QCOMPARE(chosen.last(), (QVariantList{QStringLiteral("n3"), QStringLiteral("s1")}));
    }
};

QTEST_MAIN(TestTalkersPanel)
#include "tst_talkerspanel.moc"
