#include "plantuml/mermaidwriter.h"
#include "plantuml/plantumltext.h"

#include <QHash>
#include <QMap>

namespace rosarch {

namespace {

using PlantUmlText::safeId;

/// Mermaid labels go in double quotes; a quote inside becomes the #quot; entity, and the
/// characters Mermaid reads as markup inside a label are escaped the same way.
QString quoted(const QString &text)
{
    QString out;
    for (const QChar c : text) {
        if (c == QLatin1Char('"'))
            out += QStringLiteral("#quot;");
        else if (c == QLatin1Char('<'))
            out += QStringLiteral("#lt;");
        else if (c == QLatin1Char('>'))
            out += QStringLiteral("#gt;");
        else if (c == QLatin1Char('\n') || c == QLatin1Char('\r'))
            out += QLatin1Char(' ');
        else
            out += c;
    }
    return QLatin1Char('"') + out + QLatin1Char('"');
}

QString colour(Connection::Kind kind)
{
    switch (kind) {
    case Connection::Kind::Publish:
    case Connection::Kind::DelegationOut:
        return QStringLiteral("green");
    case Connection::Kind::Subscribe:
    case Connection::Kind::DelegationIn:
        return QStringLiteral("blue");
    case Connection::Kind::Client:
        return QStringLiteral("red");
    case Connection::Kind::Server:
        return QStringLiteral("purple");
    }
    return {};
}

} // namespace

QString MermaidWriter::flowchart(const Composite &c)
{
    QString out = QStringLiteral("flowchart LR\n");
    // Element ids are prefixed so that no id can be a Mermaid keyword ("end", "graph").
    QHash<QString, QString> ids;
    auto idOf = [&](const QString &elementId) {
        return ids.value(elementId, QStringLiteral("x_") + safeId(elementId));
    };
    QMap<QString, QList<const RosNodePart *>> byNamespace;
    for (const RosNodePart &p : c.parts)
        if (p.active)
            byNamespace[p.nameSpace.isEmpty() ? QStringLiteral("/") : p.nameSpace].append(&p);
    int subgraph = 0;
    for (auto it = byNamespace.cbegin(); it != byNamespace.cend(); ++it) {
        const bool root = it.key() == QLatin1String("/");
        const QString indent = root ? QStringLiteral("  ") : QStringLiteral("    ");
        if (!root)
            out += QStringLiteral("  subgraph ns%1[%2]\n").arg(++subgraph).arg(quoted(it.key()));
        for (const RosNodePart *p : *it) {
            const QString id = QStringLiteral("part_") + safeId(p->id);
            ids.insert(p->id, id);
            if (p->kind == RosNodePart::Kind::Launch)
                out += QStringLiteral("%1%2[[%3]]\n")
                           .arg(indent, id, quoted(QLatin1Char(':') + p->typeName));
            else
                out += QStringLiteral("%1%2[%3]\n")
                           .arg(indent, id, quoted(p->name + QStringLiteral(" : ") + p->typeName));
        }
        if (!root)
            out += QStringLiteral("  end\n");
    }
    for (const Channel &ch : c.channels) {
        const QString id = QStringLiteral("ch_") + safeId(ch.id);
        ids.insert(ch.id, id);
        const QString text =
            ch.type.isEmpty() ? ch.name : ch.name + QStringLiteral(" · ") + ch.type;
        out += ch.kind == Channel::Kind::Topic
                   ? QStringLiteral("  %1([%2])\n").arg(id, quoted(text))
                   : QStringLiteral("  %1{{%2}}\n").arg(id, quoted(text));
    }
    for (const BoundaryPort &b : c.boundary) {
        const QString id = QStringLiteral("b_") + safeId(b.id);
        ids.insert(b.id, id);
        out +=
            QStringLiteral("  %1>%2]\n")
                .arg(id, quoted(QStringLiteral("%1 %2 · %3")
                                    .arg(b.isInput() ? QStringLiteral("in") : QStringLiteral("out"),
                                         b.name, b.type)));
    }
    QStringList styles;
    int index = 0;
    QHash<QString, const RosNodePart *> parts; // Composite::part() is a linear search
    for (const RosNodePart &p : c.parts)
        parts.insert(p.id, &p);
    for (const Connection &k : c.connections) {
        const RosNodePart *part = parts.value(k.partId);
        if (!part || !part->active)
            continue;
        const QString from = idOf(k.partId);
        const QString to = idOf(k.targetId);
        const bool intoPart =
            k.kind == Connection::Kind::Subscribe || k.kind == Connection::Kind::DelegationIn;
        out += intoPart ? QStringLiteral("  %1 --> %2\n").arg(to, from)
                        : QStringLiteral("  %1 --> %2\n").arg(from, to);
        styles << QStringLiteral("  linkStyle %1 stroke:%2\n").arg(index++).arg(colour(k.kind));
    }
    return out + styles.join(QString());
}

QString MermaidWriter::write(const Composite &c)
{
    const QString title = c.file.isEmpty() ? c.stem : c.file;
    return QStringLiteral("# %1\n\nComposedClassifierDiagram of `%1`, written by rosarch.\n\n"
                          "```mermaid\n%2```\n")
        .arg(title, flowchart(c));
}

} // namespace rosarch
