#include "diagram/diagrambuilder.h"
#include "core/visibletext.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <optional>

namespace rosarch {

namespace {

constexpr double kPadding = 10;   // inside boxes, left and right
constexpr double kPortInset = 12; // port labels start this far from the box edge
constexpr double kColumnGap = 18; // between input and output labels

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::DiagramBuilder", text);
}

/// The default measures: an estimate by character count.
DiagramMetrics completed(DiagramMetrics m)
{
    const auto estimate = [](double perCharacter) {
        return [perCharacter](const QString &s) { return s.size() * perCharacter; };
    };
    if (!m.titleWidth)
        m.titleWidth = estimate(7.5);
    if (!m.textWidth)
        m.textWidth = estimate(7);
    if (!m.smallWidth)
        m.smallWidth = estimate(6);
    return m;
}

/// Graphviz's HTML cells take whole points, and the drawing anchors ports at the same spots.
double even(double v)
{
    return 2 * std::ceil(v / 2);
}

QString portLabel(const PartPort &port)
{
    const QString name = visibleText(port.nameAsWritten.isEmpty() ? port.name : port.nameAsWritten);
    return port.resolved ? name : QStringLiteral("?") + name;
}

struct Visibility
{
    QSet<QString> parts;
    QSet<QString> ports; // "part/port"
};

Visibility visibleElements(const Composite &c, const DiagramOptions &o)
{
    Visibility v;
    for (const RosNodePart &part : c.parts) {
        if ((!o.showInactive && !part.active) || (!o.showExternal && part.external))
            continue;
        v.parts.insert(part.id);
        for (const PartPort &port : part.ports) {
            if ((!o.showInactive && !port.active) ||
                (!o.showParameterPorts && port.parameterDerived))
                continue;
            v.ports.insert(part.id + QLatin1Char('/') + port.id);
        }
    }
    return v;
}

/// The outermost collapsed namespace that contains `nameSpace`, or "".
QString collapsedAncestor(const QString &nameSpace, const QStringList &collapsed)
{
    for (const QString &ns : DiagramBuilder::namespaceChain(nameSpace))
        if (collapsed.contains(ns))
            return ns;
    return {};
}

int marksFlags(const Marks &marks)
{
    return (marks.provenance == Provenance::Corrected   ? LayoutCorrected
            : marks.provenance == Provenance::Suggested ? LayoutSuggested
                                                        : 0) |
           (marks.reviewed ? LayoutReviewed : 0);
}

LayoutNode partNode(const RosNodePart &part, const Visibility &visible, bool compact,
                    const DiagramMetrics &m)
{
    LayoutNode n;
    n.id = n.key = DiagramBuilder::partKey(part.id);
    if (part.kind == RosNodePart::Kind::Launch) {
        n.label = visibleText(part.typeName); // names come from files: no control characters
        n.detail = part.external ? tr("external launch file") : tr("launch file");
        if (!part.external)
            n.flags |= LayoutOpenable;
    } else {
        n.label = visibleText(part.name.isEmpty() ? part.typeName : part.name);
        n.detail = visibleText(part.typed ? part.typeName : QStringLiteral("?") + part.typeName);
        if (!part.typed)
            n.flags |= LayoutUnresolved;
    }
    if (!part.active)
        n.flags |= LayoutInactive;
    if (part.external)
        n.flags |= LayoutExternal;
    n.flags |= marksFlags(part.marks);
    n.headerHeight = std::ceil(8 + m.titleHeight + m.smallHeight + 6);
    n.rowHeight = std::ceil(m.smallHeight + 6);
    double inputWidth = 0;
    double outputWidth = 0;
    int portCount = 0;
    for (const PartPort &port : part.ports) {
        if (!visible.ports.contains(part.id + QLatin1Char('/') + port.id))
            continue;
        ++portCount;
        if (compact)
            continue;
        LayoutPort p;
        p.id = port.id;
        p.key = DiagramBuilder::portKey(part.id, port.id);
        p.label = portLabel(port);
        p.input = isInputPort(port.kind);
        p.flags = (port.active ? 0 : LayoutInactive) |
                  (port.resolved && !port.guessed ? 0 : LayoutUnresolved) |
                  (port.parameterDerived ? LayoutParameterDerived : 0) | marksFlags(port.marks);
        double &side = p.input ? inputWidth : outputWidth;
        side = std::max(side, m.smallWidth(p.label));
        n.ports << p;
    }
    if (compact && portCount > 0) // the ports stay countable: "Planner · 12 ports"
        n.detail = portCount == 1 ? tr("%1 · 1 port").arg(n.detail)
                                  : tr("%1 · %2 ports").arg(n.detail).arg(portCount);
    const double header = std::max(m.titleWidth(n.label), m.smallWidth(n.detail)) + 2 * kPadding +
                          ((n.flags & LayoutOpenable) ? 24 : 0);
    const double rows = inputWidth + outputWidth + 2 * kPortInset + kColumnGap;
    n.width = even(std::max({header, rows, 96.0}));
    n.height = std::ceil(n.headerHeight + n.rowCount() * n.rowHeight + (n.ports.isEmpty() ? 0 : 6));
    return n;
}

LayoutNode labelledNode(const QString &key, const QString &label, const QString &detail,
                        LayoutNode::Shape shape, const DiagramMetrics &m)
{
    LayoutNode n;
    n.id = n.key = key;
    n.label = visibleText(label);
    n.detail = visibleText(detail);
    n.shape = shape;
    const double text = std::max(m.textWidth(n.label), m.smallWidth(n.detail)) + 2 * kPadding;
    const double height = m.textHeight + m.smallHeight + 12;
    switch (shape) {
    case LayoutNode::Shape::Ellipse:
        n.width = text * 1.2 + 8;
        n.height = height * 1.3;
        break;
    case LayoutNode::Shape::Hexagon: {
        // Graphviz's hexagon has its corners a quarter of the width in: at the text's top
        // and bottom it is only (1 - d/h) of its full width.
        n.height = height + 6;
        const double d = (m.textHeight + m.smallHeight) / 2;
        n.width = text / (1 - d / n.height);
        break;
    }
    case LayoutNode::Shape::Queue:
        n.width = text + 12;
        n.height = height;
        break;
    default:
        n.width = text + 8;
        n.height = height;
        break;
    }
    n.width = even(n.width);
    n.height = even(n.height);
    return n;
}

LayoutNode::Shape channelShape(Channel::Kind kind)
{
    switch (kind) {
    case Channel::Kind::Topic:
        return LayoutNode::Shape::Queue;
    case Channel::Kind::Service:
        return LayoutNode::Shape::Ellipse;
    case Channel::Kind::Action:
        return LayoutNode::Shape::Hexagon;
    }
    return LayoutNode::Shape::Box;
}

void addClusters(LayoutGraph &g, const QString &nameSpace, const DiagramMetrics &m)
{
    QString parent;
    for (const QString &ns : DiagramBuilder::namespaceChain(nameSpace)) {
        const QString key = DiagramBuilder::namespaceKey(ns);
        if (!g.cluster(key)) {
            LayoutCluster c;
            c.id = c.key = key;
            c.label = visibleText(ns);
            c.parent = parent;
            c.labelWidth = std::ceil(m.textWidth(ns) + 12);
            c.labelHeight = std::ceil(m.textHeight + 6);
            g.clusters << c;
        }
        parent = key;
    }
}

/// The cluster of `part`'s subsystem in its namespace's cluster `parent`, made on first use: one
/// per namespace, the first with the key as id, the others "key@namespace" to stay unique.
QString subsystemCluster(LayoutGraph &g, const RosNodePart &part, const QString &parent,
                         const DiagramMetrics &m)
{
    const QString key = DiagramBuilder::subsystemKey(part.subsystem);
    for (const LayoutCluster &c : std::as_const(g.clusters))
        if (c.key == key && c.parent == parent)
            return c.id;
    LayoutCluster c;
    c.key = key;
    c.id = g.cluster(key) ? key + QLatin1Char('@') + part.nameSpace : key;
    c.label = visibleText(part.subsystem);
    c.parent = parent;
    c.labelWidth = std::ceil(m.textWidth(part.subsystem) + 12);
    c.labelHeight = std::ceil(m.textHeight + 6);
    g.clusters << c;
    return c.id;
}

} // namespace

