#include "widgets/talkersearch.h"

#include <QSet>

#include <algorithm>
#include <functional>

namespace rosarch {

namespace {

QString qualifiedName(const RosNodePart &part)
{
    if (part.nameSpace.isEmpty() || part.nameSpace == QLatin1String("/"))
        return QLatin1Char('/') + part.name;
    return part.nameSpace + QLatin1Char('/') + part.name;
}

/// Calls `visit` for every node part of `compositeId` and of the composites it includes,
/// each composite once (an include cycle cannot loop).
void forEachNodePart(const Architecture &architecture, const QString &compositeId,
                     const std::function<void(const Composite &, const RosNodePart &)> &visit)
{
    QSet<QString> seen;
    const std::function<void(const QString &)> walk = [&](const QString &id) {
        const Composite *c = architecture.composite(id);
        if (!c || seen.contains(id))
            return;
        seen.insert(id);
        for (const RosNodePart &part : c->parts) {
            if (part.kind == RosNodePart::Kind::Launch)
                walk(part.instanceId);
            else
                visit(*c, part);
        }
    };
    walk(compositeId);
}

} // namespace

qsizetype TalkerGroup::providers() const
{
    return std::count_if(talkers.cbegin(), talkers.cend(),
                         [](const Talker &t) { return isProvidingPort(t.port.kind); });
}

TalkerGroup TalkerSearch::find(const Architecture &architecture, const QString &compositeId,
                               const QString &family, const QString &name)
{
    TalkerGroup group{family, name, {}, {}};
    forEachNodePart(architecture, compositeId, [&](const Composite &c, const RosNodePart &part) {
        for (const PartPort &port : part.ports) {
            if (port.name != name || portFamilyName(port.kind) != family)
                continue;
            if (group.type.isEmpty())
                group.type = port.type;
            group.talkers.append({part.instanceId, c.instanceId, part.id, qualifiedName(part),
                                  part.typeName, part.typed ? part.typeId : QString(),
                                  part.active && port.active, port});
        }
    });
    std::stable_sort(group.talkers.begin(), group.talkers.end(),
                     [](const Talker &a, const Talker &b) {
                         const bool pa = isProvidingPort(a.port.kind);
                         const bool pb = isProvidingPort(b.port.kind);
                         if (pa != pb)
                             return pa;
                         if (a.nodeName != b.nodeName)
                             return a.nodeName < b.nodeName;
                         return a.port.id < b.port.id;
                     });
    return group;
}

QList<TalkerGroup> TalkerSearch::ofClassPort(const Architecture &architecture,
                                             const QString &compositeId, const QString &classId,
                                             const QString &portId)
{
    QList<QPair<QString, QString>> names; // (family, name), sorted and unique
    forEachNodePart(architecture, compositeId, [&](const Composite &, const RosNodePart &part) {
        if (!part.typed || part.typeId != classId)
            return;
        for (const PartPort &port : part.ports)
            if (port.id == portId && !port.name.isEmpty())
                names.append({portFamilyName(port.kind), port.name});
    });
    std::sort(names.begin(), names.end(),
              [](const auto &a, const auto &b) { return a.second < b.second; });
    names.erase(std::unique(names.begin(), names.end()), names.end());
    QList<TalkerGroup> groups;
    for (const auto &[family, name] : std::as_const(names))
        groups.append(find(architecture, compositeId, family, name));
    return groups;
}

TalkerGroup TalkerSearch::ofPartPort(const Architecture &architecture, const QString &compositeId,
                                     const QString &partId, const QString &portId)
{
    const Composite *c = architecture.composite(compositeId);
    const RosNodePart *part = c ? c->part(partId) : nullptr;
    if (!part)
        return {};
    for (const PartPort &port : part->ports)
        if (port.id == portId && !port.name.isEmpty())
            return find(architecture, compositeId, portFamilyName(port.kind), port.name);
    return {};
}

QString TalkerSearch::scopeOfClass(const Architecture &architecture, const QString &compositeId,
                                   const QString &classId)
{
    const auto starts = [&](const QString &id) {
        bool found = false;
        forEachNodePart(architecture, id, [&](const Composite &, const RosNodePart &part) {
            found = found || (part.typed && part.typeId == classId);
        });
        return found;
    };
    if (!compositeId.isEmpty() && starts(compositeId))
        return compositeId;
    for (const Composite &c : architecture.composites)
        if (c.parentId.isEmpty() && starts(c.instanceId))
            return c.instanceId;
    return {};
}

} // namespace rosarch
