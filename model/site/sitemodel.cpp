#include "site/sitemodel.h"
#include "diagram/diagrambuilder.h"

#include <QHash>
#include <QSet>

#include <algorithm>

namespace rosarch {

namespace {

/// A file name for a page: the readable name with anything a file system or a URL minds
/// replaced, and a number added when two names meet (compared without case, for file systems
/// that ignore it).
class Slugs
{
public:
    QString take(const QString &readable)
    {
        QString slug;
        for (const QChar c : readable)
            slug += c.isLetterOrNumber() && c.unicode() < 128 ? c
                    : c == u'_' || c == u'-' || c == u'.'     ? c
                                                              : QChar(u'_');
        while (slug.startsWith(u'.') || slug.startsWith(u'_'))
            slug.remove(0, 1);
        slug.truncate(80);
        if (slug.isEmpty())
            slug = QStringLiteral("x");
        QString unique = slug;
        for (int n = 2; m_taken.contains(unique.toLower()); ++n)
            unique = QStringLiteral("%1-%2").arg(slug).arg(n);
        m_taken.insert(unique.toLower());
        return unique;
    }

private:
    QSet<QString> m_taken;
};

QString familyOf(PortKind kind)
{
    return portFamilyName(kind);
}

/// A launch file's own diagram writes names relative to its scope, which is `/` on its own.
QString absolute(const QString &name)
{
    return name.startsWith(u'/') ? name : u'/' + name;
}

QString qualifiedName(const RosNodePart &part)
{
    return SiteModel::qualifiedName(part);
}

bool useLess(const SitePortUse &a, const SitePortUse &b)
{
    if (a.system != b.system)
        return a.system < b.system;
    const QString an = qualifiedName(*a.part);
    const QString bn = qualifiedName(*b.part);
    if (an != bn)
        return an < bn;
    if (a.port && b.port && a.port->kind != b.port->kind)
        return int(a.port->kind) < int(b.port->kind);
    if (a.port && b.port && a.port->id != b.port->id)
        return a.port->id < b.port->id;
    return a.part->id < b.part->id;
}

} // namespace

SiteModel::SiteModel(Recovery recovery, Project project)
    : m_recovery(std::move(recovery)), m_project(std::move(project))
{
    m_findings = m_recovery.nodes.diagnostics;
    m_findings.append(m_recovery.launch.diagnostics);
    m_findings.append(m_recovery.architecture.diagnostics);
    indexSystems();
    indexChannels();
    assignPages();
}

QString SiteModel::channelKey(const QString &family, const QString &name)
{
    return family + u':' + name;
}

QString SiteModel::qualifiedName(const RosNodePart &part)
{
    const QString ns = part.nameSpace.isEmpty() || part.nameSpace == QLatin1String("/")
                           ? QString()
                           : part.nameSpace;
    return ns + u'/' + (part.name.isEmpty() ? part.typeName : part.name);
}

QString SiteModel::namespaceAnchor(const QString &nameSpace)
{
    QString id = QStringLiteral("ns");
    for (const QChar c : nameSpace)
        id += c.isLetterOrNumber() && c.unicode() < 128 ? c : QChar(u'-');
    return id;
}

QString SiteModel::compositeAnchor(const QString &instanceId)
{
    return QStringLiteral("c-") + instanceId;
}

QString SiteModel::diagramTarget(const Composite &composite, const QString &key,
                                 bool inSystem) const
{
    const DiagramKey k = DiagramKey::parse(key);
    switch (k.kind) {
    case DiagramKey::Kind::Part:
        if (const RosNodePart *part = composite.part(k.id)) {
            const Composite *included = m_recovery.architecture.composite(part->typeId);
            if (inSystem && part->kind == RosNodePart::Kind::Launch && !part->external &&
                included && !included->parts.isEmpty())
                return u'#' + compositeAnchor(part->typeId);
            return partPage(*part);
        }
        break;
    case DiagramKey::Kind::Port:
        if (const PartPort *port = DiagramBuilder::port(composite, k.id, k.portId);
            port && port->resolved && !port->guessed)
            return channelPage(channelKey(portFamilyName(port->kind), absolute(port->name)));
        break;
    case DiagramKey::Kind::Channel:
        if (const Channel *channel = composite.channel(k.id))
            return channelPage(channelKey(channelKindName(channel->kind), absolute(channel->name)));
        break;
    case DiagramKey::Kind::Boundary:
        if (const BoundaryPort *b = composite.boundaryPort(k.id); b && !b->guessed)
            return channelPage(channelKey(portFamilyName(b->kind), absolute(b->name)));
        break;
    case DiagramKey::Kind::Namespace:
        return u'#' + namespaceAnchor(k.id);
    default:
        break;
    }
    return {};
}

const SiteSystem *SiteModel::system(const QString &rootId) const
{
    for (const SiteSystem &s : m_systems)
        if (s.root.instanceId == rootId)
            return &s;
    return nullptr;
}

void SiteModel::indexSystems()
{
    const Architecture &architecture = m_recovery.architecture;
    QHash<QString, QList<const Composite *>> children;
    for (const Composite &c : architecture.composites)
        if (!c.parentId.isEmpty())
            children[c.parentId] << &c;
    QHash<QString, QString> pluginIds; // by qualified class name, as parameters name them
    for (const AtomicNode &n : m_recovery.nodes.nodes)
        if (n.isPlugin() && !pluginIds.contains(n.qualifiedName))
            pluginIds.insert(n.qualifiedName, n.id);
    for (const LaunchRoot &root : RootChoice::roots(architecture, m_recovery.launch)) {
        const Composite *top = architecture.composite(root.instanceId);
        if (!top)
            continue;
        SiteSystem system;
        system.root = root;
        QList<const Composite *> stack{top};
        while (!stack.isEmpty()) {
            const Composite *c = stack.takeFirst();
            system.composites << c;
            stack = children.value(c->instanceId) + stack; // depth first, in include order
        }
        QSet<QString> files;
        for (const Composite *c : std::as_const(system.composites)) {
            if (!c->file.isEmpty())
                files.insert(c->file);
            for (const RosNodePart &part : c->parts) {
                if (part.kind != RosNodePart::Kind::Node)
                    continue;
                const SitePortUse use{root.instanceId, c, &part, nullptr,
                                      m_recovery.launch.node(part.instanceId)};
                system.nodes << use;
                const QString classId = use.instance ? use.instance->classId : part.typeId;
                if (!classId.isEmpty())
                    m_instances[classId] << use;
                // A pluginlib plugin is where the instances that load it are.
                if (use.instance)
                    for (const ParameterSetting &plugin : use.instance->plugins)
                        if (const QString id = pluginIds.value(plugin.value); !id.isEmpty())
                            m_loaders[id] << use;
            }
        }
        for (const QString &file : std::as_const(files))
            m_launchSystems[file] << root.instanceId;
        std::sort(system.nodes.begin(), system.nodes.end(), useLess);
        const QString name = system.title();
        for (const Diagnostic &d : std::as_const(m_findings))
            system.findings += d.contexts.contains(name) ? 1 : 0;
        m_systems << system;
    }
    std::sort(m_systems.begin(), m_systems.end(),
              [](const SiteSystem &a, const SiteSystem &b) { return a.title() < b.title(); });
    for (auto *index : {&m_instances, &m_loaders})
        for (auto it = index->begin(); it != index->end(); ++it) {
            std::sort(it->begin(), it->end(), useLess);
            // one entry per instance, however many names load the plugin
            it->erase(std::unique(it->begin(), it->end(),
                                  [](const SitePortUse &a, const SitePortUse &b) {
                                      return a.part == b.part;
                                  }),
                      it->end());
        }
    for (auto it = m_launchSystems.begin(); it != m_launchSystems.end(); ++it)
        std::sort(it->begin(), it->end());
}

void SiteModel::indexChannels()
{
    for (SiteSystem &system : m_systems) {
        QSet<QString> keys;
        for (const SitePortUse &node : std::as_const(system.nodes))
            for (const PartPort &port : node.part->ports) {
                // A name analysis had to guess gets no page of its own: it would join
                // unrelated ports under the guess.
                if (!port.resolved || port.guessed || port.name.isEmpty())
                    continue;
                const QString key = channelKey(familyOf(port.kind), port.name);
                SiteChannel &channel = m_channels[key];
                channel.family = familyOf(port.kind);
                channel.name = port.name;
                if (!port.type.isEmpty() && !channel.types.contains(port.type))
                    channel.types << port.type;
                channel.uses << SitePortUse{node.system, node.composite, node.part, &port,
                                            node.instance};
                keys.insert(key);
            }
        system.channels = keys.values();
        std::sort(system.channels.begin(), system.channels.end());
    }
    for (SiteChannel &channel : m_channels) {
        std::sort(channel.types.begin(), channel.types.end());
        std::sort(channel.uses.begin(), channel.uses.end(), useLess);
    }
}

void SiteModel::assignPages()
{
    Slugs nodes;
    for (const AtomicNode &n : m_recovery.nodes.nodes) // sorted by package and class
        m_nodePages.insert(
            n.id,
            QStringLiteral("nodes/%1.html").arg(nodes.take(n.packageName + u'.' + n.className)));
    Slugs channels;
    for (auto it = m_channels.cbegin(); it != m_channels.cend(); ++it)
        m_channelPages.insert(
            it.key(), QStringLiteral("%1s/%2.html")
                          .arg(it->family, channels.take(it->name.mid(1).replace(u'/', u'.'))));
    Slugs launch;
    for (const QString &file : m_recovery.launch.launchFiles) // sorted
        m_launchPages.insert(
            file, QStringLiteral("launch/%1.html")
                      .arg(launch.take(packageOf(file) + u'.' + file.section(u'/', -1))));
    Slugs systems;
    for (const SiteSystem &s : std::as_const(m_systems))
        m_systemPages.insert(s.root.instanceId,
                             QStringLiteral("systems/%1.html").arg(systems.take(s.root.stem)));
    Slugs packages;
    QStringList names;
    for (const RosPackage &p : m_recovery.nodes.packages)
        names << p.name;
    std::sort(names.begin(), names.end());
    for (const QString &name : std::as_const(names))
        if (!m_packagePages.contains(name))
            m_packagePages.insert(name,
                                  QStringLiteral("packages/%1.html").arg(packages.take(name)));
}

QList<SitePortUse> SiteModel::instancesOf(const QString &classId) const
{
    return m_instances.value(classId);
}

QList<SitePortUse> SiteModel::loadersOf(const QString &pluginId) const
{
    return m_loaders.value(pluginId);
}

QStringList SiteModel::systemsWith(const QString &path) const
{
    return m_launchSystems.value(path);
}

QString SiteModel::packageOf(const QString &file) const
{
    QString best;
    qsizetype length = -1;
    for (const RosPackage &p : m_recovery.nodes.packages) {
        const QString prefix = p.path.isEmpty() ? QString() : p.path + u'/';
        if (file.startsWith(prefix) && prefix.size() > length) {
            best = p.name;
            length = prefix.size();
        }
    }
    return best;
}

QString SiteModel::partPage(const RosNodePart &part) const
{
    if (part.kind == RosNodePart::Kind::Launch) {
        const LaunchFileInstance *lf = m_recovery.launch.instance(part.typeId);
        return lf ? launchPage(lf->file) : QString();
    }
    const NodeInstance *instance = m_recovery.launch.node(part.instanceId);
    return nodePage(instance && !instance->classId.isEmpty() ? instance->classId : part.typeId);
}

} // namespace rosarch
