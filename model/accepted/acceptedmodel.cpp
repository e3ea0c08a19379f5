#include "accepted/acceptedmodel.h"
#include "compose/composearchitecture.h"
#include "compose/subsystemgrouping.h"
#include "suggestions/suggestionitem.h"

#include <QSet>

namespace rosarch {

AcceptedDecisions AcceptedModel::select(const QMap<QString, SuggestionDecision> &decisions,
                                        const Recovery &recovery)
{
    AcceptedDecisions out;
    QSet<QString> items;
    bool itemsCollected = false;
    for (const SuggestionDecision &d : decisions) {
        if (d.status != Suggestion::Status::Accepted)
            continue;
        switch (d.kind) {
        case Suggestion::Kind::NodeDescription:
            if (recovery.nodes.node(d.targetId))
                out.descriptions.insert(d.targetId, d.proposal);
            break;
        case Suggestion::Kind::SubsystemGrouping: {
            const LaunchFileInstance *root = recovery.launch.instance(d.targetId);
            if (!root || !root->parentId.isEmpty())
                break;
            bool membersExist = !d.memberIds.isEmpty();
            for (const QString &m : d.memberIds)
                membersExist = membersExist && recovery.launch.node(m);
            if (membersExist)
                out.groupings.append({d.proposal, d.memberIds, d.targetId});
            break;
        }
        case Suggestion::Kind::NameResolution:
            if (!itemsCollected) {
                for (const SuggestionItem &item : SuggestionItem::collect(recovery))
                    items.insert(item.id);
                itemsCollected = true;
            }
            if (items.contains(d.targetId))
                out.names.insert(d.targetId, d.proposal);
            break;
        }
    }
    return out;
}

Recovery AcceptedModel::apply(const Recovery &recovery, const AcceptedDecisions &accepted)
{
    if (accepted.isEmpty())
        return recovery;
    Recovery out = recovery;
    for (AtomicNode &n : out.nodes.nodes)
        if (const auto it = accepted.descriptions.constFind(n.id);
            it != accepted.descriptions.cend())
            n.description = *it;

    // Accepted names for ports the code names by an expression ("arc_2/p1" -> value).
    bool renamed = false;
    for (auto it = accepted.names.cbegin(); it != accepted.names.cend(); ++it) {
        const QString nodeId = it.key().section(QLatin1Char('/'), 0, 0);
        const QString portId = it.key().section(QLatin1Char('/'), 1);
        if (portId.isEmpty() || it.key().contains(QLatin1Char('#')))
            continue; // launch items need a stage 2 run with the value
        for (AtomicNode &n : out.nodes.nodes) {
            if (n.id != nodeId)
                continue;
            for (Port &p : n.ports)
                if (p.id == portId && !p.isResolved()) {
                    p.name = it.value();
                    p.nameOrigin = NameOrigin::Literal;
                    renamed = true;
                }
        }
    }
    if (renamed)
        out.architecture = composeArchitecture(out.nodes, out.launch);
    out.architecture = SubsystemGrouping::apply(out.architecture, accepted.groupings);
    return out;
}

} // namespace rosarch