DiagramKey DiagramKey::parse(const QString &key)
{
    DiagramKey k;
    const int colon = key.indexOf(QLatin1Char(':'));
    if (colon < 0)
        return k;
    const QStringView kind = QStringView(key).left(colon);
    k.id = key.mid(colon + 1);
    if (kind == QLatin1String("part")) {
        k.kind = Kind::Part;
    } else if (kind == QLatin1String("port")) {
        k.kind = Kind::Port;
        const int slash = k.id.indexOf(QLatin1Char('/'));
        k.portId = k.id.mid(slash + 1);
        k.id = k.id.left(slash);
    } else if (kind == QLatin1String("channel")) {
        k.kind = Kind::Channel;
    } else if (kind == QLatin1String("boundary")) {
        k.kind = Kind::Boundary;
    } else if (kind == QLatin1String("connection")) {
        k.kind = Kind::Connection;
    } else if (kind == QLatin1String("namespace")) {
        k.kind = Kind::Namespace;
    } else if (kind == QLatin1String("subsystem")) {
        k.kind = Kind::Subsystem;
    }
    return k;
}

QString DiagramBuilder::partKey(const QString &partId)
{
    return QStringLiteral("part:") + partId;
}
QString DiagramBuilder::portKey(const QString &partId, const QString &portId)
{
    return QStringLiteral("port:%1/%2").arg(partId, portId);
}
QString DiagramBuilder::channelKey(const QString &channelId)
{
    return QStringLiteral("channel:") + channelId;
}
QString DiagramBuilder::boundaryKey(const QString &boundaryId)
{
    return QStringLiteral("boundary:") + boundaryId;
}
QString DiagramBuilder::collapsedBoundaryKey(bool input)
{
    return boundaryKey(input ? QStringLiteral("*in") : QStringLiteral("*out"));
}
QString DiagramBuilder::connectionKey(int index)
{
    return QStringLiteral("connection:%1").arg(index);
}
QString DiagramBuilder::namespaceKey(const QString &nameSpace)
{
    return QStringLiteral("namespace:") + nameSpace;
}

