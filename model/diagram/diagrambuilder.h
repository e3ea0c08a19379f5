#pragma once

#include "core/composition.h"
#include "diagram/layoutgraph.h"

#include <QStringList>

#include <functional>

namespace rosarch {

/// What the composed diagram shows of a composite.
struct DiagramOptions
{
    bool showParameterPorts = true;  ///< ports whose name comes from a parameter
    bool showInactive = true;        ///< parts and ports whose condition or guard is false
    bool showExternal = true;        ///< includes of launch files outside the workspace
    QStringList collapsedNamespaces; ///< namespaces drawn as one box ("/robot1")
    QStringList compactParts;        ///< part ids drawn without port rows, wired by their box
    bool collapseBoundary = false;   ///< one box per side for all boundary ports
};

/// Text measures of the drawing, so that boxes fit their labels. The defaults estimate.
struct DiagramMetrics
{
    std::function<double(const QString &)> titleWidth; ///< part names (bold)
    std::function<double(const QString &)> textWidth;  ///< channel and boundary names
    std::function<double(const QString &)> smallWidth; ///< types, port labels
    double titleHeight = 16;
    double textHeight = 15;
    double smallHeight = 13;
};

/// The parts of an element key: "part:part1", "port:part1/s1", "channel:q_x", "boundary:s1",
/// "connection:3", "namespace:/robot1", "subsystem:perception".
struct DiagramKey
{
    enum class Kind
    {
        None,
        Part,
        Port,
        Channel,
        Boundary,
        Connection,
        Namespace,
        Subsystem
    };
    Kind kind = Kind::None;
    QString id;     ///< part, channel, boundary id, namespace, subsystem or connection index
    QString portId; ///< for ports
    int index() const { return id.toInt(); }
    static DiagramKey parse(const QString &key);
};

/// Composite → layout graph: parts with their ports, namespaces as nested clusters (accepted
/// subsystems as clusters inside them), channels as their own shapes, boundary ports in the
/// outer columns; every element keeps its key.
class DiagramBuilder
{
public:
    /// The layout graph for `composite`; the same input always gives the same graph.
    static LayoutGraph build(const Composite &composite, const DiagramOptions &options = {},
                             const DiagramMetrics &metrics = {});

    static QString partKey(const QString &partId);
    static QString portKey(const QString &partId, const QString &portId);
    static QString channelKey(const QString &channelId);
    static QString boundaryKey(const QString &boundaryId);
    /// The key of the box that stands for all boundary ports of a side (collapseBoundary).
    static QString collapsedBoundaryKey(bool input);
    static QString connectionKey(int index);
    static QString namespaceKey(const QString &nameSpace);
    /// The key of a subsystem's clusters; one per namespace its parts sit in, all with this key.
    static QString subsystemKey(const QString &name);

    /// "/a/b" → {"/a", "/a/b"}; the root ("/" or "") has none.
    static QStringList namespaceChain(const QString &nameSpace);
    /// Where an element comes from: a part's launch line, a port's creation in code; a
    /// connection or boundary port answers with its (first) part port's. Invalid for none.
    static Evidence evidence(const Composite &composite, const QString &key);
    /// The port of a part, or null.
    static const PartPort *port(const Composite &composite, const QString &partId,
                                const QString &portId);
};

} // namespace rosarch
