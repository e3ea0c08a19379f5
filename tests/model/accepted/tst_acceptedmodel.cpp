// The model as accepted: which stored decisions apply to a recovery, and what applying them
// changes (descriptions, names of ports named by an expression, subsystem groupings), nothing else.
#include "accepted/acceptedmodel.h"
#include "accepted/decisionstore.h"
#include "suggestions/suggestionitem.h"
#include "support/testsupport.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

SuggestionDecision decision(Suggestion::Kind kind, const QString &target, const QString &proposal,
                            Suggestion::Status status = Suggestion::Status::Accepted,
                            const QStringList &members = {})
{
    SuggestionDecision d;
    d.kind = kind;
    d.targetId = target;
    d.proposal = proposal;
    d.status = status;
    d.memberIds = members;
    d.decided = QDateTime(QDate(2026, 11, 24), QTime(12, 0), Qt::UTC);
    return d;
}

QMap<QString, SuggestionDecision> keyed(const QList<SuggestionDecision> &list)
{
    QMap<QString, SuggestionDecision> out;
    for (const SuggestionDecision &d : list)
        out.insert(d.key(), d);
    return out;
}

/// A root launch-file instance with at least two node instances below it, and two of them.
QPair<QString, QStringList> rootWithNodes(const Recovery &r)
{
    const auto rootOf = [&](QString id) {
        for (int depth = 0; depth < 100; ++depth) {
            const LaunchFileInstance *i = r.launch.instance(id);
            if (!i || i->parentId.isEmpty())
                break;
            id = i->parentId;
        }
        return id;
    };
    for (const LaunchFileInstance &root : r.launch.instances) {
        if (!root.parentId.isEmpty())
            continue;
        QStringList nodes;
        for (const NodeInstance &n : r.launch.nodes)
            if (rootOf(n.launchFileId) == root.id)
                nodes << n.id;
        if (nodes.size() >= 2)
            return {root.id, nodes.mid(0, 2)};
    }
    return {};
}

} // namespace

