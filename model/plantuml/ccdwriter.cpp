#include "plantuml/ccdwriter.h"
#include "core/visibletext.h"
#include "plantuml/plantumltext.h"

#include <QHash>
#include <QSet>
#include <algorithm>

namespace rosarch {

using PlantUmlText::label;

namespace {

// An empty label does not parse in PlantUML; a channel is never unnamed, but the root name
// "/" is written relative as "".
QString channelLabel(const QString &name)
{
    return name.isEmpty() ? QStringLiteral("/") : label(name);
}

} // namespace
using PlantUmlText::safeId;

namespace {

QString arrow(Connection::Kind kind)
{
    switch (kind) {
    case Connection::Kind::Publish:
    case Connection::Kind::DelegationOut:
        return QStringLiteral("--[#Green,bold]-->");
    case Connection::Kind::Subscribe:
    case Connection::Kind::DelegationIn:
        return QStringLiteral("--[#Blue,bold]-->");
    case Connection::Kind::Client:
        return QStringLiteral("--[#Red,bold]-->");
    case Connection::Kind::Server:
        return QStringLiteral("--[#Purple,bold]-->");
    }
    return {};
}

QString namespaceLabel(const QString &ns)
{
    QString n = ns;
    while (n.startsWith(QLatin1Char('/')))
        n.remove(0, 1);
    return n;
}

QString partBlock(const RosNodePart &part, const QString &indent)
{
    QString out;
    const QString caption =
        part.kind == RosNodePart::Kind::Launch
            ? QStringLiteral(":%1").arg(label(part.typeName))
            : QStringLiteral("%1:\\n%2").arg(label(part.name), label(part.typeName));
    QStringList ports;
    for (const PartPort &p : part.ports) {
        if (!p.active)
            continue;
        // PlantUML rejects a comment after an element's alias: it stands on its own line, above.
        QString line =
            p.resolved && !p.guessed
                ? QString()
                : QStringLiteral("%1  ' name unresolved: %2\n").arg(indent, label(p.name));
        if (!p.model.isEmpty())
            line += QStringLiteral("%1  ' from interface model %2\n").arg(indent, label(p.model));
        // The id comes first and stays the label's first line, as in an ACD's topic frame; the
        // name a reader looks for follows, marked when it is only a guess.
        const QString name =
            channelLabel(p.name) + (p.resolved && !p.guessed ? QString() : QStringLiteral(" ?"));
        line += QStringLiteral("%1  %2 \"%3\\n%4\" as %5_%3")
                    .arg(indent,
                         isInputPort(p.kind) ? QStringLiteral("portin") : QStringLiteral("portout"),
                         p.id, name, part.id);
        ports << line;
    }
    out += QStringLiteral("%1component \"%2\" as %3 <<RosNodePart>>").arg(indent, caption, part.id);
    if (ports.isEmpty())
        return out + QLatin1Char('\n');
    out += QStringLiteral(" {\n") + ports.join(QLatin1Char('\n')) + QLatin1Char('\n') + indent +
           QStringLiteral("}\n");
    return out;
}

// PlantUML draws a composite's ports side by side along its top and bottom edges, and so are
// a part's; past this many on one edge the default top-to-bottom layout grows wider than
// PlantUML's default image limit (4096 px), and the ports are better stacked left to right.
constexpr int kPortsPerEdge = 12;

bool isLarge(const Composite &c)
{
    int in = 0, out = 0;
    for (const BoundaryPort &b : c.boundary)
        ++(b.isInput() ? in : out);
    if (std::max(in, out) > kPortsPerEdge)
        return true;
    for (const RosNodePart &part : c.parts) {
        int partIn = 0, partOut = 0;
        for (const PartPort &p : part.ports)
            if (p.active)
                ++(isInputPort(p.kind) ? partIn : partOut);
        if (part.active && std::max(partIn, partOut) > kPortsPerEdge)
            return true;
    }
    return false;
}

} // namespace

QString CcdWriter::write(const Composite &c, QList<WrittenElement> *elements)
{
    const QString top = safeId(c.stem);
    QString out = QStringLiteral("@startuml\n");
    // Records that the next line written declares the element (kind, id).
    const auto declare = [&](WrittenElement::Kind kind, const QString &id) {
        if (elements)
            elements->append({int(out.count(QLatin1Char('\n'))) + 1, kind, id});
    };
    if (!c.executable.isEmpty())
        out += QStringLiteral("' executable %1 of package %2, built in %3 (%4)\n")
                   .arg(c.executable, c.package, c.file, c.instanceId);
    else
        out += QStringLiteral("' launch file %1 (%2)\n")
                   .arg(c.file.isEmpty() ? c.stem : c.file, c.instanceId);
    if (isLarge(c))
        // Ports stacked down the sides, tight spacing and a smaller font keep a system of
        // navigation2's size readable within PlantUML's default limit; what still exceeds it is
        // shrunk to fit rather than cropped (README, "Large diagrams").
        out += QStringLiteral("left to right direction\n"
                              "skinparam nodesep 1\n"
                              "skinparam ranksep 5\n"
                              "skinparam defaultFontSize 9\n"
                              "scale max 4096*4096\n");
    out += QStringLiteral("component \"%1\" as %2 <<ComposedRosNodeClassifier>> {\n")
               .arg(label(c.stem), top);
    // Comments stand on a line of their own above the element (PlantUML rejects them after an
    // alias).
    for (const BoundaryPort &b : c.boundary) {
        out += QStringLiteral("  ' %1\n").arg(label(b.name));
        declare(WrittenElement::Kind::Boundary, b.id);
        out += QStringLiteral("  %1 \"%2 / %3\" as b_%2\n")
                   .arg(b.isInput() ? QStringLiteral("portin") : QStringLiteral("portout"), b.id,
                        PlantUmlText::type(b.type));
    }

    // Parts grouped by namespace, namespaces in order of first appearance; the root's parts
    // sit directly in the composite.
    QStringList namespaces;
    QHash<QString, QList<const RosNodePart *>> byNamespace;
    for (const RosNodePart &part : c.parts) {
        if (!part.active)
            continue;
        const QString ns = namespaceLabel(part.nameSpace);
        if (!byNamespace.contains(ns))
            namespaces.append(ns);
        byNamespace[ns].append(&part);
    }
    QSet<QString> nsAliases;
    QSet<QString> subAliases;
    for (const QString &ns : std::as_const(namespaces)) {
        const bool scoped = !ns.isEmpty();
        const QString indent = scoped ? QStringLiteral("    ") : QStringLiteral("  ");
        if (scoped) {
            QString alias = QStringLiteral("ns_") + safeId(ns);
            for (int n = 2; nsAliases.contains(alias); ++n)
                alias = QStringLiteral("ns_%1_%2").arg(safeId(ns)).arg(n);
            nsAliases.insert(alias);
            out += QStringLiteral("  package \"%1\" as %2 <<namespace>> {\n").arg(label(ns), alias);
        }
        // A subsystem is written where its first part stands, with all its parts of this
        // namespace; without subsystems this is the plain list of parts.
        const QList<const RosNodePart *> parts = byNamespace.value(ns);
        QSet<QString> written;
        for (const RosNodePart *part : parts) {
            if (part->subsystem.isEmpty()) {
                declare(WrittenElement::Kind::Part, part->id);
                out += partBlock(*part, indent);
                continue;
            }
            if (written.contains(part->subsystem))
                continue;
            written.insert(part->subsystem);
            QString alias = QStringLiteral("sub_") + safeId(part->subsystem);
            for (int n = 2; subAliases.contains(alias); ++n)
                alias = QStringLiteral("sub_%1_%2").arg(safeId(part->subsystem)).arg(n);
            subAliases.insert(alias);
            out += QStringLiteral("%1component \"%2\" as %3 <<Subsystem>> {\n")
                       .arg(indent, label(part->subsystem), alias);
            for (const RosNodePart *member : parts)
                if (member->subsystem == part->subsystem) {
                    declare(WrittenElement::Kind::Part, member->id);
                    out += partBlock(*member, indent + QStringLiteral("  "));
                }
            out += indent + QStringLiteral("}\n");
        }
        if (scoped)
            out += QStringLiteral("  }\n");
    }
    for (const Channel &ch : c.channels) {
        out += QStringLiteral("  ' %1\n").arg(PlantUmlText::type(ch.type));
        declare(WrittenElement::Kind::Channel, ch.id);
        switch (ch.kind) {
        case Channel::Kind::Topic:
            out += QStringLiteral("  queue \"%1\" as %2\n").arg(channelLabel(ch.name), ch.id);
            break;
        case Channel::Kind::Service:
            out += QStringLiteral("  circle \"%1\" as %2 <<Service>>\n")
                       .arg(channelLabel(ch.name), ch.id);
            break;
        case Channel::Kind::Action:
            out += QStringLiteral("  circle \"%1\" as %2 <<Action>>\n")
                       .arg(channelLabel(ch.name), ch.id);
            break;
        }
    }
    for (qsizetype i = 0; i < c.connections.size(); ++i) {
        const Connection &k = c.connections.at(i);
        declare(WrittenElement::Kind::Connection, QString::number(i));
        const QString port = QStringLiteral("%1_%2").arg(k.partId, k.portId);
        switch (k.kind) {
        case Connection::Kind::Subscribe:
            out += QStringLiteral("  %1 %2 %3\n").arg(k.targetId, arrow(k.kind), port);
            break;
        case Connection::Kind::DelegationIn:
            out += QStringLiteral("  b_%1 %2 %3\n").arg(k.targetId, arrow(k.kind), port);
            break;
        case Connection::Kind::DelegationOut:
            out += QStringLiteral("  %1 %2 b_%3\n").arg(port, arrow(k.kind), k.targetId);
            break;
        default:
            out += QStringLiteral("  %1 %2 %3\n").arg(port, arrow(k.kind), k.targetId);
        }
    }
    out += QStringLiteral("}\n@enduml\n");
    return out;
}

QMap<QString, QString> CcdWriter::fileStems(const Architecture &arch)
{
    const QList<const Composite *> reps = arch.representatives();
    QHash<QString, int> uses;
    for (const Composite *c : reps)
        ++uses[c->stem];
    QMap<QString, QString> stems;
    QSet<QString> taken;
    for (const Composite *c : reps) {
        QString stem = fileStemOf(uses.value(c->stem) > 1 && !c->package.isEmpty()
                                      ? QStringLiteral("%1__%2").arg(c->package, c->stem)
                                      : c->stem);
        const QString base = stem;
        for (int n = 2; taken.contains(stem); ++n)
            stem = QStringLiteral("%1_%2").arg(base).arg(n);
        taken.insert(stem);
        stems.insert(c->instanceId, stem);
    }
    // Every instance of a launch file points to its file's CCD.
    QHash<QString, QString> byFile;
    for (const Composite *c : reps)
        byFile.insert(c->file.isEmpty() ? c->stem : c->file, stems.value(c->instanceId));
    for (const Composite &c : arch.composites)
        if (!stems.contains(c.instanceId))
            stems.insert(c.instanceId, byFile.value(c.file.isEmpty() ? c.stem : c.file));
    return stems;
}

} // namespace rosarch
