#include "widgets/launchtreetext.h"
#include "core/atomicnode.h"

#include <algorithm>

namespace rosarch {

namespace {

QString location(const Evidence &e)
{
    return e.line > 0 ? QStringLiteral("%1:%2").arg(e.file).arg(e.line) : e.file;
}

QString html(const QString &s)
{
    return s.toHtmlEscaped();
}

QString pairs(const QList<QPair<QString, QString>> &list, const QString &separator)
{
    QStringList out;
    for (const auto &p : list)
        out << (p.first.isEmpty() ? p.second : p.first + separator + p.second);
    return out.join(QStringLiteral(", "));
}

/// One `<li>` list of at most `limit` entries, so a node with a hundred parameters keeps a
/// tooltip that fits on the screen.
QString htmlList(const QStringList &entries, int limit = 12)
{
    QString out = QStringLiteral("<ul style=\"margin:0 0 0 -24px\">");
    for (int i = 0; i < entries.size() && i < limit; ++i)
        out += QStringLiteral("<li>%1</li>").arg(entries[i]);
    if (entries.size() > limit)
        out += QStringLiteral("<li>…</li>");
    return out + QStringLiteral("</ul>");
}

QStringList unresolvedEntries(const QList<Unresolved> &list)
{
    QStringList out;
    for (const Unresolved &u : list) {
        QString entry =
            QStringLiteral("%1 <code>%2</code>")
                .arg(html(LaunchTreeText::unresolvedKindLabel(u.kind)), html(u.expression));
        if (!u.guess.isEmpty())
            entry += QStringLiteral(" → ") + html(u.guess);
        out << entry;
    }
    return out;
}

} // namespace

QString LaunchTreeText::unresolvedKindLabel(const QString &kind)
{
    if (kind == QLatin1String("substitution"))
        return tr("Substitution");
    if (kind == QLatin1String("condition"))
        return tr("Condition");
    if (kind == QLatin1String("include"))
        return tr("Include");
    if (kind == QLatin1String("opaque-function"))
        return tr("Opaque function");
    if (kind == QLatin1String("argument"))
        return tr("Argument");
    if (kind == QLatin1String("eval"))
        return tr("Python expression");
    if (kind == QLatin1String("eval-too-deep"))
        return tr("Python expression nested too deeply to evaluate");
    return kind.isEmpty() ? tr("Expression") : kind;
}

QString LaunchTreeText::nodeExecutable(const NodeInstance &node)
{
    if (node.nodeKind == QLatin1String("composable") || node.package.isEmpty())
        return node.execName;
    if (node.execName.isEmpty())
        return node.package;
    return node.package + QLatin1Char('/') + node.execName;
}

QString LaunchTreeText::fullyQualifiedName(const NodeInstance &node)
{
    QString ns = node.nameSpace.isEmpty() ? QStringLiteral("/") : node.nameSpace;
    if (!ns.endsWith(QLatin1Char('/')))
        ns += QLatin1Char('/');
    return ns + node.nodeName;
}

QString LaunchTreeText::nodeDetails(const NodeInstance &node, int composableCount)
{
    QStringList parts;
    if (!node.parentNode.isEmpty())
        parts << tr("child node, created in code");
    if (!node.condition.isEmpty())
        parts << tr("if: %1").arg(node.condition);
    if (composableCount > 0)
        parts << (composableCount == 1 ? tr("container of 1 component")
                                       : tr("container of %1 components").arg(composableCount));
    if (node.lifecycle)
        parts << tr("lifecycle");
    if (!node.remaps.isEmpty())
        parts << tr("remap: %1").arg(pairs(node.remaps, QStringLiteral("→")));
    if (!node.parameters.isEmpty())
        parts << tr("param: %1").arg(pairs(node.parameters, QStringLiteral("=")));
    if (!node.unresolved.isEmpty())
        parts << (node.unresolved.size() == 1 ? tr("1 unresolved")
                                              : tr("%1 unresolved").arg(node.unresolved.size()));
    return parts.join(QStringLiteral(" · "));
}

QString LaunchTreeText::launchFileDetails(const LaunchFileInstance &instance)
{
    QStringList parts;
    if (instance.external)
        parts << tr("external");
    if (!instance.condition.isEmpty())
        parts << tr("if: %1").arg(instance.condition);
    if (!instance.package.isEmpty())
        parts << instance.package;
    if (!instance.nodes.isEmpty())
        parts << (instance.nodes.size() == 1 ? tr("1 node")
                                             : tr("%1 nodes").arg(instance.nodes.size()));
    if (!instance.includedLaunchFiles.isEmpty())
        parts << (instance.includedLaunchFiles.size() == 1
                      ? tr("1 include")
                      : tr("%1 includes").arg(instance.includedLaunchFiles.size()));
    if (!instance.arguments.isEmpty())
        parts << pairs(instance.arguments, QStringLiteral(":="));
    return parts.join(QStringLiteral(" · "));
}

QString LaunchTreeText::unresolvedDetails(const Unresolved &unresolved)
{
    const QString kind = unresolvedKindLabel(unresolved.kind);
    return unresolved.guess.isEmpty()
               ? tr("unresolved (%1)").arg(kind)
               : tr("unresolved (%1) · guess: %2").arg(kind, unresolved.guess);
}

QString LaunchTreeText::nodeToolTip(const NodeInstance &node, const AtomicNode *atomicNode,
                                    bool inWorkspace, bool parentActive)
{
    const QString what = node.nodeKind == QLatin1String("composable") ? tr("Composable node")
                         : node.lifecycle                             ? tr("Lifecycle node")
                                                                      : tr("Node");
    QString tip = QStringLiteral("<b>%1</b> %2").arg(what, html(fullyQualifiedName(node)));
    const auto line = [&tip](const QString &text) { tip += QStringLiteral("<br/>") + text; };
    if (node.guessedNamespace && node.guessedName)
        line(tr("Namespace and name: guesses, built from a launch value nobody sets; so are the "
                "relative and private names of its ports"));
    else if (node.guessedNamespace)
        line(tr("Namespace: a guess, built from a launch value nobody sets; so are the relative "
                "and private names of its ports"));
    else if (node.guessedName)
        line(tr("Name: a guess, built from a launch value nobody sets; so are the private names "
                "of its ports"));
    if (!node.parentNode.isEmpty())
        line(tr("Child node: created in code at %1; it runs in the process of the node that "
                "creates it, with that launch line's remaps and parameter files")
                 .arg(html(location(node.evidence))));
    if (!node.package.isEmpty())
        line(tr("Package: %1").arg(html(node.package)));
    if (!node.execName.isEmpty())
        line(
            (node.nodeKind == QLatin1String("composable") ? tr("Plugin: %1") : tr("Executable: %1"))
                .arg(html(node.execName)));
    if (!node.className.isEmpty()) {
        QString cls = tr("Class: %1").arg(html(node.className));
        if (atomicNode && atomicNode->evidence.isValid())
            cls += QStringLiteral(" (%1)").arg(html(location(atomicNode->evidence)));
        line(cls);
    } else {
        line(inWorkspace ? tr("Class: not found in the workspace")
                         : tr("Class: not analysed; package %1 is not in the workspace")
                               .arg(html(node.package)));
    }
    if (!node.container.isEmpty())
        line(tr("Loaded into container: %1").arg(html(node.container)));
    const bool undecided =
        std::any_of(node.unresolved.cbegin(), node.unresolved.cend(),
                    [](const Unresolved &u) { return u.kind == QLatin1String("condition"); });
    if (!node.condition.isEmpty())
        line(!node.active
                 ? tr("Condition: %1 (<b>false</b>: not started)").arg(html(node.condition))
             : undecided
                 ? tr("Condition: %1 (undecidable: kept, as if true)").arg(html(node.condition))
                 : tr("Condition: %1 (true)").arg(html(node.condition)));
    if (node.active && !parentActive)
        line(tr("<b>Inactive:</b> the launch file that declares it is not included"));
    if (!node.remaps.isEmpty()) {
        QStringList entries;
        for (qsizetype i = 0; i < node.remaps.size(); ++i) {
            const auto &[from, to] = node.remaps.at(i);
            entries << (node.guessedRemaps.contains(int(i))
                            ? tr("%1 → %2 (a guess: built from a launch value nobody sets)")
                                  .arg(html(from), html(to))
                            : QStringLiteral("%1 → %2").arg(html(from), html(to)));
        }
        line(tr("Remappings:") + htmlList(entries));
    }
    if (!node.parameters.isEmpty()) {
        QStringList entries;
        for (const auto &p : node.parameters)
            entries << (p.first.isEmpty()
                            ? tr("file %1").arg(html(p.second))
                            : QStringLiteral("%1 = %2").arg(html(p.first), html(p.second)));
        line(tr("Parameters given:") + htmlList(entries));
    }
    if (!node.plugins.isEmpty()) {
        QStringList entries;
        for (const ParameterSetting &p : node.plugins)
            entries << QStringLiteral("%1: %2").arg(html(p.name), html(p.value));
        line(tr("Loads plugins:") + htmlList(entries));
    }
    if (!node.effectiveParameters.isEmpty())
        line(tr("Parameters in effect: %n (listed under the node, each with its source)", nullptr,
                int(node.effectiveParameters.size())));
    if (!node.unresolved.isEmpty())
        line(tr("Not resolved statically:") + htmlList(unresolvedEntries(node.unresolved)));
    if (node.evidence.isValid())
        line(tr("Declared at %1").arg(html(location(node.evidence))));
    return tip;
}

QString LaunchTreeText::launchFileToolTip(const LaunchFileInstance &instance,
                                          const QList<Unresolved> &attributeUnresolved,
                                          bool parentActive)
{
    const bool executable = instance.format == QLatin1String("executable");
    const QString what = executable                    ? tr("Executable building its own nodes")
                         : instance.parentId.isEmpty() ? tr("Launch file")
                         : instance.external           ? tr("External include")
                                                       : tr("Included launch file");
    QString tip = QStringLiteral("<b>%1</b> %2").arg(what, html(instance.type));
    const auto line = [&tip](const QString &text) { tip += QStringLiteral("<br/>") + text; };
    if (!instance.file.isEmpty())
        line(tr("File: %1").arg(html(instance.file)));
    if (instance.external)
        line(tr("Package %1 is not in the workspace; its nodes are not analysed.")
                 .arg(html(instance.package)));
    else if (!instance.package.isEmpty())
        line(tr("Package: %1").arg(html(instance.package)));
    if (!instance.condition.isEmpty())
        line(instance.active
                 ? tr("Condition: %1 (true)").arg(html(instance.condition))
                 : tr("Condition: %1 (<b>false</b>: not included)").arg(html(instance.condition)));
    if (instance.active && !parentActive)
        line(tr("<b>Inactive:</b> the launch file that includes it is not included"));
    if (!instance.arguments.isEmpty()) {
        QStringList entries;
        for (const auto &a : instance.arguments)
            entries << QStringLiteral("%1 := %2").arg(html(a.first), html(a.second));
        line(tr("Launch arguments:") + htmlList(entries));
    }
    if (!attributeUnresolved.isEmpty())
        line(tr("Not resolved statically:") + htmlList(unresolvedEntries(attributeUnresolved)));
    if (instance.evidence.isValid())
        line((instance.parentId.isEmpty() ? tr("At %1") : tr("Included at %1"))
                 .arg(html(location(instance.evidence))));
    return tip;
}

QString LaunchTreeText::namespaceToolTip(const QString &nameSpace,
                                         const LaunchFileInstance &instance, int itemCount)
{
    QString tip = tr("<b>Namespace</b> %1").arg(html(nameSpace));
    tip += QStringLiteral("<br/>") + tr("Pushed in %1").arg(html(instance.type));
    tip += QStringLiteral("<br/>") + (itemCount == 1
                                          ? tr("1 instance inside this scope")
                                          : tr("%1 instances inside this scope").arg(itemCount));
    return tip;
}

QString LaunchTreeText::unresolvedToolTip(const Unresolved &unresolved)
{
    QString tip =
        tr("<b>Not resolved statically:</b> %1").arg(html(unresolvedKindLabel(unresolved.kind)));
    tip += QStringLiteral("<br/><code>%1</code>").arg(html(unresolved.expression));
    if (!unresolved.guess.isEmpty())
        tip += QStringLiteral("<br/>") +
               tr("The analysis continued with: %1").arg(html(unresolved.guess));
    if (unresolved.evidence.isValid())
        tip += QStringLiteral("<br/>") + tr("At %1").arg(html(location(unresolved.evidence)));
    return tip;
}

QString LaunchTreeText::parameterDetails(const ParameterSetting &parameter)
{
    QString source;
    if (parameter.source == QLatin1String("default"))
        source = tr("default in code");
    else if (parameter.source == QLatin1String("file"))
        source = QStringLiteral("%1:%2")
                     .arg(parameter.evidence.file.section(QLatin1Char('/'), -1))
                     .arg(parameter.evidence.line);
    else
        source = tr("launch file");
    return QStringLiteral("%1 · %2").arg(parameter.value.simplified(), source);
}

QString LaunchTreeText::parameterToolTip(const ParameterSetting &parameter)
{
    QString tip =
        QStringLiteral("<b>%1</b> = %2<br>").arg(html(parameter.name), html(parameter.value));
    if (parameter.source == QLatin1String("default"))
        tip += tr("No launch value or parameter file sets it: the default declared in code, "
                  "at %1.")
                   .arg(html(location(parameter.evidence)));
    else if (parameter.source == QLatin1String("file"))
        tip += tr("From the parameter file %1.").arg(html(location(parameter.evidence)));
    else
        tip += tr("Set by the launch file at %1.").arg(html(location(parameter.evidence)));
    return tip;
}

} // namespace rosarch