QString DiagramBuilder::subsystemKey(const QString &name)
{
    return QStringLiteral("subsystem:") + name;
}

QStringList DiagramBuilder::namespaceChain(const QString &nameSpace)
{
    QStringList chain;
    QString path;
    for (const QString &segment : nameSpace.split(QLatin1Char('/'), Qt::SkipEmptyParts)) {
        path += QLatin1Char('/') + segment;
        chain << path;
    }
    return chain;
}

const PartPort *DiagramBuilder::port(const Composite &composite, const QString &partId,
                                     const QString &portId)
{
    if (const RosNodePart *part = composite.part(partId))
        for (const PartPort &p : part->ports)
            if (p.id == portId)
                return &p;
    return nullptr;
}

Evidence DiagramBuilder::evidence(const Composite &c, const QString &key)
{
    const DiagramKey k = DiagramKey::parse(key);
    const auto portEvidence = [&c](const QString &partId, const QString &portId) {
        const PartPort *p = port(c, partId, portId);
        return p ? p->evidence : Evidence();
    };
    switch (k.kind) {
    case DiagramKey::Kind::Part:
        if (const RosNodePart *part = c.part(k.id))
            return part->evidence;
        break;
    case DiagramKey::Kind::Port:
        return portEvidence(k.id, k.portId);
    case DiagramKey::Kind::Connection:
        if (k.index() >= 0 && k.index() < c.connections.size())
            return portEvidence(c.connections[k.index()].partId, c.connections[k.index()].portId);
        break;
    case DiagramKey::Kind::Boundary:
        for (const Connection &conn : c.connections)
            if (conn.targetId == k.id && (conn.kind == Connection::Kind::DelegationIn ||
                                          conn.kind == Connection::Kind::DelegationOut))
                return portEvidence(conn.partId, conn.portId);
        break;
    default:
        break;
    }
    return {};
}

