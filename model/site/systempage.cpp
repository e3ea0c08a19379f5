#include "site/systempage.h"
#include "diagram/diagrambuilder.h"
#include "site/sitediagram.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>
#include <QUrl>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::SystemPage", text);
}

using SiteHtml::code;
using SiteHtml::escape;
using SiteHtml::link;

class Writer
{
public:
    Writer(const SiteContext &context, const SiteSystem &system)
        : m_context(context), m_model(*context.model), m_system(system),
          m_path(m_model.systemPage(system.root.instanceId))
    {
    }

    SiteFile page()
    {
        QString body = intro();
        body += diagram();
        body += launchTree();
        body += nodes();
        body += channels();
        return SiteHtml::page(m_context, m_path, m_system.root.stem,
                              {{tr("Home"), QStringLiteral("index.html")},
                               {tr("Systems"), QStringLiteral("index.html#systems")},
                               {m_system.root.stem, m_path}},
                              body);
    }

private:
    QString intro() const
    {
        const Composite *top = m_system.composites.value(0);
        QString out = QStringLiteral("<p class=\"lead\">");
        out += m_system.root.executable
                   ? tr("An executable that builds its own nodes: %1.")
                         .arg(code(top ? top->executable : m_system.root.stem))
                   : tr("A launch file that no other file includes: %1.")
                         .arg(link(m_path, m_model.launchPage(m_system.root.file),
                                   m_system.root.file));
        if (top && !top->file.isEmpty())
            out += u' ' + SiteHtml::source(m_context, m_path, Evidence::startOf(top->file));
        out += QStringLiteral("</p>\n<ul class=\"facts\">");
        out += QStringLiteral("<li><strong>%1</strong> %2</li>")
                   .arg(m_system.nodes.size())
                   .arg(escape(m_system.nodes.size() == 1 ? tr("node instance")
                                                          : tr("node instances")));
        out +=
            QStringLiteral("<li><strong>%1</strong> %2</li>")
                .arg(m_system.composites.size())
                .arg(escape(m_system.composites.size() == 1 ? tr("launch file")
                                                            : tr("launch files (with includes)")));
        out += QStringLiteral("<li><strong>%1</strong> %2</li>")
                   .arg(m_system.channels.size())
                   .arg(escape(tr("topics, services and actions")));
        out += QStringLiteral("<li><a href=\"%1\"><strong>%2</strong> %3</a></li></ul>\n")
                   .arg(escape(SiteHtml::href(
                       m_path, QStringLiteral("findings.html?system=") +
                                   QString::fromLatin1(QUrl::toPercentEncoding(m_system.title())))))
                   .arg(m_system.findings)
                   .arg(escape(m_system.findings == 1 ? tr("finding") : tr("findings")));
        return out;
    }

    /// One composite's drawing; `index` numbers the drawings of the page (ids stay unique).
    QString drawing(const Composite &c, int index) const
    {
        const bool root = index == 0;
        const QString title =
            (root ? tr("Composed diagram of %1: %2 parts, %3 channels.")
                  : tr("Diagram of %1 as this system includes it: %2 parts, %3 channels."))
                .arg(c.stem)
                .arg(c.parts.size())
                .arg(c.channels.size()) +
            u' ' +
            tr("Parts link to their node class or to the drawing of the launch file they "
               "include, ports and channels to their topic, service or action.");
        const SiteDiagram::Result d =
            SiteDiagram::draw(c, title, QStringLiteral("d%1").arg(index), [&](const QString &key) {
                const QString target = m_model.diagramTarget(c, key, true);
                return target.isEmpty() ? QString() : SiteHtml::href(m_path, target);
            });
        QString out;
        if (!root) {
            const Composite *parent = m_model.recovery().architecture.composite(c.parentId);
            out += QStringLiteral("<h3 id=\"%1\">%2 <span class=\"muted\">%3</span></h3>\n")
                       .arg(SiteModel::compositeAnchor(c.instanceId),
                            link(m_path, m_model.launchPage(c.file),
                                 c.file.isEmpty() ? c.stem : c.file),
                            escape(tr("included by %1").arg(parent ? parent->stem : c.parentId)));
        }
        if (d.svg.isEmpty())
            return out + QStringLiteral("<p class=\"note\">%1</p>\n").arg(escape(d.error));
        if (d.overview)
            out += QStringLiteral("<p class=\"note\">%1</p>\n")
                       .arg(escape(tr("Too big to read in one drawing, so drawn as an overview: "
                                      "each namespace as one box (it leads to its nodes in the "
                                      "table below), parts without their port rows, the "
                                      "boundary ports as one box per side.")));
        out += QStringLiteral("<figure class=\"diagram-wrap\">\n<div class=\"scroll\" "
                              "tabindex=\"0\" role=\"region\" aria-label=\"%1\">\n")
                   .arg(escape(tr("%1, scrollable").arg(c.stem)));
        out += d.svg;
        out +=
            QStringLiteral("</div>\n<figcaption>%1</figcaption>\n</figure>\n").arg(escape(title));
        return out;
    }

