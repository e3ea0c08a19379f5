#include "core/parameterview.h"

#include "core/port.h"

#include <QRegularExpression>

#include <algorithm>

namespace rosarch {

QStringList parameterListItems(const QString &value)
{
    const QString list = value.trimmed();
    if (!list.startsWith(u'[') || !list.endsWith(u']'))
        return {};
    QStringList out;
    for (QString item : list.mid(1, list.size() - 2).split(u',')) {
        item = item.trimmed();
        if (item.size() >= 2 && (item.front() == u'\'' || item.front() == u'"') &&
            item.back() == item.front()) // `['a', 'b']`: the items, not their quotes
            item = item.mid(1, item.size() - 2);
        out << item;
    }
    return out;
}

namespace {

/// A name built from the node's own name (`get_name() + ".verbose"`) as the instance has it.
QString withNodeName(const QString &name, const NodeInstance &n)
{
    if (!name.contains(QLatin1String(kNodeNamePlaceholder)) || n.nodeName.isEmpty() ||
        n.nodeName.contains(u'{'))
        return name;
    return QString(name).replace(QLatin1String(kNodeNamePlaceholder), n.nodeName);
}

} // namespace

ParameterView::ParameterView(const AtomicNodeList &nodes) : m_nodes(nodes)
{
    for (const AtomicNode &n : nodes.nodes)
        if (n.isPlugin())
            m_plugins.insert(n.qualifiedName, &n);
    for (const ParameterDeclaration &h : nodes.helperParameters) {
        if (h.name.contains(u'{'))
            m_helperPatterns.append(&h);
        else if (!m_helperNames.contains(h.name))
            m_helperNames.insert(h.name, &h);
    }
}

const ParameterDeclaration *ParameterView::helperDeclaring(const QString &key) const
{
    if (const ParameterDeclaration *h = m_helperNames.value(key))
        return h;
    for (const ParameterDeclaration *h : m_helperPatterns)
        if (parameterNameMatches(h->name, key))
            return h;
    return nullptr;
}

const AtomicNode *ParameterView::pluginClass(const QString &written) const
{
    QString name = written.trimmed();
    name.replace(u'/', QLatin1String("::")); // the older pluginlib spelling pkg/Class
    if (name.startsWith(QLatin1String("::")))
        name = name.mid(2);
    return m_plugins.value(name);
}

QList<QPair<QString, const AtomicNode *>>
ParameterView::loadedPlugins(const NodeInstance &n, QStringList *unknownPlugins) const
{
    QList<QPair<QString, const AtomicNode *>> out;
    for (const ParameterSetting &plugin : n.plugins) {
        if (const AtomicNode *cls = pluginClass(plugin.value))
            out.append({plugin.name, cls});
        else if (unknownPlugins)
            unknownPlugins->append(plugin.name);
    }
    // A plugin that loads plugins of its own by class name from a list of its parameters
    // (navigation2 MPPI's `FollowPath.critics: [GoalCritic, ...]`, each critic declaring
    // under `FollowPath.GoalCritic`): an item that names exactly one plugin class of the
    // loading plugin's package is that plugin, loaded under the item's name.
    const qsizetype loaders = out.size();
    for (qsizetype i = 0; i < loaders; ++i) {
        const QString prefix = out.at(i).first + QLatin1Char('.');
        const QString package = out.at(i).second->packageName;
        for (const ParameterSetting &s : n.effectiveParameters) {
            if (!s.name.startsWith(prefix) || s.name.indexOf(u'.', prefix.size()) >= 0)
                continue;
            for (const QString &item : parameterListItems(s.value)) {
                const AtomicNode *found = nullptr;
                int count = 0;
                for (const AtomicNode *p : m_plugins)
                    if (p->packageName == package && p->className == item) {
                        found = p;
                        ++count;
                    }
                if (count == 1 && found != out.at(i).second)
                    out.append({prefix + item, found});
            }
        }
    }
    return out;
}

QList<ParameterDeclaration> ParameterView::declarationsOf(const NodeInstance &n,
                                                          QStringList *unknownPlugins) const
{
    QList<ParameterDeclaration> out;
    if (const AtomicNode *cls = m_nodes.node(n.classId))
        out = cls->parameters;
    for (const auto &[name, cls] : loadedPlugins(n, unknownPlugins))
        for (ParameterDeclaration d : cls->parameters) {
            d.name = parameterNameFor(d.name, name);
            out.append(d);
        }
    for (ParameterDeclaration &d : out)
        d.name = withNodeName(d.name, n);
    // A name with a part that another parameter's list value decides
    // (generate_parameter_library's `gains.{joints}.p`) stands for one name per item.
    QList<ParameterDeclaration> expanded;
    for (const ParameterDeclaration &d : std::as_const(out)) {
        static const QRegularExpression part(QStringLiteral("\\{([A-Za-z0-9_.]+)\\}"));
        const QRegularExpressionMatch m = part.match(d.name);
        const ParameterSetting *list = nullptr;
        if (m.hasMatch())
            for (const ParameterSetting &s : n.effectiveParameters)
                if (s.name == m.captured(1) && s.value.startsWith(u'['))
                    list = &s;
        if (!list) {
            expanded.append(d);
            continue;
        }
        for (const QString &item : parameterListItems(list->value)) {
            ParameterDeclaration one = d;
            one.name.replace(m.capturedStart(), m.capturedLength(), item);
            if (!item.isEmpty())
                expanded.append(one);
        }
    }
    return expanded;
}

InstanceParameter ParameterView::declared(const ParameterDeclaration &d, const QString &plugin)
{
    InstanceParameter p;
    p.name = d.name;
    p.plugin = plugin;
    p.declared = true;
    p.type = d.type;
    p.defaultValue = d.defaultValue;
    p.hasDefault = d.hasDefault;
    p.description = d.description;
    p.readOnly = d.readOnly;
    p.range = d.range;
    p.declaration = d.evidence;
    if (d.hasDefault) {
        p.value = d.defaultValue;
        p.source = QStringLiteral("default");
    }
    return p;
}

QList<InstanceParameter> ParameterView::of(const NodeInstance &n) const
{
    QList<InstanceParameter> out;
    QHash<QString, qsizetype> at;
    const AtomicNode *cls = m_nodes.node(n.classId);
    auto declare = [&](ParameterDeclaration d, const QString &plugin) {
        d.name = withNodeName(d.name, n);
        if (at.contains(d.name))
            return;
        const InstanceParameter p = declared(d, plugin);
        at.insert(p.name, out.size());
        out.append(p);
    };
    if (cls)
        for (const ParameterDeclaration &d : cls->parameters)
            declare(d, QString());
    for (const auto &[name, pc] : loadedPlugins(n))
        for (ParameterDeclaration d : pc->parameters) {
            d.name = parameterNameFor(d.name, name);
            declare(d, name);
        }
    for (const ParameterSetting &s : n.effectiveParameters) {
        if (s.source == QLatin1String("default"))
            continue; // the class's own default, already there
        qsizetype i = at.value(s.name, -1);
        if (i < 0) {
            // a declared name with a run-time part (`{source}.topic`) takes the value
            for (qsizetype k = 0; k < out.size() && i < 0; ++k)
                if (out.at(k).name.contains(u'{') && parameterNameMatches(out.at(k).name, s.name))
                    i = k;
            InstanceParameter p = i >= 0 ? out.at(i) : InstanceParameter{};
            p.name = s.name;
            if (i < 0 && isBuiltinParameter(s.name)) { // rclcpp and rclpy declare it for any node
                p.declared = true;
                p.description = QStringLiteral("declared by ROS 2 for every node");
            } else if (const ParameterDeclaration *h = i < 0 ? helperDeclaring(s.name) : nullptr) {
                p.declared = true;
                p.type = h->type;
                p.declaration = h->evidence;
                p.description = QStringLiteral("declared by helper code (%1)").arg(h->via);
            }
            at.insert(p.name, out.size());
            out.append(p);
            i = out.size() - 1;
        }
        InstanceParameter &p = out[i];
        p.value = s.value;
        p.hasValue = true;
        p.source = s.source;
        p.file = s.file;
        p.valueEvidence = s.evidence;
    }
    // names with run-time parts that took a value are shown by the values they took
    out.erase(std::remove_if(out.begin(), out.end(),
                             [](const InstanceParameter &p) {
                                 return !p.hasValue && parameterNameIsPattern(p.name);
                             }),
              out.end());
    std::sort(out.begin(), out.end(), [](const InstanceParameter &a, const InstanceParameter &b) {
        return a.name < b.name;
    });
    return out;
}

} // namespace rosarch
