#pragma once

#include "diagram/rootchoice.h"
#include "pipeline/recovery.h"
#include "project/project.h"

#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

namespace rosarch {

/// One port of a node part in a system: who publishes, subscribes, serves or calls a name.
struct SitePortUse
{
    QString system; ///< the system's root launch-file instance id
    const Composite *composite = nullptr;
    const RosNodePart *part = nullptr;
    const PartPort *port = nullptr;
    const NodeInstance *instance = nullptr; ///< null when stage 2 has none (a given part)
};

/// A topic, service or action of the workspace: one resolved name and its family.
struct SiteChannel
{
    QString family; ///< "topic", "service" or "action"
    QString name;   ///< resolved, absolute
    QStringList types;
    QList<SitePortUse> uses; ///< by system, then node name, then port kind
};

/// A system: an entry point (a root launch file, or an executable that builds its nodes) with
/// the composites below it.
struct SiteSystem
{
    LaunchRoot root;
    QList<const Composite *> composites; ///< the root first, then its includes depth first
    QList<SitePortUse> nodes;            ///< one per node part (port null), by name
    QStringList channels;                ///< channel keys ("topic:/scan"), sorted
    int findings = 0;                    ///< findings seen in this system
    QString title() const { return root.file.isEmpty() ? root.stem : root.file; }
};

/// The accepted model as the site's pages read it: every page, its file name in the site, and
/// the indexes that join the stages (a node class's instances, a name's publishers, the
/// systems a launch file belongs to). Built once; pages are then pure functions of it.
class SiteModel
{
public:
    SiteModel(Recovery recovery, Project project);
    SiteModel(const SiteModel &) = delete; // the indexes point into m_recovery
    SiteModel &operator=(const SiteModel &) = delete;

    const Recovery &recovery() const { return m_recovery; }
    const Project &project() const { return m_project; }
    const QList<SiteSystem> &systems() const { return m_systems; }
    const SiteSystem *system(const QString &rootId) const;
    /// By key "topic:/scan", "service:/x", "action:/y"; sorted by key.
    const QMap<QString, SiteChannel> &channels() const { return m_channels; }
    /// Every diagnostic of the three stages, in stage order.
    const QList<Diagnostic> &findings() const { return m_findings; }

    /// The uses of node class `classId` (an ARC id) in the systems.
    QList<SitePortUse> instancesOf(const QString &classId) const;
    /// The node instances in the systems that load pluginlib plugin `pluginId` (an ARC id).
    QList<SitePortUse> loadersOf(const QString &pluginId) const;
    /// The systems whose launch tree holds the launch file at `path`.
    QStringList systemsWith(const QString &path) const;
    /// The package whose folder holds the workspace-relative `file` ("" when none).
    QString packageOf(const QString &file) const;

    /// Site-relative page paths ("nodes/pkg.Class.html"); "" for an element with no page.
    QString nodePage(const QString &classId) const { return m_nodePages.value(classId); }
    QString channelPage(const QString &key) const { return m_channelPages.value(key); }
    QString launchPage(const QString &path) const { return m_launchPages.value(path); }
    QString systemPage(const QString &rootId) const { return m_systemPages.value(rootId); }
    QString packagePage(const QString &name) const { return m_packagePages.value(name); }
    /// The page of a part's type: its node class, or its included launch file.
    QString partPage(const RosNodePart &part) const;

    /// The page (site-relative, or a fragment "#ns-x" of the system page) a diagram element
    /// of `composite` links to; "" for none. On a system page (`inSystem`) an included launch
    /// file leads to its drawing further down the page, "#c-lf2".
    QString diagramTarget(const Composite &composite, const QString &key, bool inSystem) const;
    /// The fragment id of an included composite's drawing on its system page.
    static QString compositeAnchor(const QString &instanceId);

    static QString channelKey(const QString &family, const QString &name);
    /// "/ns/name" of a node part (its type when it has no name).
    static QString qualifiedName(const RosNodePart &part);
    /// The fragment id of a namespace's first row in a system's node table.
    static QString namespaceAnchor(const QString &nameSpace);

private:
    void indexSystems();
    void indexChannels();
    void assignPages();

    Recovery m_recovery;
    Project m_project;
    QList<SiteSystem> m_systems;
    QMap<QString, SiteChannel> m_channels;
    QList<Diagnostic> m_findings;
    QMap<QString, QList<SitePortUse>> m_instances; ///< by class id
    QMap<QString, QList<SitePortUse>> m_loaders;   ///< by plugin id
    QMap<QString, QStringList> m_launchSystems;    ///< launch file -> system root ids
    QMap<QString, QString> m_nodePages, m_channelPages, m_launchPages, m_systemPages,
        m_packagePages;
};

} // namespace rosarch
