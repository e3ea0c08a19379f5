#include "site/indexpage.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::IndexPage", text);
}

using SiteHtml::code;
using SiteHtml::escape;
using SiteHtml::link;

/// "1 system", "3 systems": `text` holds a singular and a plural form, "system|systems".
QString count(const char *text, qsizetype n)
{
    const QString forms = QCoreApplication::translate("rosarch::IndexPage", text);
    return QStringLiteral("%1 %2").arg(n).arg(forms.section(u'|', n == 1 ? 0 : 1, n == 1 ? 0 : 1));
}

} // namespace

SiteFile IndexPage::index(const SiteContext &context)
{
    const SiteModel &model = *context.model;
    const Recovery &r = model.recovery();
    const QString path = QStringLiteral("index.html");
    qsizetype classes = 0;
    for (const AtomicNode &n : r.nodes.nodes)
        classes += n.isPlugin() ? 0 : 1;
    QString body =
        QStringLiteral("<p class=\"lead\">%1</p>\n")
            .arg(escape(tr("The architecture of this ROS 2 workspace as rosarch "
                           "recovered it from the source: %1, %2, %3 and %4. Search "
                           "for any node, topic or launch file above.")
                            .arg(count("system|systems", model.systems().size()),
                                 count("package|packages", r.nodes.packages.size()),
                                 count("node class|node classes", classes),
                                 count("launch file|launch files", r.launch.launchFiles.size()))));
    QList<QStringList> rows;
    for (const SiteSystem &s : model.systems())
        rows << QStringList{link(path, model.systemPage(s.root.instanceId), s.root.stem),
                            s.root.executable ? escape(tr("executable")) : code(s.root.file),
                            QString::number(s.nodes.size()), QString::number(s.channels.size()),
                            QString::number(s.findings)};
    body += QStringLiteral("<section aria-labelledby=\"systems\">\n<h2 id=\"systems\">%1</h2>\n")
                .arg(escape(tr("Systems")));
    body += rows.isEmpty()
                ? QStringLiteral("<p>%1</p>\n")
                      .arg(escape(tr("No launch file or executable "
                                     "starts a system here.")))
                : SiteHtml::table(tr("Entry points: launch files no other file includes, and "
                                     "executables that build their own nodes"),
                                  {tr("System"), tr("Entry point"), tr("Nodes"),
                                   tr("Topics, services, actions"), tr("Findings")},
                                  rows, QStringLiteral("numbers"));
    body += QStringLiteral("</section>\n");

    rows.clear();
    QList<RosPackage> packages = r.nodes.packages;
    std::sort(packages.begin(), packages.end(),
              [](const RosPackage &a, const RosPackage &b) { return a.name < b.name; });
    QSet<QString> seen;
    for (const RosPackage &p : std::as_const(packages)) {
        if (seen.contains(p.name))
            continue;
        seen.insert(p.name);
        qsizetype launchFiles = 0;
        for (const QString &f : r.launch.launchFiles)
            launchFiles += model.packageOf(f) == p.name ? 1 : 0;
        rows << QStringList{link(path, model.packagePage(p.name), p.name),
                            QString::number(r.nodes.nodesOfPackage(p.name).size()),
                            QString::number(launchFiles)};
    }
    body += QStringLiteral("<section aria-labelledby=\"packages\">\n<h2 id=\"packages\">%1</h2>\n")
                .arg(escape(tr("Packages")));
    body += SiteHtml::table(tr("Packages of the workspace"),
                            {tr("Package"), tr("Node classes and plugins"), tr("Launch files")},
                            rows, QStringLiteral("counts"));
    body += QStringLiteral("</section>\n<p><a href=\"findings.html\">%1</a></p>\n")
                .arg(escape(tr("All findings (%1)").arg(model.findings().size())));
    return SiteHtml::page(context, path, context.title, {{tr("Home"), path}}, body);
}