    /// The system's own composite, then each launch file it includes (depth first), so that
    /// an include in a drawing leads to the drawing of what it starts.
    QString diagram() const
    {
        QString out =
            QStringLiteral("<section aria-labelledby=\"diagram\">\n<h2 id=\"diagram\">%1</h2>\n")
                .arg(tr("Composed diagram"));
        int index = 0;
        for (const Composite *c : m_system.composites)
            if (index == 0 || !c->parts.isEmpty())
                out += drawing(*c, index++);
        return out + QStringLiteral("</section>\n");
    }

    QString launchItem(const LaunchFileInstance &lf,
                       const QHash<QString, QList<const LaunchFileInstance *>> &children,
                       int depth) const
    {
        const LaunchDependencies &launch = m_model.recovery().launch;
        QString out = QStringLiteral("<li>");
        out +=
            lf.external
                ? code(lf.type) +
                      QStringLiteral(" <span class=\"tag\">%1</span>").arg(escape(tr("external")))
                : link(m_path, m_model.launchPage(lf.file), lf.file);
        if (!lf.external && lf.evidence.isValid() && !lf.parentId.isEmpty())
            out += QStringLiteral(" <span class=\"muted\">%1</span> %2")
                       .arg(escape(tr("included at")),
                            SiteHtml::source(m_context, m_path, lf.evidence));
        if (!lf.condition.isEmpty())
            out += QStringLiteral(" <span class=\"tag%1\">%2 %3</span>")
                       .arg(lf.active ? QString() : QStringLiteral(" off"),
                            escape(lf.active ? tr("if") : tr("skipped: if")), code(lf.condition));
        if (!lf.arguments.isEmpty()) {
            out +=
                QStringLiteral("<details><summary>%1</summary><dl class=\"args\">")
                    .arg(escape(QCoreApplication::translate("rosarch::SystemPage", "%n arguments",
                                                            nullptr, int(lf.arguments.size()))));
            for (const auto &[name, value] : lf.arguments)
                out += QStringLiteral("<dt>%1</dt><dd>%2</dd>").arg(code(name), code(value));
            out += QStringLiteral("</dl></details>");
        }
        QStringList items;
        for (const QString &id : lf.nodes)
            if (const NodeInstance *n = launch.node(id)) {
                const QString name =
                    (n->nameSpace == QLatin1String("/") ? QString() : n->nameSpace) + u'/' +
                    (n->nodeName.isEmpty() ? n->execName : n->nodeName);
                items << QStringLiteral("<li>%1 %2%3</li>")
                             .arg(link(m_path, m_model.nodePage(n->classId), name),
                                  n->active ? QString()
                                            : QStringLiteral("<span class=\"tag off\">%1</span> ")
                                                  .arg(escape(tr("not started"))),
                                  SiteHtml::source(m_context, m_path, n->evidence));
            }
        for (const LaunchFileInstance *child : children.value(lf.id))
            items << launchItem(*child, children, depth + 1);
        if (!items.isEmpty())
            out += QStringLiteral("\n<ul>") + items.join(QString()) + QStringLiteral("</ul>");
        return out + QStringLiteral("</li>\n");
    }

