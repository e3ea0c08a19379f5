#pragma once

#include "core/port.h"
#include "pipeline/recovery.h"

#include <QHash>
#include <QString>
#include <QStringList>

namespace rosarch {

/// The stable keys (blueprint §5) of every element of one recovery, and back. Ids inside an
/// artifact (`arc_1`, `n3`, `lf2`) are positions; a key is built from what the code says, so a
/// decision or correction that names its target by key finds it again after the code changed,
/// or finds nothing (it is orphaned), and never lands on another element.
///
/// Keys, each prefixed by what it names:
/// - `package:<name>`
/// - `class:<package>|<qualified class name>` (node classes and plugins)
/// - `port:<package>|<qualified class>|<kind>|<name as written>` (`#2`... among identical ones)
/// - `launch:<workspace-relative path>` (an external one: `launch:<package>/<file name>`)
/// - `include:<path>>...><path>`: a launch-file instance, by the chain of files down to it
/// - `instance:<chain>|<node name, else executable>`: a node instance (`#2`... among siblings)
/// - `part:<path>|<node name, else executable>` or `part:<path>|include:<path>`: a part of the
///   CCD of the file at `<path>`; it designates every instance of that declaration
/// - `topic:<name>`, `service:<name>`, `action:<name>`: a resolved name
/// - `<instance or port key>#unresolved:<kind>:<expression>`: an item analysis left open
class StableKeys
{
public:
    StableKeys() = default;
    explicit StableKeys(const Recovery &recovery);

    /// The key of an element by the id the model and the suggestions use: "arc_3" (class),
    /// "arc_3/p1" (port), "n3" (node instance), "lf2" (launch-file instance), "n3#u1" and
    /// "lf2#u1" (unresolved items), "lf2/part3" (a part of the composite of lf2), or a key
    /// itself (returned as is). "" when there is no such element.
    QString keyOf(const QString &id) const;
    /// The element `key` names in this recovery ("" when none): the id keyOf takes. A `part:`
    /// key names the first instance of its declaration; instancesOf has all of them.
    QString idOf(const QString &key) const;
    /// Every node or launch-file instance id `key` designates (an `instance:`, `include:` or
    /// `part:` key), in model order; empty when it designates none. A node instance's key also
    /// designates its declaration in the CCD of the launch file that declares it, so that a
    /// correction of an instance shows in that file's diagram too.
    QStringList instancesOf(const QString &key) const;
    /// True when `key` names an element of this recovery.
    bool contains(const QString &key) const;

    static QString packageKey(const QString &package);
    static QString classKey(const AtomicNode &node);
    static QString launchKey(const LaunchFileInstance &instance);
    /// `<kind>:<name>` of a topic, service or action (the same text as channelKey).
    static QString channelKey(PortKind kind, const QString &name);
    /// The family of a key: "class", "port", "instance", "include", "part", "topic", ... ("" if
    /// it is not a key).
    static QString family(const QString &key);
    /// True for a `topic:`, `service:` or `action:` key: a resolved name, its own key.
    static bool isChannelKey(const QString &key);

private:
    void add(const QString &id, const QString &key);
    void addNodes(const AtomicNodeList &nodes);
    void addLaunch(const QList<LaunchFileInstance> &instances, const QList<NodeInstance> &nodes,
                   bool classifiers);
    /// An instance in a system is also its declaration in the CCD of the file that declares it.
    void addDeclarations();
    void addComposites(const QList<Composite> &composites);

    QHash<QString, QString> m_keyOfId;
    QHash<QString, QString> m_idOfKey;
    QHash<QString, QStringList> m_instancesOfKey;
    QHash<QString, QString> m_partOfInstance;          ///< node instance id -> part key
    QHash<QString, QStringList> m_classifierIdsOfPart; ///< part key -> CCD node instance ids
};

} // namespace rosarch
