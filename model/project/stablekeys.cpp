#include "project/stablekeys.h"

#include <QSet>

namespace rosarch {

namespace {

// The n-th (1-based) of otherwise identical keys gets "#n" from the second on, in model order.
class Ordinals
{
public:
    QString next(const QString &key)
    {
        const int n = ++m_seen[key];
        return n == 1 ? key : QStringLiteral("%1#%2").arg(key).arg(n);
    }

private:
    QHash<QString, int> m_seen;
};

QString writtenName(const Port &p)
{
    return p.nameExpression.isEmpty() ? p.name : p.nameExpression;
}

QString nodeLabel(const NodeInstance &n)
{
    return n.nodeName.isEmpty() ? n.execName : n.nodeName;
}

QString fileOf(const LaunchFileInstance &lf)
{
    return lf.file.isEmpty() ? QStringLiteral("%1/%2").arg(lf.package, lf.type) : lf.file;
}

} // namespace

StableKeys::StableKeys(const Recovery &recovery)
{
    addNodes(recovery.nodes);
    addLaunch(recovery.launch.instances, recovery.launch.nodes, false);
    addLaunch(recovery.launch.classifierInstances, recovery.launch.classifierNodes, true);
    addDeclarations();
    addComposites(recovery.architecture.composites);
    addComposites(recovery.architecture.classifiers);
}

QString StableKeys::packageKey(const QString &package)
{
    return QStringLiteral("package:") + package;
}

QString StableKeys::classKey(const AtomicNode &node)
{
    const QString name = node.qualifiedName.isEmpty() ? node.className : node.qualifiedName;
    return QStringLiteral("class:%1|%2").arg(node.packageName, name);
}

QString StableKeys::launchKey(const LaunchFileInstance &instance)
{
    return QStringLiteral("launch:") + fileOf(instance);
}

QString StableKeys::channelKey(PortKind kind, const QString &name)
{
    return portFamilyName(kind) + QLatin1Char(':') + name;
}

QString StableKeys::family(const QString &key)
{
    const qsizetype colon = key.indexOf(QLatin1Char(':'));
    if (colon <= 0)
        return {};
    const QString f = key.left(colon);
    static const QSet<QString> families = {QStringLiteral("package"), QStringLiteral("class"),
                                           QStringLiteral("port"),    QStringLiteral("launch"),
                                           QStringLiteral("include"), QStringLiteral("instance"),
                                           QStringLiteral("part"),    QStringLiteral("topic"),
                                           QStringLiteral("service"), QStringLiteral("action")};
    return families.contains(f) ? f : QString();
}

bool StableKeys::isChannelKey(const QString &key)
{
    const QString f = family(key);
    return f == QLatin1String("topic") || f == QLatin1String("service") ||
           f == QLatin1String("action");
}

void StableKeys::add(const QString &id, const QString &key)
{
    if (!m_keyOfId.contains(id))
        m_keyOfId.insert(id, key);
    if (!m_idOfKey.contains(key))
        m_idOfKey.insert(key, id);
}

void StableKeys::addNodes(const AtomicNodeList &nodes)
{
    Ordinals classes;
    for (const AtomicNode &n : nodes.nodes) {
        add(QStringLiteral("package:") + n.packageName, packageKey(n.packageName));
        const QString cls = classes.next(classKey(n));
        add(n.id, cls);
        Ordinals ports;
        const QString body = cls.mid(int(qstrlen("class:")));
        for (const Port &p : n.ports) {
            const QString key = ports.next(
                QStringLiteral("port:%1|%2|%3").arg(body, portKindName(p.kind), writtenName(p)));
            add(n.id + QLatin1Char('/') + p.id, key);
        }
    }
}

void StableKeys::addDeclarations()
{
    for (auto it = m_instancesOfKey.begin(); it != m_instancesOfKey.end(); ++it) {
        if (!it.key().startsWith(QLatin1String("instance:")))
            continue;
        QStringList ids = it.value();
        QSet<QString> listed(ids.cbegin(), ids.cend()); // a key may stand for 90,000 instances
        for (const QString &id : it.value())
            for (const QString &declared : m_classifierIdsOfPart.value(m_partOfInstance.value(id)))
                if (!listed.contains(declared)) {
                    listed.insert(declared);
                    ids.append(declared);
                }
        it.value() = ids;
    }
}

void StableKeys::addLaunch(const QList<LaunchFileInstance> &instances,
                           const QList<NodeInstance> &nodes, bool classifiers)
{
    QHash<QString, const LaunchFileInstance *> byId;
    for (const LaunchFileInstance &lf : instances)
        byId.insert(lf.id, &lf);
    // chain keys, parents first (instances come roots first, depth first)
    QHash<QString, QString> chainOf;
    Ordinals includes;
    auto addItems = [this](const QString &id, const QString &key,
                           const QList<Unresolved> &unresolved) {
        Ordinals items;
        for (int i = 0; i < unresolved.size(); ++i)
            add(QStringLiteral("%1#u%2").arg(id).arg(i + 1),
                items.next(QStringLiteral("%1#unresolved:%2:%3")
                               .arg(key, unresolved[i].kind, unresolved[i].expression)));
    };
    for (const LaunchFileInstance &lf : instances) {
        const QString parentChain = chainOf.value(lf.parentId);
        const QString chain =
            parentChain.isEmpty() ? fileOf(lf) : parentChain + QLatin1Char('>') + fileOf(lf);
        const QString key = includes.next(QStringLiteral("include:") + chain);
        chainOf.insert(lf.id, key.mid(int(qstrlen("include:"))));
        add(lf.id, key);
        m_instancesOfKey[key].append(lf.id);
        add(QStringLiteral("launch:") + fileOf(lf), launchKey(lf));
        addItems(lf.id, key, lf.unresolved);
        if (const LaunchFileInstance *parent = byId.value(lf.parentId)) {
            const QString part =
                QStringLiteral("part:%1|include:%2").arg(fileOf(*parent), fileOf(lf));
            m_instancesOfKey[part].append(lf.id);
            if (!m_idOfKey.contains(part))
                m_idOfKey.insert(part, lf.id);
        }
    }
    Ordinals siblings;
    QHash<QString, Ordinals> partOrdinals; // per launch-file instance
    for (const NodeInstance &n : nodes) {
        const QString chain = chainOf.value(n.launchFileId);
        const QString key =
            siblings.next(QStringLiteral("instance:%1|%2").arg(chain, nodeLabel(n)));
        add(n.id, key);
        m_instancesOfKey[key].append(n.id);
        addItems(n.id, key, n.unresolved);
        if (const LaunchFileInstance *lf = byId.value(n.launchFileId)) {
            const QString part = partOrdinals[lf->id].next(
                QStringLiteral("part:%1|%2").arg(fileOf(*lf), nodeLabel(n)));
            m_instancesOfKey[part].append(n.id);
            if (!m_idOfKey.contains(part))
                m_idOfKey.insert(part, n.id);
            if (classifiers)
                m_classifierIdsOfPart[part].append(n.id);
            else
                m_partOfInstance.insert(n.id, part);
        }
    }
}

void StableKeys::addComposites(const QList<Composite> &composites)
{
    for (const Composite &c : composites) {
        for (const RosNodePart &part : c.parts) {
            const QString instanceKey = m_keyOfId.value(part.instanceId);
            if (!instanceKey.isEmpty())
                m_keyOfId.insert(c.instanceId + QLatin1Char('/') + part.id, instanceKey);
            for (const PartPort &pp : part.ports)
                if (pp.resolved)
                    add(channelKey(pp.kind, pp.name), channelKey(pp.kind, pp.name));
        }
        for (const Channel &ch : c.channels) {
            const QString family = ch.kind == Channel::Kind::Topic     ? QStringLiteral("topic")
                                   : ch.kind == Channel::Kind::Service ? QStringLiteral("service")
                                                                       : QStringLiteral("action");
            add(c.instanceId + QLatin1Char('/') + ch.id, family + QLatin1Char(':') + ch.name);
        }
    }
}

QString StableKeys::keyOf(const QString &id) const
{
    if (const auto it = m_keyOfId.constFind(id); it != m_keyOfId.cend())
        return *it;
    return m_idOfKey.contains(id) ? id : QString();
}

QString StableKeys::idOf(const QString &key) const
{
    return m_idOfKey.value(key);
}

QStringList StableKeys::instancesOf(const QString &key) const
{
    return m_instancesOfKey.value(key);
}

bool StableKeys::contains(const QString &key) const
{
    return m_idOfKey.contains(key);
}

} // namespace rosarch