    QString launchTree() const
    {
        QString out =
            QStringLiteral("<section aria-labelledby=\"launch\">\n<h2 id=\"launch\">%1</h2>\n")
                .arg(tr("Launch tree"));
        const LaunchDependencies &launch = m_model.recovery().launch;
        QHash<QString, QList<const LaunchFileInstance *>> children;
        const LaunchFileInstance *root = nullptr;
        for (const LaunchFileInstance &lf : launch.instances) {
            if (lf.id == m_system.root.instanceId)
                root = &lf;
            if (!lf.parentId.isEmpty())
                children[lf.parentId] << &lf;
        }
        if (!root)
            return out + QStringLiteral("<p>%1</p>\n</section>\n")
                             .arg(escape(tr("This system is not started by a launch file.")));
        out += QStringLiteral("<ul class=\"tree\">\n") + launchItem(*root, children, 0) +
               QStringLiteral("</ul>\n</section>\n");
        return out;
    }

    QString nodes() const
    {
        QList<QStringList> rows;
        QSet<QString> anchored;
        for (const SitePortUse &use : m_system.nodes) {
            const RosNodePart &part = *use.part;
            QString name = code(SiteModel::qualifiedName(part));
            // The first node of each namespace is where an overview's namespace box leads.
            QString anchors;
            for (const QString &ns : DiagramBuilder::namespaceChain(part.nameSpace))
                if (!anchored.contains(ns)) {
                    anchored.insert(ns);
                    anchors += QStringLiteral("<span id=\"%1\"></span>")
                                   .arg(SiteModel::namespaceAnchor(ns));
                }
            const QString classId = use.instance ? use.instance->classId : part.typeId;
            const AtomicNode *arc = m_model.recovery().nodes.node(classId);
            QString state;
            if (!part.active)
                state = tr("not started (condition false)");
            else if (use.instance && use.instance->activeByGuess)
                state = tr("started if its condition holds");
            rows << QStringList{
                anchors + name,
                link(m_path, m_model.partPage(part), arc ? arc->className : part.typeName),
                escape(arc            ? arc->packageName
                       : use.instance ? use.instance->package
                                      : QString()),
                link(m_path, m_model.launchPage(use.composite->file), use.composite->stem) + u' ' +
                    SiteHtml::source(m_context, m_path, part.evidence),
                escape(state)};
        }
        return QStringLiteral("<section aria-labelledby=\"nodes\">\n<h2 id=\"nodes\">%1</h2>\n")
                   .arg(tr("Nodes")) +
               SiteHtml::table(
                   tr("The node instances of %1").arg(m_system.root.stem),
                   {tr("Node"), tr("Class"), tr("Package"), tr("Launched by"), tr("State")}, rows) +
               QStringLiteral("</section>\n");
    }

    QString channels() const
    {
        QList<QStringList> rows;
        for (const QString &key : m_system.channels) {
            const SiteChannel channel = m_model.channels().value(key);
            int providers = 0;
            int users = 0;
            for (const SitePortUse &use : channel.uses)
                if (use.system == m_system.root.instanceId)
                    (isProvidingPort(use.port->kind) ? providers : users) += 1;
            rows << QStringList{link(m_path, m_model.channelPage(key), channel.name),
                                escape(channel.family),
                                escape(channel.types.join(QStringLiteral(", "))),
                                QString::number(providers), QString::number(users)};
        }
        return QStringLiteral(
                   "<section aria-labelledby=\"channels\">\n<h2 id=\"channels\">%1</h2>\n")
                   .arg(tr("Topics, services and actions")) +
               SiteHtml::table(tr("Names used in %1; publishers, servers; subscribers, clients")
                                   .arg(m_system.root.stem),
                               {tr("Name"), tr("Kind"), tr("Type"), tr("Publishers / servers"),
                                tr("Subscribers / clients")},
                               rows) +
               QStringLiteral("</section>\n");
    }

    const SiteContext &m_context;
    const SiteModel &m_model;
    const SiteSystem &m_system;
    QString m_path;
};

} // namespace

SiteFile SystemPage::write(const SiteContext &context, const SiteSystem &system)
{
    return Writer(context, system).page();
}

} // namespace rosarch
