#include "site/nodepage.h"

#include <QCoreApplication>
#include <QHash>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::NodePage", text);
}

using SiteHtml::code;
using SiteHtml::escape;
using SiteHtml::link;

QString kindText(PortKind kind)
{
    switch (kind) {
    case PortKind::Publisher:
        return tr("publisher");
    case PortKind::Subscriber:
        return tr("subscriber");
    case PortKind::ServiceServer:
        return tr("service server");
    case PortKind::ServiceClient:
        return tr("service client");
    case PortKind::ActionServer:
        return tr("action server");
    case PortKind::ActionClient:
        return tr("action client");
    }
    return {};
}

class Writer
{
public:
    Writer(const SiteContext &context, const AtomicNode &node)
        : m_context(context), m_model(*context.model), m_node(node),
          m_path(m_model.nodePage(node.id))
    {
    }

    SiteFile page() const
    {
        QString body = about();
        body += ports();
        body += parameters();
        body += instances();
        const QString package = m_model.packagePage(m_node.packageName);
        return SiteHtml::page(m_context, m_path, m_node.className,
                              {{tr("Home"), QStringLiteral("index.html")},
                               {m_node.packageName, package},
                               {m_node.className, m_path}},
                              body);
    }

private:
    QString about() const
    {
        QString out;
        if (!m_node.description.isEmpty())
            out += QStringLiteral("<p class=\"lead\">%1</p>\n").arg(escape(m_node.description));
        out += QStringLiteral("<dl class=\"props\">");
        const auto row = [&out](const QString &term, const QString &html) {
            if (!html.isEmpty())
                out += QStringLiteral("<dt>%1</dt><dd>%2</dd>").arg(escape(term), html);
        };
        row(tr("Class"),
            code(m_node.qualifiedName.isEmpty() ? m_node.className : m_node.qualifiedName) + u' ' +
                SiteHtml::source(m_context, m_path, m_node.evidence));
        row(tr("Package"),
            link(m_path, m_model.packagePage(m_node.packageName), m_node.packageName));
        QStringList kind{m_node.isPlugin()
                             ? tr("pluginlib plugin of %1").arg(m_node.pluginInterface)
                         : m_node.lifecycle ? tr("lifecycle node")
                                            : tr("node")};
        kind << compileTypeName(m_node.compileType);
        if (m_node.isComposable())
            kind << tr("composable");
        row(tr("Kind"), escape(kind.join(QStringLiteral(", "))));
        if (!m_node.nodeName.isEmpty())
            row(tr("Node name in code"), code(m_node.nodeName));
        QStringList runs;
        for (const QString &e : m_node.executables)
            runs << code(e);
        for (const QString &p : m_node.plugins)
            runs << code(p);
        row(tr("Started as"), runs.join(QStringLiteral(", ")));
        QStringList files;
        for (const QString &f : m_node.headerFiles + m_node.sourceFiles)
            files << SiteHtml::source(m_context, m_path, Evidence::startOf(f));
        row(tr("Files"), files.join(QStringLiteral(", ")));
        return out + QStringLiteral("</dl>\n");
    }

    QString ports() const
    {
        QList<QStringList> rows;
        for (const Port &p : m_node.ports) {
            QString name = code(p.name);
            if (!p.isResolved())
                name +=
                    QStringLiteral(" <span class=\"tag\">%1</span>").arg(escape(tr("unresolved")));
            if (!p.parameter.isEmpty())
                name += QStringLiteral(" <span class=\"muted\">%1</span>")
                            .arg(escape(tr("from parameter %1").arg(p.parameter)));
            QString extra;
            if (!p.guard.isEmpty())
                extra += escape(tr("if ")) + code(p.guard);
            if (!p.via.isEmpty())
                extra += (extra.isEmpty() ? QString() : QStringLiteral("; ")) + escape(tr("via ")) +
                         code(p.via);
            rows << QStringList{escape(kindText(p.kind)),
                                name,
                                code(p.type),
                                p.qos.isEmpty() ? QString() : code(p.qos),
                                p.callback.isEmpty() ? QString() : code(p.callback),
                                extra,
                                SiteHtml::source(m_context, m_path, p.evidence)};
        }
        QString out =
            QStringLiteral("<section aria-labelledby=\"ports\">\n<h2 id=\"ports\">%1</h2>\n")
                .arg(tr("Ports"));
        if (rows.isEmpty())
            return out + QStringLiteral("<p>%1</p>\n</section>\n")
                             .arg(escape(tr("The analysis found no port in this class.")));
        return out +
               SiteHtml::table(tr("Ports of %1 as written in the code").arg(m_node.className),
                               {tr("Kind"), tr("Name"), tr("Type"), tr("QoS"), tr("Callback"),
                                tr("Condition"), tr("Source")},
                               rows) +
               QStringLiteral("</section>\n");
    }

