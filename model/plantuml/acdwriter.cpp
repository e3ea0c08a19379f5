#include "plantuml/acdwriter.h"
#include "core/visibletext.h"
#include "plantuml/plantumltext.h"

#include <QHash>
#include <QSet>

namespace rosarch {

using PlantUmlText::label;

namespace {

QString comment(const Port &p)
{
    QStringList notes;
    if (p.nameOrigin == NameOrigin::Parameter)
        notes << QStringLiteral("name from parameter '%1'").arg(p.parameter);
    else if (p.nameOrigin == NameOrigin::Expression)
        notes << QStringLiteral("name unresolved: %1")
                     .arg(label(p.nameExpression.isEmpty() ? p.name : p.nameExpression));
    if (!p.guard.isEmpty())
        notes << QStringLiteral("guard: %1").arg(label(p.guard));
    if (!p.via.isEmpty())
        notes << QStringLiteral("via %1").arg(p.via);
    if (p.inherited)
        notes << QStringLiteral("inherited");
    return notes.isEmpty()
               ? QString()
               : QStringLiteral("  ' ") + notes.join(QStringLiteral("; ")) + QLatin1Char('\n');
}

bool isTopic(PortKind k)
{
    return k == PortKind::Publisher || k == PortKind::Subscriber;
}

} // namespace

QString AcdWriter::write(const AtomicNode &node)
{
    QString out;
    out += QStringLiteral("@startuml\n");
    out += QStringLiteral("' %1 (%2) in package %3\n")
               .arg(node.qualifiedName.isEmpty() ? node.className : node.qualifiedName,
                    compileTypeName(node.compileType), node.packageName);
    if (node.isPlugin()) // a pluginlib plugin: its ports are those of the node that loads it
        out += QStringLiteral("' plugin of %1; {plugin} is the name it is loaded under\n")
                   .arg(node.pluginInterface);
    out += QStringLiteral("component \"<<AtomicRosNodeClassifier>>\\n%1\" as node {\n")
               .arg(label(node.className));
    for (const Port &p : node.ports) {
        if (p.kind == PortKind::Subscriber)
            out += QStringLiteral("  portin \"%1\" as %2\n")
                       .arg(p.callback.isEmpty() ? QStringLiteral(" ") : label(p.callback), p.id);
        else if (p.kind == PortKind::Publisher)
            out += QStringLiteral("  portout \" \" as %1\n").arg(p.id);
    }
    out += QStringLiteral("}\n");
    for (const Port &p : node.ports) {
        // a name only an instance's value gives (declared without a default): the parameter
        const QString shown = p.name.isEmpty() && !p.parameter.isEmpty()
                                  ? QStringLiteral("$(%1)").arg(p.parameter)
                                  : p.name;
        const QString caption = QStringLiteral("%1\\n%2").arg(p.id, label(shown));
        out += comment(p);
        if (isTopic(p.kind)) {
            out += QStringLiteral("frame \"%1\" as topic_%2 {\n").arg(caption, p.id);
            out += QStringLiteral("  rectangle \"**%1**\" as t_%2\n")
                       .arg(PlantUmlText::type(p.type), p.id);
            out += QStringLiteral("}\n");
            continue;
        }
        const bool service = p.kind == PortKind::ServiceServer || p.kind == PortKind::ServiceClient;
        const bool provided = p.kind == PortKind::ServiceServer || p.kind == PortKind::ActionServer;
        const QString prefix = service ? QStringLiteral("srv") : QStringLiteral("act");
        const QString t = service ? QStringLiteral("st") : QStringLiteral("at");
        const QString f = service ? QStringLiteral("sf") : QStringLiteral("af");
        out += QStringLiteral("folder \"%1\" as %2_%3 {\n").arg(caption, prefix, p.id);
        out += QStringLiteral("  rectangle \"**%1**\" as %2_%3\n")
                   .arg(PlantUmlText::type(p.type), t, p.id);
        if (provided && !p.callback.isEmpty())
            out += QStringLiteral("  rectangle \"%1(...)\" as %2_%3\n")
                       .arg(label(p.callback), f, p.id);
        out += QStringLiteral("}\n");
    }
    for (const Port &p : node.ports) {
        switch (p.kind) {
        case PortKind::Subscriber:
            out += QStringLiteral("topic_%1 -[#blue,bold]-> %1\n").arg(p.id);
            break;
        case PortKind::Publisher:
            out += QStringLiteral("%1 -[#green,bold]-> topic_%1\n").arg(p.id);
            break;
        case PortKind::ServiceServer:
            out += QStringLiteral("node --0 srv_%1\n").arg(p.id);
            break;
        case PortKind::ServiceClient:
            out += QStringLiteral("node --( srv_%1\n").arg(p.id);
            break;
        case PortKind::ActionServer:
            out += QStringLiteral("node --0 act_%1\n").arg(p.id);
            break;
        case PortKind::ActionClient:
            out += QStringLiteral("node --( act_%1\n").arg(p.id);
            break;
        }
    }
    out += QStringLiteral("@enduml\n");
    return out;
}

QMap<QString, QString> AcdWriter::fileStems(const AtomicNodeList &list)
{
    QHash<QString, int> byClass;
    for (const AtomicNode &n : list.nodes)
        ++byClass[n.className];
    QMap<QString, QString> stems;
    QSet<QString> used;
    for (const AtomicNode &n : list.nodes) {
        QString stem = fileStemOf(byClass.value(n.className) > 1 && !n.packageName.isEmpty()
                                      ? n.packageName + QLatin1Char('.') + n.className
                                      : n.className);
        const QString base = stem;
        for (int k = 2; used.contains(stem); ++k)
            stem = base + QLatin1Char('_') + QString::number(k);
        used.insert(stem);
        stems.insert(n.id, stem);
    }
    return stems;
}

} // namespace rosarch
