#include "suggestions/suggestionitem.h"

namespace rosarch {

QList<SuggestionItem> SuggestionItem::collect(const Recovery &recovery)
{
    QList<SuggestionItem> items;
    for (const AtomicNode &n : recovery.nodes.nodes)
        for (const Port &p : n.ports)
            if (p.nameOrigin == NameOrigin::Expression)
                items.append({n.id + QLatin1Char('/') + p.id, QStringLiteral("port-name"), n.id,
                              p.nameExpression.isEmpty() ? p.name : p.nameExpression, p.name,
                              p.evidence});
    auto add = [&](const QString &elementId, const QList<Unresolved> &list) {
        for (qsizetype i = 0; i < list.size(); ++i)
            items.append({QStringLiteral("%1#u%2").arg(elementId).arg(i + 1), list[i].kind,
                          elementId, list[i].expression, list[i].guess, list[i].evidence});
    };
    for (const LaunchFileInstance &lf : recovery.launch.instances)
        add(lf.id, lf.unresolved);
    for (const NodeInstance &n : recovery.launch.nodes)
        add(n.id, n.unresolved);
    return items;
}

} // namespace rosarch