    QString parameters() const
    {
        QString out =
            QStringLiteral(
                "<section aria-labelledby=\"parameters\">\n<h2 id=\"parameters\">%1</h2>\n")
                .arg(tr("Parameters"));
        if (m_node.acceptsUndeclared)
            out += QStringLiteral("<p>%1</p>\n")
                       .arg(escape(tr("This node accepts parameters it "
                                      "does not declare.")));
        QList<QStringList> rows;
        for (const ParameterDeclaration &p : m_node.parameters)
            rows << QStringList{
                code(p.name), escape(p.type), p.hasDefault ? code(p.defaultValue) : QString(),
                escape(p.description) +
                    (p.range.isEmpty()
                         ? QString()
                         : QStringLiteral(" <span class=\"muted\">%1</span>").arg(escape(p.range))),
                SiteHtml::source(m_context, m_path, p.evidence)};
        if (rows.isEmpty())
            return out + QStringLiteral("<p>%1</p>\n</section>\n")
                             .arg(escape(tr("The analysis found no parameter declaration.")));
        return out +
               SiteHtml::table(
                   tr("Parameters %1 declares").arg(m_node.className),
                   {tr("Name"), tr("Type"), tr("Default"), tr("Description"), tr("Source")}, rows) +
               QStringLiteral("</section>\n");
    }

    /// What an instance shows below its summary, but for the systems it is part of: where it
    /// is launched, its ports' resolved names and its parameters in effect.
    QString instanceBody(const SitePortUse &use) const
    {
        const RosNodePart &part = *use.part;
        QString out =
            QStringLiteral("<p>%1 %2 %3</p>\n")
                .arg(escape(tr("Launched by")),
                     link(m_path, m_model.launchPage(use.composite->file), use.composite->stem),
                     SiteHtml::source(m_context, m_path, part.evidence));
        QList<QStringList> rows;
        for (const PartPort &p : part.ports) {
            const QString key = SiteModel::channelKey(portFamilyName(p.kind), p.name);
            QString resolved =
                p.resolved && !p.guessed
                    ? link(m_path, m_model.channelPage(key), p.name)
                    : code(p.name) +
                          QStringLiteral(" <span class=\"tag\">%1</span>").arg(escape(tr("guess")));
            if (p.remapped)
                resolved +=
                    QStringLiteral(" <span class=\"muted\">%1</span>").arg(escape(tr("remapped")));
            if (!p.active)
                resolved += QStringLiteral(" <span class=\"tag off\">%1</span>")
                                .arg(escape(tr("inactive")));
            rows << QStringList{escape(kindText(p.kind)), code(p.nameAsWritten), resolved,
                                code(p.type)};
        }
        if (!rows.isEmpty())
            out +=
                SiteHtml::table(tr("Resolved names of %1").arg(SiteModel::qualifiedName(part)),
                                {tr("Kind"), tr("As written"), tr("Resolved"), tr("Type")}, rows);
        if (use.instance && !use.instance->effectiveParameters.isEmpty()) {
            QList<QStringList> params;
            for (const ParameterSetting &s : use.instance->effectiveParameters)
                params << QStringList{code(s.name), code(s.value), escape(s.source),
                                      SiteHtml::source(m_context, m_path, s.evidence)};
            out += SiteHtml::table(
                tr("Parameters in effect for %1").arg(SiteModel::qualifiedName(part)),
                {tr("Name"), tr("Value"), tr("From"), tr("Source")}, params);
        }
        return out;
    }

