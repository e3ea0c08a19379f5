#pragma once

#include <QHash>
#include <QList>
#include <QPointF>
#include <QRectF>
#include <QString>

namespace rosarch {

/// Display flags of a layout graph element; the layout ignores them, the drawing uses them.
enum LayoutFlag
{
    LayoutInactive = 0x1,          ///< greyed: condition or guard false
    LayoutUnresolved = 0x2,        ///< italic with "?": a name the analysis could not decide
    LayoutExternal = 0x4,          ///< outside the workspace
    LayoutOpenable = 0x8,          ///< an included launch file whose composite can be opened
    LayoutParameterDerived = 0x10, ///< a port whose name comes from a parameter
    LayoutCorrected = 0x20,        ///< a person's correction changed or added it (dashed tint)
    LayoutSuggested = 0x40,        ///< an accepted suggestion changed it
    LayoutReviewed = 0x80          ///< a person marked it reviewed (a small ✓)
};

/// A port of a node: a row on its left (input) or right (output) side.
struct LayoutPort
{
    QString id;  ///< unique within the node
    QString key; ///< back-reference to the model element
    QString label;
    bool input = true;
    int flags = 0;
    bool operator==(const LayoutPort &) const = default;
};

/// A node of a layout graph; its size is given by the caller (in points = scene units).
struct LayoutNode
{
    enum class Shape
    {
        Box,
        Queue,
        Ellipse,
        Hexagon,
        Tag,
        Folder
    };
    enum class Rank
    {
        Any,
        Source,
        Sink
    }; ///< Source = leftmost column, Sink = rightmost

    QString id;  ///< unique within the graph
    QString key; ///< back-reference to the model element
    QString label;
    QString detail; ///< a second, smaller line (type, class)
    Shape shape = Shape::Box;
    Rank rank = Rank::Any;
    QString cluster; ///< id of the innermost enclosing cluster ("" = none)
    double width = 80;
    double height = 36;
    double headerHeight = 0; ///< where the port rows start, from the top
    double rowHeight = 16;   ///< height of one port row
    QList<LayoutPort> ports;
    int flags = 0;

    /// Index of a port among the ports on its side (inputs and outputs count separately).
    int sideIndex(const QString &portId) const;
    /// The port's attachment point relative to the node's top-left corner.
    QPointF portAnchor(const QString &portId) const;
    int rowCount() const;
    bool operator==(const LayoutNode &) const = default;
};

/// A cluster: a frame around nodes and nested clusters, with a label on top.
struct LayoutCluster
{
    QString id;
    QString key;
    QString label;
    QString parent;         ///< enclosing cluster id ("" = top level)
    double labelWidth = 60; ///< the space reserved for the label
    double labelHeight = 18;
    int flags = 0;
    bool operator==(const LayoutCluster &) const = default;
};

/// A directed edge between two nodes, optionally from/to one of their ports.
struct LayoutEdge
{
    QString id;
    QString key;
    QString tail;
    QString tailPort; ///< "" = the node itself
    QString head;
    QString headPort;
    int category = 0; ///< the caller's kind of edge (colour); the layout ignores it
    bool dashed = false;
    int flags = 0;
    bool operator==(const LayoutEdge &) const = default;
};

/// A graph to lay out left to right: nodes, nested clusters and edges, in a stable order.
struct LayoutGraph
{
    QList<LayoutNode> nodes;
    QList<LayoutCluster> clusters; ///< parents before children
    QList<LayoutEdge> edges;
    double nodeSeparation = 18; ///< points between nodes of one rank
    double rankSeparation = 56; ///< points between ranks

    const LayoutNode *node(const QString &id) const;
    const LayoutCluster *cluster(const QString &id) const;
    bool operator==(const LayoutGraph &) const = default;
};

/// Where the layout put an edge: cubic Bézier control points (3n+1) and arrow tips.
struct EdgeGeometry
{
    QList<QPointF> points;
    bool hasArrowStart = false;
    QPointF arrowStart;
    bool hasArrowEnd = false;
    QPointF arrowEnd;
};

/// Coordinates of a laid-out graph, y pointing down, keyed by the graph's ids.
struct LayoutGeometry
{
    QRectF bounds;
    QHash<QString, QRectF> nodes;
    QHash<QString, QRectF> clusters;
    QHash<QString, QRectF> clusterLabels;
    QHash<QString, EdgeGeometry> edges;
};

} // namespace rosarch
