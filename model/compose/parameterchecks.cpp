#include "compose/parameterchecks.h"
#include "compose/checkscope.h"
#include "core/declaringcall.h"
#include "core/editdistance.h"
#include "core/parameterview.h"
#include "core/rosnames.h"

#include <QRegularExpression>
#include <QSet>

namespace rosarch {

namespace {

/// Whether the class's declarations are all in the workspace: every base is a ROS node base, a
/// standard-library helper, or a node class the analysis read.
bool basesKnown(const AtomicNode &cls, const AtomicNodeList &nodes)
{
    static const QStringList rosBases{QStringLiteral("rclcpp::Node"),
                                      QStringLiteral("Node"),
                                      QStringLiteral("rclcpp_lifecycle::LifecycleNode"),
                                      QStringLiteral("LifecycleNode"),
                                      QStringLiteral("rclpy.node.Node"),
                                      QStringLiteral("rclpy.lifecycle.Node"),
                                      QStringLiteral("rclpy.lifecycle.LifecycleNode")};
    for (QString base : cls.baseClasses) {
        base = base.simplified().remove(u' ');
        base.remove(QRegularExpression(QStringLiteral("^(public|protected|private|virtual)")));
        if (base.startsWith(QLatin1String("::")))
            base = base.mid(2);
        if (rosBases.contains(base) || base.startsWith(QLatin1String("std::")))
            continue;
        const QString bare = base.section(u'<', 0, 0);
        bool found = false;
        for (const AtomicNode &n : nodes.nodes)
            found = found || n.qualifiedName == bare || n.className == bare ||
                    n.qualifiedName.endsWith(QLatin1String("::") + bare) ||
                    n.qualifiedName.endsWith(QLatin1Char('.') + bare);
        if (!found)
            return false;
    }
    return true;
}

/// Whether every parameter file the instance is given was read: each gave it a value (a file
/// that gives it none, or whose path rests on an unknown value, leaves that open).
bool filesRead(const NodeInstance &n)
{
    for (const auto &[name, value] : n.parameters) {
        if (!name.isEmpty())
            continue;
        QString tail = value.section(u')', -1).trimmed();
        if (tail.isEmpty() || tail.contains(u'$') || tail.contains(u'('))
            return false;
        if (!tail.startsWith(u'/'))
            tail.prepend(u'/');
        const bool read =
            std::any_of(n.effectiveParameters.begin(), n.effectiveParameters.end(),
                        [&](const ParameterSetting &s) { return ('/' + s.file).endsWith(tail); });
        if (!read)
            return false;
    }
    return true;
}

bool outsideRange(const QString &range, const QString &value)
{
    if (range.startsWith(QLatin1String("one of ["))) { // generate_parameter_library's one_of<>
        QStringList allowed = range.mid(8, range.size() - 9).split(u',');
        for (QString &a : allowed)
            a = a.trimmed();
        return !allowed.isEmpty() && !allowed.contains(value.trimmed());
    }
    static const QRegularExpression bounds(
        QStringLiteral("^\\[\\s*([-+0-9.eE]+)\\s*,\\s*([-+0-9.eE]+)\\s*\\]"));
    const QRegularExpressionMatch m = bounds.match(range);
    bool okFrom = false, okTo = false, okValue = false;
    const double v = value.trimmed().toDouble(&okValue);
    if (!m.hasMatch() || !okValue)
        return false;
    const double from = m.captured(1).toDouble(&okFrom);
    const double to = m.captured(2).toDouble(&okTo);
    return okFrom && okTo && (v < from || v > to);
}

/// Whether the declarations name the key's namespace (`FollowPath.` of
/// `FollowPath.max_vel_x`): a plugin a plugin loads (a critic) declares its own, and a key
/// under a namespace nothing declares is left unjudged.
bool namespaceKnown(const QString &key, const QList<ParameterDeclaration> &declared)
{
    const qsizetype dot = key.lastIndexOf(u'.');
    if (dot < 0)
        return true;
    const QString ns = key.left(dot);
    // only a namespace written out counts: one with run-time parts (`{name_}` of a critic a
    // plugin loads) does not say which of its keys exist
    for (const ParameterDeclaration &d : declared) {
        const qsizetype end = d.name.lastIndexOf(u'.');
        if (end > 0 && d.name.left(end) == ns)
            return true;
    }
    return false;
}

QString nearest(const QString &key, const QList<ParameterDeclaration> &declared)
{
    QString best;
    int bestDistance = std::max(2, int(key.size()) / 4) + 1;
    for (const ParameterDeclaration &d : declared) {
        if (d.name.contains(u'{'))
            continue;
        const int distance = editDistance(key, d.name, bestDistance);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = d.name;
        }
    }
    return best;
}

QString where(const Evidence &e)
{
    return QStringLiteral("%1:%2").arg(e.file).arg(e.line);
}

} // namespace