    /// The instances that show the same (one launch file's node included by many systems) as
    /// one entry that lists its systems: the page stays one entry per distinct instance, not
    /// one per system, which on a large workspace is the difference between kilobytes and
    /// megabytes.
    QString instanceGroups(const QList<SitePortUse> &uses) const
    {
        QStringList order;
        QHash<QString, QList<const SitePortUse *>> groups;
        for (const SitePortUse &use : uses) {
            const QString key = SiteModel::qualifiedName(*use.part) + u'\n' + instanceBody(use);
            if (!groups.contains(key))
                order << key;
            groups[key] << &use;
        }
        QString out;
        for (const QString &key : order) {
            const QList<const SitePortUse *> &group = groups.value(key);
            QStringList stems;
            QStringList links;
            for (const SitePortUse *use : group) {
                const SiteSystem *system = m_model.system(use->system);
                stems << (system ? system->root.stem : use->system);
                links << link(m_path, m_model.systemPage(use->system),
                              system ? system->title() : use->system);
            }
            const QString where = group.size() <= 3
                                      ? tr("in %1").arg(stems.join(QStringLiteral(", ")))
                                      : tr("in %1 systems").arg(group.size());
            out +=
                QStringLiteral("<details><summary>%1 <span class=\"muted\">%2</span></summary>\n")
                    .arg(code(SiteModel::qualifiedName(*group.first()->part)), escape(where));
            out += QStringLiteral("<p>%1 %2</p>\n")
                       .arg(escape(group.size() == 1 ? tr("System") : tr("Systems")),
                            links.join(QStringLiteral(", ")));
            out += key.section(u'\n', 1) + QStringLiteral("</details>\n");
        }
        return out;
    }

    /// A plugin runs inside the node instances that load it by their parameters.
    QString loaders() const
    {
        QList<QStringList> rows;
        for (const SitePortUse &use : m_model.loadersOf(m_node.id)) {
            QStringList names;
            for (const ParameterSetting &p : use.instance->plugins)
                if (p.value == m_node.qualifiedName)
                    names << code(p.name) + u' ' + SiteHtml::source(m_context, m_path, p.evidence);
            const SiteSystem *system = m_model.system(use.system);
            rows << QStringList{
                link(m_path, m_model.partPage(*use.part), SiteModel::qualifiedName(*use.part)),
                names.join(QStringLiteral("<br>")),
                link(m_path, m_model.systemPage(use.system),
                     system ? system->root.stem : use.system)};
        }
        if (rows.isEmpty())
            return QStringLiteral("<p>%1</p>\n")
                .arg(escape(tr("No node instance of the workspace's systems loads this plugin.")));
        return SiteHtml::table(tr("Node instances that load %1").arg(m_node.className),
                               {tr("Node"), tr("Loaded as"), tr("System")}, rows);
    }

    QString instances() const
    {
        QString out = QStringLiteral(
                          "<section aria-labelledby=\"instances\">\n<h2 id=\"instances\">%1</h2>\n")
                          .arg(tr("Where it is launched"));
        if (m_node.isPlugin())
            return out + loaders() + QStringLiteral("</section>\n");
        const QList<SitePortUse> uses = m_model.instancesOf(m_node.id);
        if (uses.isEmpty())
            return out + QStringLiteral("<p>%1</p>\n</section>\n")
                             .arg(escape(tr("No system of the workspace launches this class.")));
        return out + instanceGroups(uses) + QStringLiteral("</section>\n");
    }

    const SiteContext &m_context;
    const SiteModel &m_model;
    const AtomicNode &m_node;
    QString m_path;
};

} // namespace

SiteFile NodePage::write(const SiteContext &context, const AtomicNode &node)
{
    return Writer(context, node).page();
}

} // namespace rosarch
