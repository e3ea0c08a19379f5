#include "site/launchpage.h"
#include "core/rosnames.h"
#include "site/sitediagram.h"

#include <QCoreApplication>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::LaunchPage", text);
}

using SiteHtml::code;
using SiteHtml::escape;
using SiteHtml::link;

/// Whether a launch action's own condition could not be decided: the run recorded it as
/// unresolved at the action, under its text.
bool undecidedCondition(const QList<Unresolved> &unresolved, const QString &condition,
                        const Evidence &evidence)
{
    for (const Unresolved &u : unresolved)
        if (u.evidence == evidence && u.expression == condition)
            return true;
    return false;
}

/// A condition as written, then what the analysis made of it: `value` when decided (the
/// action ran, or "does not hold"), or that it was undecidable and kept as the best guess.
QString conditionCell(const QString &written, bool undecided, bool ran, const QString &notRun)
{
    if (written.isEmpty())
        return {};
    const QString value =
        undecided ? QStringLiteral("<span class=\"tag\">%1</span>")
                        .arg(escape(tr("undecided: kept as the best guess")))
        : ran ? QStringLiteral("<span class=\"tag\">%1</span>").arg(escape(tr("holds")))
              : QStringLiteral("<span class=\"tag off\">%1</span>").arg(escape(notRun));
    return code(written) + u' ' + value;
}

/// A group's condition as the file writes it: XML and YAML give the attribute's value alone.
QString groupCondition(const LaunchGroupCondition &g, const QString &format)
{
    if (format == QLatin1String("python"))
        return g.condition;
    return QStringLiteral("%1=\"%2\"")
        .arg(g.unless ? QStringLiteral("unless") : QStringLiteral("if"), g.condition);
}

class Writer
{
public:
    Writer(const SiteContext &context, const QString &file)
        : m_context(context), m_model(*context.model), m_file(file),
          m_path(m_model.launchPage(file))
    {
        const LaunchDependencies &launch = m_model.recovery().launch;
        // The file on its own (its classifier run), else its first instance in a system.
        for (const LaunchFileInstance &lf : launch.classifierInstances)
            if (lf.file == file && lf.parentId.isEmpty()) {
                m_instance = &lf;
                m_nodes = &launch.classifierNodes;
                m_instances = &launch.classifierInstances;
                break;
            }
        if (!m_instance)
            for (const LaunchFileInstance &lf : launch.instances)
                if (lf.file == file) {
                    m_instance = &lf;
                    m_nodes = &launch.nodes;
                    m_instances = &launch.instances;
                    break;
                }
        for (const Composite *c : m_model.recovery().architecture.representatives())
            if (c->file == file) {
                m_composite = c;
                break;
            }
    }

    SiteFile page() const
    {
        const QString name = m_file.section(u'/', -1);
        const QString package = m_model.packageOf(m_file);
        QString body =
            QStringLiteral("<dl class=\"props\"><dt>%1</dt><dd>%2</dd><dt>%3</dt><dd>%4</dd>")
                .arg(escape(tr("File")),
                     SiteHtml::source(m_context, m_path, Evidence::startOf(m_file)),
                     escape(tr("Package")), link(m_path, m_model.packagePage(package), package));
        QStringList systems;
        for (const QString &id : m_model.systemsWith(m_file))
            if (const SiteSystem *s = m_model.system(id))
                systems << link(m_path, m_model.systemPage(id), s->root.stem);
        body +=
            QStringLiteral("<dt>%1</dt><dd>%2</dd></dl>\n")
                .arg(escape(tr("Part of")), systems.isEmpty() ? escape(tr("no system"))
                                                              : systems.join(QStringLiteral(", ")));
        body += diagram();
        body += arguments();
        body += includes();
        body += groups();
        body += nodes();
        return SiteHtml::page(m_context, m_path, name,
                              {{tr("Home"), QStringLiteral("index.html")},
                               {package, m_model.packagePage(package)},
                               {name, m_path}},
                              body);
    }

private:
    QString section(const QString &id, const QString &title) const
    {
        return QStringLiteral("<section aria-labelledby=\"%1\">\n<h2 id=\"%1\">%2</h2>\n")
            .arg(id, escape(title));
    }

    QString diagram() const
    {
        if (!m_composite || m_composite->parts.isEmpty())
            return {};
        const QString title = tr("Diagram of %1 on its own: %2 parts, %3 channels.")
                                  .arg(m_file.section(u'/', -1))
                                  .arg(m_composite->parts.size())
                                  .arg(m_composite->channels.size());
        const SiteDiagram::Result d =
            SiteDiagram::draw(*m_composite, title, QStringLiteral("d"), [&](const QString &key) {
                const QString target = m_model.diagramTarget(*m_composite, key, false);
                return target.isEmpty() || target.startsWith(u'#') ? QString()
                                                                   : SiteHtml::href(m_path, target);
            });
        QString out = section(QStringLiteral("diagram"), tr("Diagram"));
        if (d.svg.isEmpty())
            return out +
                   QStringLiteral("<p class=\"note\">%1</p>\n</section>\n").arg(escape(d.error));
        out +=
            QStringLiteral("<figure class=\"diagram-wrap\">\n<div class=\"scroll\" tabindex=\"0\" "
                           "role=\"region\" aria-label=\"%1\">\n")
                .arg(escape(tr("Diagram, scrollable")));
        return out + d.svg +
               QStringLiteral("</div>\n<figcaption>%1</figcaption>\n</figure>\n</section>\n")
                   .arg(escape(title));
    }

