#include "project/classifiercorrections.h"
#include "compose/composer.h"

#include <QSet>

namespace rosarch {

namespace {

/// "/a/b" for "a/b/", "/a/b" and "/a/b/"; "/" for the root.
QString normalizedNamespace(const QString &nameSpace)
{
    QString ns = nameSpace.trimmed();
    while (ns.endsWith(u'/'))
        ns.chop(1);
    if (ns.isEmpty())
        return QStringLiteral("/");
    return ns.startsWith(u'/') ? ns : u'/' + ns;
}

/// A port of a system instance that talks on a renamed channel, and the name it has now.
struct RenamedPort
{
    QString portId;
    QString name;
    QString systemNamespace;
};

} // namespace

QString ClassifierCorrections::relativeTo(const QString &name, const QString &systemNamespace)
{
    // In the root namespace nothing tells an absolute name from a relative one: it stays.
    const QString ns = normalizedNamespace(systemNamespace);
    if (!name.startsWith(u'/') || ns == QLatin1String("/") || name.size() <= ns.size() + 1 ||
        !name.startsWith(ns + u'/'))
        return name;
    return name.mid(ns.size() + 1);
}

QString ClassifierCorrections::carried(const QString &name, const QString &systemNamespace,
                                       const QString &classifierNamespace)
{
    const QString relative = relativeTo(name, systemNamespace);
    if (relative.startsWith(u'/'))
        return relative;
    QString ns = classifierNamespace.trimmed();
    while (ns.endsWith(u'/'))
        ns.chop(1);
    return ns.isEmpty() ? relative : ns + u'/' + relative;
}

void ClassifierCorrections::rename(Architecture *architecture, const AtomicNodeList &nodes,
                                   const LaunchDependencies &launch,
                                   const QHash<QString, QString> &renamed, const StableKeys &keys)
{
    if (renamed.isEmpty() || launch.classifierInstances.isEmpty())
        return;
    QSet<QString> renamedTo; // the channels as renamed: "topic:/robot1/status"
    for (auto it = renamed.cbegin(); it != renamed.cend(); ++it)
        renamedTo.insert(StableKeys::family(it.key()) + u':' + it.value());

    // The system's ports on a renamed channel, and then the same ports of the instances' copies
    // in the classifiers (the copies have the same port ids).
    QHash<QString, QList<RenamedPort>> ofCopy; // classifier node instance id -> its ports
    for (const Composite &c : std::as_const(architecture->composites))
        for (const RosNodePart &part : c.parts) {
            if (part.kind != RosNodePart::Kind::Node)
                continue;
            QList<RenamedPort> ports;
            for (const PartPort &pp : part.ports)
                if (pp.resolved && renamedTo.contains(channelKey(pp.kind, pp.name)))
                    ports.append({pp.id, pp.name, part.nameSpace});
            if (ports.isEmpty())
                continue;
            for (const QString &id : keys.instancesOf(keys.keyOf(part.instanceId)))
                if (id != part.instanceId)
                    ofCopy[id] += ports;
        }
    if (ofCopy.isEmpty())
        return;

    // Each classifier run (one launch file analysed alone, with what it includes) that holds
    // such a copy is composed again, the rename spelled as that run spells the channel: within
    // one run a name is one channel (blueprint §1, "Wiring in a launch file's own CCD").
    QHash<QString, QString> rootOf; // classifier launch-file instance -> the root of its run
    for (const LaunchFileInstance &lf : launch.classifierInstances) // parents come first
        rootOf.insert(lf.id, lf.parentId.isEmpty() ? lf.id : rootOf.value(lf.parentId));
    QSet<QString> touched;
    for (const NodeInstance &n : launch.classifierNodes)
        if (ofCopy.contains(n.id))
            touched.insert(rootOf.value(n.launchFileId));
    for (const LaunchFileInstance &root : launch.classifierInstances) {
        if (!root.parentId.isEmpty() || !touched.contains(root.id))
            continue;
        LaunchDependencies run;
        for (const LaunchFileInstance &lf : launch.classifierInstances)
            if (rootOf.value(lf.id) == root.id)
                run.instances.append(lf);
        for (const NodeInstance &n : launch.classifierNodes)
            if (rootOf.value(n.launchFileId) == root.id)
                run.nodes.append(n);
        const Architecture first = Composer::run(nodes, run, {}, renamed);
        QHash<QString, QString> spelled = renamed;
        bool more = false;
        for (const Composite &c : first.composites)
            for (const RosNodePart &part : c.parts) {
                const auto it = ofCopy.constFind(part.instanceId);
                if (part.kind != RosNodePart::Kind::Node || it == ofCopy.cend())
                    continue;
                for (const RenamedPort &r : *it)
                    for (const PartPort &pp : part.ports) {
                        if (pp.id != r.portId || !pp.resolved || pp.name == r.name)
                            continue;
                        const QString name = carried(r.name, r.systemNamespace, part.nameSpace);
                        if (pp.name == name)
                            continue;
                        spelled.insert(channelKey(pp.kind, pp.name), name);
                        more = true;
                    }
            }
        if (!more)
            continue;
        Architecture again = Composer::run(nodes, run, {}, spelled);
        Composite *composed = nullptr;
        for (Composite &c : again.composites)
            if (c.instanceId == root.id)
                composed = &c;
        if (!composed)
            continue;
        for (Composite &c : architecture->classifiers)
            if (c.instanceId == root.id) {
                c = std::move(*composed);
                break;
            }
    }
}

} // namespace rosarch