SiteFile IndexPage::package(const SiteContext &context, const RosPackage &package)
{
    const SiteModel &model = *context.model;
    const Recovery &r = model.recovery();
    const QString path = model.packagePage(package.name);
    QString body =
        QStringLiteral("<dl class=\"props\"><dt>%1</dt><dd>%2</dd>")
            .arg(escape(tr("Manifest")), SiteHtml::source(context, path, package.evidence));
    if (!package.buildType.isEmpty())
        body += QStringLiteral("<dt>%1</dt><dd>%2</dd>")
                    .arg(escape(tr("Build type")), code(package.buildType));
    if (!package.version.isEmpty())
        body += QStringLiteral("<dt>%1</dt><dd>%2</dd>")
                    .arg(escape(tr("Version")), code(package.version));
    body += QStringLiteral("</dl>\n");
    QList<QStringList> rows;
    for (const AtomicNode *n : r.nodes.nodesOfPackage(package.name))
        rows << QStringList{link(path, model.nodePage(n->id), n->className),
                            escape(n->isPlugin() ? tr("plugin") : tr("node")),
                            escape(n->description)};
    body += QStringLiteral("<section aria-labelledby=\"classes\">\n<h2 id=\"classes\">%1</h2>\n")
                .arg(escape(tr("Node classes")));
    body += rows.isEmpty() ? QStringLiteral("<p>%1</p>\n").arg(escape(tr("None.")))
                           : SiteHtml::table(tr("Node classes and plugins of %1").arg(package.name),
                                             {tr("Class"), tr("Kind"), tr("Description")}, rows);
    body += QStringLiteral("</section>\n");
    QStringList files;
    for (const QString &f : r.launch.launchFiles)
        if (model.packageOf(f) == package.name)
            files << QStringLiteral("<li>%1</li>").arg(link(path, model.launchPage(f), f));
    body += QStringLiteral("<section aria-labelledby=\"launch\">\n<h2 id=\"launch\">%1</h2>\n")
                .arg(escape(tr("Launch files")));
    body += files.isEmpty()
                ? QStringLiteral("<p>%1</p>\n").arg(escape(tr("None.")))
                : QStringLiteral("<ul>") + files.join(QString()) + QStringLiteral("</ul>\n");
    body += QStringLiteral("</section>\n");
    return SiteHtml::page(context, path, package.name,
                          {{tr("Home"), QStringLiteral("index.html")},
                           {tr("Packages"), QStringLiteral("index.html#packages")},
                           {package.name, path}},
                          body);
}

SiteFile IndexPage::search(const SiteContext &context)
{
    const QString body = QStringLiteral("<p id=\"search-summary\" aria-live=\"polite\">%1</p>\n"
                                        "<ul id=\"search-page-results\" class=\"listing\"></ul>\n"
                                        "<noscript><p>%2</p></noscript>\n")
                             .arg(escape(tr("Type a name in the search box.")),
                                  escape(tr("Search needs JavaScript; the index lists every "
                                            "system and package.")));
    return SiteHtml::page(
        context, QStringLiteral("search.html"), tr("Search"),
        {{tr("Home"), QStringLiteral("index.html")}, {tr("Search"), QStringLiteral("search.html")}},
        body);
}

SiteFile IndexPage::searchIndex(const SiteModel &model)
{
    QList<QStringList> entries;
    QSet<QString> seen;
    const auto add = [&](const QString &name, const QString &kind, const QString &url,
                         const QString &detail) {
        if (url.isEmpty() || name.isEmpty())
            return;
        const QString key = name + u'\n' + kind + u'\n' + url;
        if (seen.contains(key))
            return;
        seen.insert(key);
        entries << QStringList{name, kind, url, detail};
    };
    const Recovery &r = model.recovery();
    for (const SiteSystem &s : model.systems())
        add(s.root.stem, QStringLiteral("system"), model.systemPage(s.root.instanceId), s.title());
    for (const AtomicNode &n : r.nodes.nodes)
        add(n.className, n.isPlugin() ? QStringLiteral("plugin") : QStringLiteral("node class"),
            model.nodePage(n.id), n.packageName);
    for (const SiteSystem &s : model.systems())
        for (const SitePortUse &use : s.nodes)
            add(SiteModel::qualifiedName(*use.part), QStringLiteral("node"),
                model.partPage(*use.part), use.part->typeName);
    for (auto it = model.channels().cbegin(); it != model.channels().cend(); ++it)
        add(it->name, it->family, model.channelPage(it.key()),
            it->types.join(QStringLiteral(", ")));
    for (const QString &f : r.launch.launchFiles)
        add(f.section(u'/', -1), QStringLiteral("launch file"), model.launchPage(f), f);
    for (const RosPackage &p : r.nodes.packages)
        add(p.name, QStringLiteral("package"), model.packagePage(p.name), p.path);
    std::sort(entries.begin(), entries.end());
    QJsonArray array;
    for (const QStringList &e : std::as_const(entries))
        array.append(QJsonArray::fromStringList(e));
    // "</" cannot end the script early: JSON allows "\/".
    const QByteArray json =
        QJsonDocument(array).toJson(QJsonDocument::Compact).replace("</", "<\\/");
    return {QStringLiteral("assets/search-index.js"),
            "window.rosarchSearchIndex = " + json + ";\n"};
}

} // namespace rosarch
