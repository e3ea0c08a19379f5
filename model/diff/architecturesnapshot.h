#pragma once

#include "pipeline/recovery.h"

#include <QList>
#include <QMap>
#include <QString>

namespace rosarch {

/// What `rosarch diff` compares, keyed by what the code and the launch files say (never by
/// the positional ids of one run): node classes with their ports, and for each launch file's
/// CCD its parts, the topics, services and actions it names, and who talks to them.
struct ArchitectureSnapshot
{
    struct Port
    {
        QString kind; ///< "publisher", "subscriber", ...
        QString name; ///< as written in the class; resolved in a part
        QString type;
        bool operator==(const Port &) const = default;
    };
    struct NodeClass
    {
        QString key; ///< package + qualified name (blueprint §5)
        QString name;
        QList<Port> ports;
    };
    struct Part
    {
        QString key;  ///< "/ns/name" for a node; ":stem" (+ namespace) for an included file
        QString type; ///< class name, or the included launch stem
    };
    struct Name
    {
        QString kind; ///< "topic", "service", "action"
        QString name; ///< resolved, absolute
        QString type;
    };
    struct Composite
    {
        QString file; ///< workspace-relative launch file: the key
        QList<Part> parts;
        QList<Name> names;       ///< channels and boundary ports, by kind + name
        QStringList connections; ///< "talker publishes topic /chatter"
    };

    QMap<QString, NodeClass> classes;    ///< by key
    QMap<QString, Composite> composites; ///< by launch file; one per file (its CCD)

    /// Reads atomic_nodes.json and architecture.json from an artifact folder (as `rosarch
    /// recover` writes it). False, with `error`, when they are missing or malformed.
    static bool load(const QString &folder, ArchitectureSnapshot *out, QString *error);
    /// The same from the JSON texts (architecture may be empty: no launch files).
    static bool read(const QByteArray &atomicNodes, const QByteArray &architecture,
                     ArchitectureSnapshot *out, QString *error);
    /// From a recovery in memory, through the same JSON a run writes.
    static ArchitectureSnapshot of(const Recovery &recovery);
};

} // namespace rosarch
