#include "suggestions/deterministicprovider.h"
#include "suggestions/nodedocumentation.h"
#include "suggestions/subsystemgrouper.h"

#include <QSet>

namespace rosarch {

DeterministicProvider::DeterministicProvider(const QString &workspaceRoot, const Recovery &recovery,
                                             const QDateTime &timestamp)
    : m_recovery(recovery), m_source(workspaceRoot), m_timestamp(timestamp.toUTC())
{
}

Suggestion DeterministicProvider::make(Suggestion::Kind kind) const
{
    Suggestion s;
    s.kind = kind;
    s.origin.provider = QStringLiteral("deterministic");
    s.origin.prompt = kind == Suggestion::Kind::NodeDescription
                          ? QStringLiteral("docstring")
                          : QStringLiteral("communication-graph");
    s.origin.timestamp = m_timestamp;
    return s;
}

QList<Suggestion> DeterministicProvider::describeNodes() const
{
    QList<Suggestion> out;
    for (const AtomicNode &node : m_recovery.nodes.nodes) {
        const std::optional<NodeDocumentation> doc = NodeDocumentation::read(m_source, node);
        if (!doc)
            continue;
        const QString &text = doc->text;
        const QString &quote = doc->quote;
        const int first = doc->first;
        const int last = doc->last;
        Suggestion s = make(Suggestion::Kind::NodeDescription);
        s.targetId = node.id;
        s.value = text;
        s.quoted = true;
        s.rationale = QStringLiteral("The documentation of %1 in %2, lines %3-%4.")
                          .arg(node.className, node.evidence.file)
                          .arg(first)
                          .arg(last);
        s.evidence.append({{node.evidence.file, first, 1, last, 0}, quote});
        out << s;
    }
    return out;
}

QList<Suggestion> DeterministicProvider::groupSubsystems() const
{
    QList<Suggestion> out;
    const SubsystemGrouper grouper(m_recovery);
    for (const LaunchFileInstance &root : m_recovery.launch.instances) {
        if (!root.parentId.isEmpty())
            continue;
        QSet<QString> scope{root.id};
        for (const LaunchFileInstance &lf : m_recovery.launch.instances)
            if (scope.contains(lf.parentId))
                scope.insert(lf.id);
        QStringList ids;
        for (const NodeInstance &n : m_recovery.launch.nodes)
            if (scope.contains(n.launchFileId))
                ids << n.id;
        for (const SubsystemGrouper::Group &g : grouper.groups(ids)) {
            Suggestion s = make(Suggestion::Kind::SubsystemGrouping);
            s.targetId = root.id;
            s.memberIds = g.memberIds;
            s.value = g.name;
            QStringList names = g.sharedNames.mid(0, 8);
            if (g.sharedNames.size() > 8)
                names << QStringLiteral("... (%1 in all)").arg(g.sharedNames.size());
            s.rationale =
                QStringLiteral("The instances communicate through %1 (label propagation over the "
                               "communication graph of %2; hub topics ignored).")
                    .arg(names.join(QStringLiteral(", ")), root.type);
            for (const QString &id : g.memberIds) {
                const NodeInstance *n = m_recovery.launch.node(id);
                const QStringList lines = m_source.lines(n->evidence.file);
                const int first = n->evidence.line;
                const int last = qMax(first, n->evidence.endLine);
                if (first < 1 || last > lines.size())
                    continue;
                const QString cited = lines.mid(first - 1, last - first + 1).join(QLatin1Char(' '));
                for (const QString &quote : {n->nodeName, n->execName})
                    if (!quote.isEmpty() && cited.contains(quote)) {
                        s.evidence.append({{n->evidence.file, first, n->evidence.column, last,
                                            n->evidence.endColumn},
                                           quote});
                        break;
                    }
            }
            out << s;
        }
    }
    return out;
}

QList<Suggestion> DeterministicProvider::suggest() const
{
    return describeNodes() + groupSubsystems();
}

} // namespace rosarch
