#include "atomicnodetext.h"
#include "rospackage.h"

namespace rosarch {

namespace {

QString location(const Evidence &e)
{
    return QStringLiteral("%1:%2").arg(e.file).arg(e.line);
}

QString html(const QString &s)
{
    return s.toHtmlEscaped();
}

} // namespace

QString AtomicNodeText::portKindLabel(PortKind kind)
{
    switch (kind) {
    case PortKind::Publisher:
        return tr("Publisher");
    case PortKind::Subscriber:
        return tr("Subscriber");
    case PortKind::ServiceServer:
        return tr("Service server");
    case PortKind::ServiceClient:
        return tr("Service client");
    case PortKind::ActionServer:
        return tr("Action server");
    case PortKind::ActionClient:
        return tr("Action client");
    }
    return {};
}

QString AtomicNodeText::nodeDetails(const AtomicNode &node)
{
    QStringList parts;
    if (!node.nodeName.isEmpty())
        parts << tr("node: %1").arg(node.nodeName);
    if (!node.execution().isEmpty())
        parts << (node.executables.isEmpty() ? tr("plugin: %1") : tr("exec: %1"))
                     .arg(node.execution());
    parts << (node.compileType == AtomicNode::CompileType::Python ? tr("Python") : tr("C++"));
    if (node.lifecycle)
        parts << tr("lifecycle");
    return parts.join(QStringLiteral(" · "));
}

QString AtomicNodeText::portDetails(const Port &port)
{
    QStringList parts;
    if (!port.callback.isEmpty())
        parts << tr("callback: %1").arg(port.callback);
    switch (port.nameOrigin) {
    case NameOrigin::Literal:
        break;
    case NameOrigin::Member:
        parts << tr("member");
        break;
    case NameOrigin::Local:
        parts << tr("local");
        break;
    case NameOrigin::Parameter:
        parts << tr("param: %1").arg(port.parameter);
        break;
    case NameOrigin::Expression:
        parts << tr("unresolved: %1").arg(port.nameExpression);
        break;
    }
    if (!port.guard.isEmpty())
        parts << tr("guard: %1").arg(port.guard);
    if (!port.via.isEmpty())
        parts << tr("via: %1").arg(port.via);
    if (port.inherited)
        parts << tr("inherited");
    return parts.join(QStringLiteral(" · "));
}

QString AtomicNodeText::packageToolTip(const QString &name, const RosPackage *pkg, int nodeCount)
{
    QString tip = tr("<b>ROS 2 package</b> %1").arg(html(name));
    if (!pkg)
        return tip + QStringLiteral("<br/>") +
               tr("Named by node sources only; no package.xml found.");
    if (!pkg->buildType.isEmpty())
        tip += QStringLiteral("<br/>") + tr("Build type: %1").arg(html(pkg->buildType));
    tip += QStringLiteral("<br/>") +
           (nodeCount == 1 ? tr("1 atomic node") : tr("%1 atomic nodes").arg(nodeCount));
    if (pkg->evidence.isValid())
        tip += QStringLiteral("<br/>") + tr("Declared in %1").arg(html(location(pkg->evidence)));
    return tip;
}

QString AtomicNodeText::nodeToolTip(const AtomicNode &node)
{
    const QString what = node.isPlugin()   ? tr("pluginlib plugin")
                         : node.lifecycle  ? tr("Lifecycle node class")
                         : node.procedural ? tr("Procedurally built node")
                                           : tr("Atomic ROS node class");
    QString tip =
        QStringLiteral("<b>%1</b> %2")
            .arg(what, html(node.qualifiedName.isEmpty() ? node.className : node.qualifiedName));
    const auto line = [&tip](const QString &text) { tip += QStringLiteral("<br/>") + text; };
    if (!node.nodeName.isEmpty())
        line(tr("Node name in code: %1").arg(html(node.nodeName)));
    if (!node.baseClasses.isEmpty())
        line(tr("Derives from: %1").arg(html(node.baseClasses.join(QStringLiteral(", ")))));
    if (node.isPlugin())
        line(tr("Exported as a %1 plugin: a node that loads it (by its parameters) gets these "
                "ports; {plugin} in a name is the name it is loaded under")
                 .arg(html(node.pluginInterface)));
    if (!node.executables.isEmpty())
        line(
            tr("Started by executable: %1").arg(html(node.executables.join(QStringLiteral(", ")))));
    if (!node.plugins.isEmpty())
        line(tr("Component plugin: %1").arg(html(node.plugins.join(QStringLiteral(", ")))));
    line(tr("Compile type: %1")
             .arg(node.compileType == AtomicNode::CompileType::Python ? tr("Python") : tr("C++")));
    line(node.ports.size() == 1 ? tr("1 port") : tr("%1 ports").arg(node.ports.size()));
    if (!node.description.isEmpty())
        line(tr("Description: %1").arg(html(node.description)));
    if (node.evidence.isValid())
        line(tr("Defined at %1").arg(html(location(node.evidence))));
    return tip;
}

QString AtomicNodeText::portToolTip(const AtomicNode &node, const Port &port)
{
    QString tip = QStringLiteral("<b>%1</b> %2")
                      .arg(portKindLabel(port.kind),
                           html(port.name.isEmpty() ? port.nameExpression : port.name));
    const auto line = [&tip](const QString &text) { tip += QStringLiteral("<br/>") + text; };
    line(tr("Of node %1").arg(html(node.className)));
    if (!port.type.isEmpty())
        line(tr("Interface type: %1").arg(html(port.type)));
    if (!port.callback.isEmpty())
        line(tr("Callback: %1").arg(html(port.callback)));
    switch (port.nameOrigin) {
    case NameOrigin::Literal:
        line(tr("Name written as a literal"));
        break;
    case NameOrigin::Member:
        line(tr("Name taken from a member variable"));
        break;
    case NameOrigin::Local:
        line(tr("Name taken from a local variable"));
        break;
    case NameOrigin::Parameter:
        line(tr("Name is the default of parameter '%1'").arg(html(port.parameter)));
        break;
    case NameOrigin::Expression:
        line(tr("Name could not be resolved statically: %1").arg(html(port.nameExpression)));
        break;
    }
    if (!port.guard.isEmpty())
        line(tr("Exists only if: %1").arg(html(port.guard)));
    if (!port.via.isEmpty())
        line(tr("Created through: %1").arg(html(port.via)));
    if (!port.viaEvidence.isEmpty()) {
        QStringList steps;
        for (const Evidence &e : port.viaEvidence)
            steps << html(location(e));
        line(tr("Reached from the node through %1").arg(steps.join(QStringLiteral(" → "))));
    }
    if (port.inherited)
        line(tr("Declared in a base class"));
    if (port.evidence.isValid())
        line(tr("Created at %1").arg(html(location(port.evidence))));
    return tip;
}

} // namespace rosarch