class TestAcceptedModel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        // Launch files with node instances, and a port the code names by an expression.
        m_recovery = recoverWorkspace(test::dataDir(QStringLiteral("suggest_groups")));
        QVERIFY(!m_recovery.nodes.nodes.isEmpty());
        QVERIFY(!m_recovery.architecture.composites.isEmpty());
    }

    void onlyAcceptedDecisionsOnExistingTargetsApply()
    {
        const auto [root, members] = rootWithNodes(m_recovery);
        QVERIFY(!root.isEmpty());
        const QString node = m_recovery.nodes.nodes.first().id;
        const AcceptedDecisions a = AcceptedModel::select(
            keyed({decision(Suggestion::Kind::NodeDescription, node, QStringLiteral("Does it.")),
                   decision(Suggestion::Kind::NodeDescription, QStringLiteral("arc_999"),
                            QStringLiteral("A node that is gone.")),
                   decision(Suggestion::Kind::NodeDescription, node, QStringLiteral("Rejected."),
                            Suggestion::Status::Rejected),
                   decision(Suggestion::Kind::SubsystemGrouping, root, QStringLiteral("core"),
                            Suggestion::Status::Accepted, members),
                   decision(Suggestion::Kind::SubsystemGrouping, root, QStringLiteral("ghosts"),
                            Suggestion::Status::Accepted, {QStringLiteral("n999")}),
                   decision(Suggestion::Kind::NameResolution, QStringLiteral("arc_999/p1"),
                            QStringLiteral("/gone"))}),
            m_recovery);
        QCOMPARE(a.descriptions, (QMap<QString, QString>{{node, QStringLiteral("Does it.")}}));
        QCOMPARE(a.groupings.size(), 1);
        QCOMPARE(a.groupings.first().name, QStringLiteral("core"));
        QCOMPARE(a.groupings.first().rootId, root);
        QCOMPARE(a.groupings.first().memberInstanceIds, members);
        QVERIFY(a.names.isEmpty());
    }

    void nothingAcceptedChangesNothing()
    {
        const Recovery same = AcceptedModel::apply(m_recovery, {});
        QCOMPARE(same.nodes.nodes, m_recovery.nodes.nodes);
        QCOMPARE(same.architecture.composites.size(), m_recovery.architecture.composites.size());
        for (qsizetype i = 0; i < same.architecture.composites.size(); ++i) {
            const Composite &a = same.architecture.composites.at(i);
            const Composite &b = m_recovery.architecture.composites.at(i);
            QCOMPARE(a.parts, b.parts);
            QCOMPARE(a.channels, b.channels);
            QCOMPARE(a.connections, b.connections);
            QCOMPARE(a.boundary, b.boundary);
        }
    }

    void applyingSetsDescriptionsGroupsAndNames()
    {
        const auto [root, members] = rootWithNodes(m_recovery);
        AcceptedDecisions a;
        const QString node = m_recovery.nodes.nodes.first().id;
        a.descriptions.insert(node, QStringLiteral("Accepted description."));
        a.groupings.append({QStringLiteral("core"), members, root});
        const Recovery r = AcceptedModel::apply(m_recovery, a);
        QCOMPARE(r.nodes.node(node)->description, QStringLiteral("Accepted description."));
        int grouped = 0;
        for (const Composite &c : r.architecture.composites)
            for (const RosNodePart &p : c.parts)
                if (members.contains(p.instanceId)) {
                    QCOMPARE(p.subsystem, QStringLiteral("core"));
                    ++grouped;
                }
        QVERIFY(grouped >= 2);
        // the recovery itself is a value: unchanged
        QVERIFY(m_recovery.nodes.node(node)->description !=
                QStringLiteral("Accepted description."));
    }

    void anAcceptedPortNameResolvesAndWires()
    {
        // A port named by an expression: accepting a name makes it a literal and composes again.
        const QList<SuggestionItem> items = SuggestionItem::collect(m_recovery);
        const SuggestionItem *port = nullptr;
        for (const SuggestionItem &i : items)
            if (i.kind == QLatin1String("port-name"))
                port = &i;
        QVERIFY2(port, "the fixture has a port named by an expression");
        const AcceptedDecisions a =
            AcceptedModel::select(keyed({decision(Suggestion::Kind::NameResolution, port->id,
                                                  QStringLiteral("/accepted_name"))}),
                                  m_recovery);
        QCOMPARE(a.names.value(port->id), QStringLiteral("/accepted_name"));
        const Recovery r = AcceptedModel::apply(m_recovery, a);
        const QString nodeId = port->id.section(QLatin1Char('/'), 0, 0);
        const QString portId = port->id.section(QLatin1Char('/'), 1);
        const AtomicNode *n = r.nodes.node(nodeId);
        QVERIFY(n);
        bool found = false;
        for (const Port &p : n->ports)
            if (p.id == portId) {
                QVERIFY(p.isResolved());
                QCOMPARE(p.name, QStringLiteral("/accepted_name"));
                found = true;
            }
        QVERIFY(found);
        bool composed = false;
        for (const Composite &c : r.architecture.composites)
            for (const RosNodePart &part : c.parts)
                for (const PartPort &pp : part.ports)
                    composed =
                        composed || (pp.name == QLatin1String("/accepted_name") && pp.resolved);
        QVERIFY2(composed, "stage 3 composed the accepted name");
    }

    void storedDecisionsRoundTrip()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("decisions.json"));
        const QMap<QString, SuggestionDecision> decisions = keyed({decision(
            Suggestion::Kind::NodeDescription, QStringLiteral("arc_1"), QStringLiteral("x"))});
        QString error;
        QVERIFY2(DecisionStore::save(file, dir.path(), decisions, &error), qPrintable(error));
        QCOMPARE(DecisionStore::load(file), decisions);
    }

private:
    Recovery m_recovery;
};

QTEST_GUILESS_MAIN(TestAcceptedModel)
#include "tst_acceptedmodel.moc"