LayoutGraph DiagramBuilder::build(const Composite &c, const DiagramOptions &options,
                                  const DiagramMetrics &givenMetrics)
{
    const DiagramMetrics m = completed(givenMetrics);
    const Visibility visible = visibleElements(c, options);
    LayoutGraph g;

    // Edges first, on paper: which channels and boundary ports keep a visible connection.
    struct Wire
    {
        int index;
        const Connection *connection;
        QString partNode;
        QString portId;
        QString home; // the namespace whose cluster holds the part's node
    };
    QList<Wire> wires;
    QSet<QString> connectedTargets;
    QSet<QString> usedTargets;
    QHash<QString, int> collapsedCounts;
    for (const RosNodePart &part : c.parts)
        if (visible.parts.contains(part.id))
            if (const QString ns = collapsedAncestor(part.nameSpace, options.collapsedNamespaces);
                !ns.isEmpty())
                collapsedCounts[ns]++;
    for (int i = 0; i < c.connections.size(); ++i) {
        const Connection &conn = c.connections[i];
        connectedTargets.insert(conn.targetId);
        if (!visible.ports.contains(conn.partId + QLatin1Char('/') + conn.portId))
            continue;
        const RosNodePart *part = c.part(conn.partId);
        if (!part)
            continue;
        const QString ns = collapsedAncestor(part->nameSpace, options.collapsedNamespaces);
        const QStringList chain = namespaceChain(ns);
        const bool compact = options.compactParts.contains(part->id);
        wires << Wire{i, &conn, ns.isEmpty() ? partKey(part->id) : namespaceKey(ns),
                      ns.isEmpty() && !compact ? conn.portId : QString(),
                      ns.isEmpty() ? part->nameSpace : chain.value(chain.size() - 2)};
        usedTargets.insert(conn.targetId);
    }
    // A channel whose every wire ends in one collapsed namespace is inside that box: counted
    // there, not drawn (with its edges) outside it.
    QHash<QString, QSet<QString>> channelEnds;
    for (const Wire &w : std::as_const(wires))
        if (c.channel(w.connection->targetId))
            channelEnds[w.connection->targetId].insert(w.partNode);
    QSet<QString> innerChannels;
    QHash<QString, int> innerCounts; // per collapsed namespace
    for (auto it = channelEnds.cbegin(); it != channelEnds.cend(); ++it)
        if (it.value().size() == 1 &&
            DiagramKey::parse(*it.value().cbegin()).kind == DiagramKey::Kind::Namespace) {
            innerChannels.insert(it.key());
            innerCounts[DiagramKey::parse(*it.value().cbegin()).id]++;
        }
    const auto shown = [&](const QString &id) {
        return !innerChannels.contains(id) &&
               (usedTargets.contains(id) || !connectedTargets.contains(id));
    };

    // The boundary ports of one side, or one box that stands for them all.
    const auto addBoundary = [&](bool input) {
        int count = 0;
        for (const BoundaryPort &b : c.boundary) {
            if (isInputPort(b.kind) != input || !shown(b.id))
                continue;
            ++count;
            if (options.collapseBoundary)
                continue;
            LayoutNode n =
                labelledNode(boundaryKey(b.id), b.name, b.type, LayoutNode::Shape::Tag, m);
            if (b.guessed)
                n.flags |= LayoutUnresolved;
            n.rank = input ? LayoutNode::Rank::Source : LayoutNode::Rank::Sink;
            g.nodes << n;
        }
        if (!options.collapseBoundary || count == 0)
            return;
        const QString label = input
                                  ? (count == 1 ? tr("1 port in") : tr("%1 ports in").arg(count))
                                  : (count == 1 ? tr("1 port out") : tr("%1 ports out").arg(count));
        LayoutNode n = labelledNode(collapsedBoundaryKey(input), label, tr("boundary, collapsed"),
                                    LayoutNode::Shape::Tag, m);
        n.rank = input ? LayoutNode::Rank::Source : LayoutNode::Rank::Sink;
        g.nodes << n;
    };
    addBoundary(true);
    QSet<QString> collapsedDone;
    for (const RosNodePart &part : c.parts) {
        if (!visible.parts.contains(part.id))
            continue;
        const QString ns = collapsedAncestor(part.nameSpace, options.collapsedNamespaces);
        if (!ns.isEmpty()) {
            if (collapsedDone.contains(ns))
                continue;
            collapsedDone.insert(ns);
            const int count = collapsedCounts.value(ns);
            const int inner = innerCounts.value(ns);
            const QString parts = count == 1 ? tr("1 part") : tr("%1 parts").arg(count);
            const QString detail = inner == 0 ? tr("%1, collapsed").arg(parts)
                                   : inner == 1
                                       ? tr("%1, 1 channel, collapsed").arg(parts)
                                       : tr("%1, %2 channels, collapsed").arg(parts).arg(inner);
            LayoutNode n = labelledNode(namespaceKey(ns), ns, detail, LayoutNode::Shape::Folder, m);
            n.width =
                even(std::max(m.titleWidth(n.label), m.smallWidth(n.detail)) + 2 * kPadding + 8);
            n.height = even(m.titleHeight + m.smallHeight + 24); // + the folder tab
            const QStringList chain = namespaceChain(ns);
            if (chain.size() > 1) {
                addClusters(g, chain[chain.size() - 2], m);
                n.cluster = namespaceKey(chain[chain.size() - 2]);
            }
            g.nodes << n;
            continue;
        }
        LayoutNode n = partNode(part, visible, options.compactParts.contains(part.id), m);
        addClusters(g, part.nameSpace, m);
        const QStringList chain = namespaceChain(part.nameSpace);
        n.cluster = chain.isEmpty() ? QString() : namespaceKey(chain.last());
        if (!part.subsystem.isEmpty())
            n.cluster = subsystemCluster(g, part, n.cluster, m);
        g.nodes << n;
    }
    for (const Channel &ch : c.channels) {
        if (!shown(ch.id))
            continue;
        LayoutNode n = labelledNode(channelKey(ch.id), ch.name, ch.type, channelShape(ch.kind), m);
        n.flags |= marksFlags(ch.marks);
        // Inside the innermost namespace that holds all its parts: a channel between two
        // parts of one namespace drawn outside that namespace's frame would tangle the layout.
        std::optional<QStringList> common;
        // Likewise inside a subsystem when every part on the channel belongs to it.
        QSet<QString> homes; // "namespace\nsubsystem" per wire's part; "" in a collapsed one
        const RosNodePart *member = nullptr;
        for (const Wire &w : std::as_const(wires)) {
            if (w.connection->targetId != ch.id)
                continue;
            member = c.part(w.connection->partId);
            homes.insert(w.portId.isEmpty()
                             ? QString()
                             : member->nameSpace + QLatin1Char('\n') + member->subsystem);
            const QStringList chain = namespaceChain(w.home);
            if (!common) {
                common = chain;
                continue;
            }
            int same = 0;
            while (same < common->size() && same < chain.size() && common->at(same) == chain[same])
                ++same;
            *common = common->mid(0, same);
        }
        if (common && !common->isEmpty())
            n.cluster = namespaceKey(common->last());
        if (homes.size() == 1 && !homes.contains(QString()) && !member->subsystem.isEmpty())
            n.cluster = subsystemCluster(g, *member, n.cluster, m);
        g.nodes << n;
    }
    addBoundary(false);
    // Boundary ports line up on the frame: one width per side.
    for (const auto rank : {LayoutNode::Rank::Source, LayoutNode::Rank::Sink}) {
        double width = 0;
        for (const LayoutNode &n : std::as_const(g.nodes))
            if (n.rank == rank)
                width = std::max(width, n.width);
        for (LayoutNode &n : g.nodes)
            if (n.rank == rank)
                n.width = width;
    }

    QSet<QString> seen;
    for (const Wire &w : std::as_const(wires)) {
        const Connection &conn = *w.connection;
        const BoundaryPort *boundary = c.boundaryPort(conn.targetId);
        const QString target = c.channel(conn.targetId) ? channelKey(conn.targetId)
                               : boundary && options.collapseBoundary
                                   ? collapsedBoundaryKey(isInputPort(boundary->kind))
                                   : boundaryKey(conn.targetId);
        const bool fromPart = conn.kind == Connection::Kind::Publish ||
                              conn.kind == Connection::Kind::Client ||
                              conn.kind == Connection::Kind::DelegationOut;
        LayoutEdge e;
        e.id = e.key = connectionKey(w.index);
        e.tail = fromPart ? w.partNode : target;
        e.tailPort = fromPart ? w.portId : QString();
        e.head = fromPart ? target : w.partNode;
        e.headPort = fromPart ? QString() : w.portId;
        e.category = int(conn.kind);
        e.dashed = conn.kind == Connection::Kind::DelegationIn ||
                   conn.kind == Connection::Kind::DelegationOut;
        // A collapsed namespace carries each of its wires once.
        const QString signature =
            QStringList{e.tail, e.tailPort, e.head, e.headPort, QString::number(e.category)}.join(
                QLatin1Char('|'));
        if (seen.contains(signature) || innerChannels.contains(conn.targetId))
            continue;
        seen.insert(signature);
        if (!g.node(e.tail) || !g.node(e.head))
            continue;
        g.edges << e;
    }
    std::sort(g.clusters.begin(), g.clusters.end(),
              [](const LayoutCluster &a, const LayoutCluster &b) { return a.id < b.id; });
    return g;
}

} // namespace rosarch
