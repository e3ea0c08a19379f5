#pragma once

#include "core/diagnostic.h"
#include "core/evidence.h"
#include "core/port.h"
#include "core/provenance.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// A port of a RosNodePart: an atomic port with its name resolved for the instance, or a
/// boundary port of the composite that types a launch-file part.
struct PartPort
{
    QString id; ///< the ARC port id (p1, s1, ps1, ...) or the included composite's boundary id
    PortKind kind = PortKind::Publisher;
    QString nameAsWritten; ///< the name in code ("" for a launch part's port)
    QString name; ///< the resolved absolute name ("/robot_ns/scan"); the guess when unresolved
    QString type; ///< canonical "pkg/msg/T"
    bool resolved = true; ///< false when the name is an expression the analysis could not decide
    /// The name comes from a remapping whose target rests on a launch value the analysis had to
    /// guess (an argument nobody sets): wired under the guess, but not a name to draw
    /// conclusions from, so the checks leave it out and the artifacts mark it unresolved.
    bool guessed = false;
    bool parameterDerived = false; ///< the name comes from a parameter (default or launch value)
    bool remapped = false;
    /// The remap rule that gave the port its name: an index into its node instance's remaps,
    /// past their end into its container's (process-wide rules); -1 when none did.
    int remap = -1;
    bool active = true; ///< the guard holds for this instance (or is undecidable)
    QString guard;      ///< as written ("" = always)
    QString qos;        ///< the QoS argument at the creating call, as written ("" = none)
    Evidence evidence;  ///< the port's creation in code (or the inner port for a boundary)
    Marks marks = {};   ///< provenance and review (blueprint §5); set by the corrected model
    /// The interface model the port comes from (code outside the workspace; its evidence is the
    /// launch action); "" for a port found in the workspace's code.
    QString model = {};
    bool operator==(const PartPort &) const = default;
};

/// A launch-time instance inside a composite: a node instance, or an included launch file.
struct RosNodePart
{
    enum class Kind
    {
        Node,
        Launch
    };

    QString id; ///< "part1", ... unique within the composite, in declaration order
    Kind kind = Kind::Node;
    QString instanceId;    ///< node instance id ("n3") or launch-file instance id ("lf2")
    QString name;          ///< node name; "" for a launch part
    QString typeName;      ///< the ARC's class name (exec name when unknown), or the included stem
    QString typeId;        ///< the ARC id, or the included launch-file instance id
    QString nameSpace;     ///< effective namespace ("/" at the root)
    bool active = true;    ///< the launch condition holds
    bool external = false; ///< an include of a launch file outside the workspace
    bool typed = true;     ///< false when the class could not be found (no ports known)
    QList<PartPort> ports;
    Evidence evidence; ///< the node or include in the launch file
    QString subsystem; ///< accepted subsystem grouping ("" = none)
    Marks marks = {};  ///< provenance and review (blueprint §5); set by the corrected model
    bool operator==(const RosNodePart &) const = default;
};

/// A topic, service or action bound inside a composite (it has both sides there).
struct Channel
{
    enum class Kind
    {
        Topic,
        Service,
        Action
    };

    QString id; ///< PlantUML-safe alias: "q_robot_ns_scan", "c_...", "a_..."
    Kind kind = Kind::Topic;
    QString name;     ///< resolved absolute name
    QString type;     ///< the first type seen; conflicts are diagnostics
    Marks marks = {}; ///< provenance and review (blueprint §5); set by the corrected model
    bool operator==(const Channel &) const = default;
};

/// A boundary port of a composite: an inner port with no counterpart inside, promoted.
struct BoundaryPort
{
    QString id; ///< "s1", "p1", "ps1", ... per composite, in order of first appearance
    PortKind kind = PortKind::Publisher; ///< the kind of the inner port(s)
    QString name; ///< resolved absolute name (what wiring at the next level up matches)
    QString type;
    bool guessed = false; ///< the inner port's name rests on a guessed launch value
    bool isInput() const; ///< subscriber, service server, action server
    bool operator==(const BoundaryPort &) const = default;
};

/// An edge inside a composite; endpoints are a part's port and a channel or boundary port.
struct Connection
{
    enum class Kind
    {
        Publish,
        Subscribe,
        Client,
        Server,
        DelegationIn,
        DelegationOut
    };

    Kind kind = Kind::Publish;
    QString partId;
    QString portId;
    QString targetId; ///< the channel id, or the boundary port id for a delegation
    bool operator==(const Connection &) const = default;
};

/// A ComposedRosNodeClassifier: the composition one launch-file instance defines.
struct Composite
{
    QString instanceId; ///< the launch-file instance ("lf1")
    QString stem;       ///< launch file stem: "robot" for robot.launch.py
    QString file;       ///< workspace-relative path ("" when external)
    QString package;
    QString parentId; ///< the including launch-file instance ("" for a root)
    /// The executable whose own code builds this system (blueprint §1, "Nodes built in code");
    /// "" for a launch file. `file` is then its main source.
    QString executable;
    QList<RosNodePart> parts;
    QList<Channel> channels;
    QList<BoundaryPort> boundary;
    QList<Connection> connections;

    const RosNodePart *part(const QString &id) const;
    const Channel *channel(const QString &id) const;
    const BoundaryPort *boundaryPort(const QString &id) const;
    bool operator==(const Composite &) const = default;
};

/// Stage 3's result: one composite per launch-file instance, plus the architecture checks.
struct Architecture
{
    QList<Composite> composites; ///< in launch-file instance order (roots first, depth first)
    /// One per launch file: the file analysed on its own, its classifier (blueprint §1); names
    /// relative to its scope stay relative. In launch-file order of first appearance.
    QList<Composite> classifiers;
    QList<Diagnostic> diagnostics;
    bool canceled = false;

    const Composite *composite(const QString &instanceId) const;
    /// The composite written as each launch file's CCD: its classifier, or, for a file without
    /// one (a skipped or over-budget run, a composition of given instances), its first
    /// instance (roots come first).
    QList<const Composite *> representatives() const;
    bool operator==(const Architecture &) const = default;
};

QString connectionKindName(Connection::Kind kind);
QString channelKindName(Channel::Kind kind);

} // namespace rosarch