void ParameterChecks::run(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                          QList<Diagnostic> *out)
{
    const QSet<QString> systems = CheckScope::judgedInstances(launch);
    const ParameterView view(nodes);
    QSet<QString> reported; // code, place, name: one finding for a line many instances read
    auto report = [&](const QString &code, const QString &name, const QString &message,
                      const Evidence &at, const QList<Diagnostic::Related> &related) {
        const QString key = code + QChar(0) + where(at) + QChar(0) + name;
        if (reported.contains(key))
            return;
        reported.insert(key);
        out->append({Diagnostic::Severity::Warning, code, message, at, related});
    };
    struct Instance
    {
        const NodeInstance *n;
        const AtomicNode *cls;
        QList<ParameterDeclaration> declared;
        QStringList unknownPlugins;
        bool judged;
    };
    QSet<QString> startedByRun; // the launch-file instances standing for an executable
    for (const LaunchFileInstance &f : launch.instances)
        if (f.format == QLatin1String("executable"))
            startedByRun.insert(f.id);
    QList<Instance> instances;
    for (const NodeInstance &n : launch.nodes) {
        if (!n.active || !systems.contains(n.launchFileId))
            continue;
        Instance i{&n, nodes.node(n.classId), {}, {}, false};
        if (i.cls && n.interfaceModel.isEmpty()) {
            i.declared = view.declarationsOf(n, &i.unknownPlugins);
            i.judged = !i.cls->acceptsUndeclared && !i.cls->parameters.isEmpty() &&
                       basesKnown(*i.cls, nodes) &&
                       std::none_of(i.declared.begin(), i.declared.end(),
                                    [](const ParameterDeclaration &d) {
                                        return parameterNameIsOpen(d.name);
                                    });
        }
        instances.append(i);
    }
    // A value the instance's declarations leave undeclared (with no class, or a class not
    // judged, nothing is).
    auto undeclared = [&](const Instance &i, const ParameterSetting &s) {
        if (!i.judged || isBuiltinParameter(s.name) ||
            i.unknownPlugins.contains(s.name.section(u'.', 0, 0)) ||
            s.name.endsWith(QLatin1String(".plugin")) || !namespaceKnown(s.name, i.declared))
            return false;
        const auto matches = [&](const ParameterDeclaration &d) {
            return parameterNameMatches(d.name, s.name);
        };
        return std::none_of(i.declared.begin(), i.declared.end(), matches) &&
               !view.helperDeclaring(s.name);
    };
    // A wildcard key (`/**`) of a file given to several nodes is meant for any of them: it is
    // undeclared only when every node it reaches leaves it undeclared.
    QHash<QString, bool> wildcardTaken;
    for (const Instance &i : std::as_const(instances))
        for (const ParameterSetting &s : i.n->effectiveParameters)
            if (s.wildcard) {
                bool &taken = wildcardTaken[where(s.evidence) + QChar(0) + s.name];
                taken = taken || !undeclared(i, s);
            }
    for (const Instance &i : std::as_const(instances)) {
        if (!i.judged)
            continue;
        const NodeInstance &n = *i.n;
        const AtomicNode *cls = i.cls;
        const QList<ParameterDeclaration> &declared = i.declared;
        const QString node = RosNames::fullyQualified(n.nameSpace, n.nodeName);
        QSet<QString> given;
        for (const ParameterSetting &s : n.effectiveParameters) {
            if (s.source == QLatin1String("default"))
                continue;
            given.insert(s.name);
            const ParameterDeclaration *d = nullptr;
            for (const ParameterDeclaration &c : declared)
                if (parameterNameMatches(c.name, s.name) && (!d || !c.name.contains(u'{')))
                    d = &c;
            if (!d) {
                if (!undeclared(i, s) ||
                    (s.wildcard && wildcardTaken.value(where(s.evidence) + QChar(0) + s.name)))
                    continue;
                const QString guess = nearest(s.name, declared);
                report(QStringLiteral("parameter-undeclared"), s.name,
                       QStringLiteral("Node %1 (%2) is given parameter '%3', which it does not "
                                      "declare: ROS 2 ignores the value.%4 Fix the key, or remove "
                                      "it.")
                           .arg(node, cls->className, s.name,
                                guess.isEmpty() ? QString()
                                                : QStringLiteral(" Did you mean '%1'?").arg(guess)),
                       s.evidence, {{QStringLiteral("the class"), cls->evidence}});
                continue;
            }
            // a launch value that is still an expression (an include's argument the analysis
            // could not evaluate) has no type yet
            const bool typed = !d->dynamicTyping && isStandardDeclaringCall(d->via) &&
                               !(s.source == QLatin1String("launch") && s.value.contains(u'('));
            if (typed && !parameterTypeAccepts(d->type, s.type)) {
                report(QStringLiteral("parameter-type"), s.name,
                       QStringLiteral("Node %1 is given %2 '%3' for parameter '%4', which is "
                                      "declared as %5: the node fails to set it. Write the value "
                                      "as %5.")
                           .arg(node, s.type, s.value, s.name, d->type),
                       s.evidence, {{QStringLiteral("the declaration"), d->evidence}});
            } else if (!d->range.isEmpty() && outsideRange(d->range, s.value)) {
                report(QStringLiteral("parameter-range"), s.name,
                       QStringLiteral("Node %1 is given %2 for parameter '%3', outside its range "
                                      "%4: the node rejects it.")
                           .arg(node, s.value, s.name, d->range),
                       s.evidence, {{QStringLiteral("the declaration"), d->evidence}});
            }
        }
        // `ros2 run` of an executable that builds its own nodes takes its parameters from the
        // command line, which the analysis does not see
        if (!filesRead(n) || !n.unresolved.isEmpty() || startedByRun.contains(n.launchFileId))
            continue;
        for (const ParameterDeclaration &d : declared) {
            // a helper's or a base's declaration may sit in code this node never runs (a
            // strategy chosen at run time, a method only other nodes call)
            if (d.hasDefault || d.name.contains(u'{') || !d.guard.isEmpty() || d.inherited ||
                !isStandardDeclaringCall(d.via) || given.contains(d.name))
                continue;
            report(QStringLiteral("parameter-missing"), d.name + QChar(0) + n.id,
                   QStringLiteral("Node %1 declares parameter '%2' without a default, and "
                                  "nothing sets it: the node cannot read it. Set it in the launch "
                                  "file or a parameter file.")
                       .arg(node, d.name),
                   n.evidence, {{QStringLiteral("the declaration"), d.evidence}});
        }
    }
}

} // namespace rosarch
