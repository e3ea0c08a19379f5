#include "widgets/atomicnodetext.h"
#include "core/rospackage.h"

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

QString AtomicNodeText::nodeToolTip(const AtomicNode &node, const NodeDescription &description,
                                    const QList<const AtomicNode *> &loaded)
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
    if (!node.parameters.isEmpty())
        line(node.parameters.size() == 1
                 ? tr("1 declared parameter")
                 : tr("%1 declared parameters").arg(node.parameters.size()));
    if (description.text.isEmpty())
        line(description.source == NodeDescription::Source::Correction
                 ? tr("No description (a person removed it)")
                 : tr("No description in the code"));
    else
        line(tr("Description (%1): %2").arg(description.sourceText(), html(description.text)));
    if (!loaded.isEmpty()) {
        // what the host serves through its plugins: a newcomer's "which actions does it serve"
        constexpr qsizetype kMaxShown = 12;
        QStringList plugins;
        for (const AtomicNode *plugin : loaded.first(std::min(loaded.size(), kMaxShown))) {
            QStringList served;
            for (const Port &p : plugin->ports)
                if (p.kind == PortKind::ActionServer || p.kind == PortKind::ServiceServer)
                    served << (p.kind == PortKind::ActionServer ? tr("action %1")
                                                                : tr("service %1"))
                                  .arg(html(p.name.isEmpty() ? p.nameExpression : p.name));
            plugins << (served.isEmpty()
                            ? html(plugin->className)
                            : tr("%1 (serves %2)")
                                  .arg(html(plugin->className), served.join(QStringLiteral(", "))));
        }
        if (loaded.size() > kMaxShown)
            plugins << tr("%n more", nullptr, int(loaded.size() - kMaxShown));
        line(tr("Loads, where it is launched: %1").arg(plugins.join(QStringLiteral("; "))));
    }
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

QString AtomicNodeText::parametersDetails(const AtomicNode &node)
{
    QString details = tr("%n declared", nullptr, int(node.parameters.size()));
    if (node.acceptsUndeclared)
        details += QStringLiteral(" · ") + tr("takes any parameter");
    return details;
}

QString AtomicNodeText::parametersToolTip(const AtomicNode &node)
{
    QString tip = tr("<b>Parameters</b> %1 declares: name, type, default, and the read-only flag "
                     "and range its descriptor sets. An instance's values in effect show in the "
                     "launch tree and the Parameters panel.")
                      .arg(html(node.className));
    if (node.acceptsUndeclared)
        tip += QStringLiteral("<br/>") +
               tr("It takes any parameter (allow_undeclared_parameters or "
                  "automatically_declare_parameters_from_overrides): no value given to it is "
                  "undeclared.");
    return tip;
}

QString AtomicNodeText::parameterDetails(const ParameterDeclaration &parameter)
{
    QStringList parts;
    if (parameter.hasDefault)
        parts << tr("default: %1").arg(parameter.defaultValue);
    else
        parts << tr("no default");
    if (parameter.readOnly)
        parts << tr("read-only");
    if (parameter.dynamicTyping)
        parts << tr("any type");
    if (!parameter.range.isEmpty())
        parts << tr("range: %1").arg(parameter.range);
    if (!parameter.guard.isEmpty())
        parts << tr("guard: %1").arg(parameter.guard);
    if (parameter.inherited)
        parts << tr("inherited");
    return parts.join(QStringLiteral(" · "));
}

QString AtomicNodeText::parameterToolTip(const AtomicNode &node,
                                         const ParameterDeclaration &parameter)
{
    QString tip = tr("<b>Parameter</b> %1").arg(html(parameter.name));
    const auto line = [&tip](const QString &text) { tip += QStringLiteral("<br/>") + text; };
    line(tr("Declared by %1").arg(html(node.className)));
    if (!parameter.nameExpression.isEmpty())
        line(tr("Name as written: %1").arg(html(parameter.nameExpression)));
    if (parameter.name.contains(QLatin1String("{plugin}")))
        line(tr("{plugin} is the name the plugin is loaded under"));
    line(parameter.type.isEmpty() ? tr("Type: not fixed by the declaration")
                                  : tr("Type: %1").arg(html(parameter.type)));
    if (parameter.dynamicTyping)
        line(tr("Its descriptor allows a value of any type"));
    line(parameter.hasDefault ? tr("Default: %1").arg(html(parameter.defaultValue))
                              : tr("No default: an instance must be given a value"));
    if (parameter.readOnly)
        line(tr("Read-only: set at start, never changed while the node runs"));
    if (!parameter.range.isEmpty())
        line(tr("Range: %1").arg(html(parameter.range)));
    line(parameter.description.isEmpty() ? tr("No description in the code")
                                         : tr("Description: %1").arg(html(parameter.description)));
    if (!parameter.guard.isEmpty())
        line(tr("Declared only if: %1").arg(html(parameter.guard)));
    if (!parameter.via.isEmpty())
        line(tr("Declared through: %1").arg(html(parameter.via)));
    if (parameter.inherited)
        line(tr("Declared by a base class or helper code"));
    if (parameter.evidence.isValid())
        line(tr("Declared at %1").arg(html(location(parameter.evidence))));
    return tip;
}

} // namespace rosarch