    QString arguments() const
    {
        QList<QStringList> rows;
        QMap<QString, const LaunchArgument *> declared;
        for (const LaunchArgument &a : m_model.recovery().launch.arguments)
            if (a.launchFile == m_file)
                declared.insert(a.name, &a);
        if (m_instance)
            for (const auto &[name, value] : m_instance->arguments) {
                const LaunchArgument *a = declared.value(name);
                rows << QStringList{code(name), code(value), a ? escape(a->description) : QString(),
                                    a ? SiteHtml::source(m_context, m_path, a->evidence)
                                      : QString()};
            }
        if (rows.isEmpty())
            return {};
        return section(QStringLiteral("arguments"), tr("Arguments")) +
               SiteHtml::table(tr("Launch arguments and the values analysed"),
                               {tr("Name"), tr("Value"), tr("Description"), tr("Source")}, rows) +
               QStringLiteral("</section>\n");
    }

    QString includes() const
    {
        QList<QStringList> rows;
        if (m_instance)
            for (const QString &id : m_instance->includedLaunchFiles)
                for (const LaunchFileInstance &lf : *m_instances)
                    if (lf.id == id)
                        rows << QStringList{
                            lf.external ? code(lf.package + u'/' + lf.type)
                                        : link(m_path, m_model.launchPage(lf.file), lf.file),
                            conditionCell(
                                lf.condition,
                                undecidedCondition(lf.unresolved, lf.condition, lf.evidence),
                                lf.active, tr("not included")),
                            SiteHtml::source(m_context, m_path, lf.evidence)};
        QString out;
        if (!rows.isEmpty())
            out += section(QStringLiteral("includes"), tr("Includes")) +
                   SiteHtml::table(tr("Launch files this file includes"),
                                   {tr("File"), tr("Condition"), tr("Source")}, rows) +
                   QStringLiteral("</section>\n");
        if (m_instance && m_instance->namespaces.size() > 0) {
            out += section(QStringLiteral("groups"), tr("Namespaces and groups"));
            out += QStringLiteral("<ul>");
            for (auto it = m_instance->namespaces.cbegin(); it != m_instance->namespaces.cend();
                 ++it) {
                QStringList members;
                for (const QString &id : *it)
                    members << member(id);
                members.removeAll(QString());
                out += QStringLiteral("<li>%1: %2</li>")
                           .arg(RosNames::scopeRelative(it.key()).isEmpty() || it.key() == u'/'
                                    ? escape(tr("the file's own scope"))
                                    : code(RosNames::scopeRelative(it.key())),
                                members.join(QStringLiteral(", ")));
            }
            out += QStringLiteral("</ul>\n</section>\n");
        }
        return out;
    }

    /// The groups with a condition: as written, and its value with the file's defaults.
    QString groups() const
    {
        if (!m_instance || m_instance->groups.isEmpty())
            return {};
        QList<QStringList> rows;
        for (const LaunchGroupCondition &g : m_instance->groups)
            rows << QStringList{escape(tr("line %1").arg(g.evidence.line)),
                                conditionCell(groupCondition(g, m_instance->format), g.undecided,
                                              g.holds, tr("does not hold: its actions do not run")),
                                SiteHtml::source(m_context, m_path, g.evidence)};
        return section(QStringLiteral("conditions"), tr("Conditional groups")) +
               SiteHtml::table(tr("Groups that run only under a condition"),
                               {tr("Group"), tr("Condition"), tr("Source")}, rows) +
               QStringLiteral("</section>\n");
    }

    /// A node or an include inside a namespace scope, linked to its page.
    QString member(const QString &id) const
    {
        for (const NodeInstance &n : *m_nodes)
            if (n.id == id)
                return link(m_path, m_model.nodePage(n.classId),
                            n.nodeName.isEmpty() ? n.execName : n.nodeName);
        for (const LaunchFileInstance &lf : *m_instances)
            if (lf.id == id)
                return lf.external ? code(lf.type)
                                   : link(m_path, m_model.launchPage(lf.file), lf.type);
        return {};
    }

    QString nodes() const
    {
        QList<QStringList> rows;
        if (m_instance)
            for (const QString &id : m_instance->nodes)
                for (const NodeInstance &n : *m_nodes)
                    if (n.id == id) {
                        const QString ns =
                            n.nameSpace == QLatin1String("/") ? QString() : n.nameSpace;
                        rows << QStringList{
                            // relative to the file's own scope, as its diagram writes it
                            code(RosNames::scopeRelative(
                                ns + u'/' + (n.nodeName.isEmpty() ? n.execName : n.nodeName))),
                            code(n.package + u'/' + n.execName),
                            link(m_path, m_model.nodePage(n.classId), n.className),
                            conditionCell(n.condition,
                                          undecidedCondition(n.unresolved, n.condition, n.evidence),
                                          n.active, tr("not started")),
                            SiteHtml::source(m_context, m_path, n.evidence)};
                    }
        if (rows.isEmpty())
            return {};
        return section(QStringLiteral("nodes"), tr("Nodes")) +
               SiteHtml::table(
                   tr("Nodes this file starts itself"),
                   {tr("Node"), tr("Executable"), tr("Class"), tr("Condition"), tr("Source")},
                   rows) +
               QStringLiteral("</section>\n");
    }

    const SiteContext &m_context;
    const SiteModel &m_model;
    QString m_file;
    QString m_path;
    const LaunchFileInstance *m_instance = nullptr;
    const QList<NodeInstance> *m_nodes = nullptr;
    const QList<LaunchFileInstance> *m_instances = nullptr;
    const Composite *m_composite = nullptr;
};

} // namespace

SiteFile LaunchPage::write(const SiteContext &context, const QString &file)
{
    return Writer(context, file).page();
}

} // namespace rosarch
