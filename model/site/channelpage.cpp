#include "site/channelpage.h"

#include <QCoreApplication>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::ChannelPage", text);
}

using SiteHtml::code;
using SiteHtml::escape;
using SiteHtml::link;

QString familyTitle(const QString &family)
{
    return family == QLatin1String("service")  ? tr("Service")
           : family == QLatin1String("action") ? tr("Action")
                                               : tr("Topic");
}

/// The remap rule that gave `port` its name ("from → to", as evaluated), as the composition
/// recorded it: one of the instance's own rules, or past them one of its container's.
QString remapRule(const SiteModel &model, const NodeInstance *instance, const PartPort &port)
{
    if (!instance || port.remap < 0)
        return {};
    const QPair<QString, QString> *rule = nullptr;
    if (port.remap < instance->remaps.size()) {
        rule = &instance->remaps.at(port.remap);
    } else if (const NodeInstance *container = model.recovery().launch.node(instance->container)) {
        const qsizetype index = port.remap - instance->remaps.size();
        if (index < container->remaps.size())
            rule = &container->remaps.at(index);
    }
    return rule ? rule->first + QStringLiteral(" → ") + rule->second : QString();
}

} // namespace

SiteFile ChannelPage::write(const SiteContext &context, const QString &key,
                            const SiteChannel &channel)
{
    const SiteModel &model = *context.model;
    const QString path = model.channelPage(key);
    const bool topic = channel.family == QLatin1String("topic");
    QString body =
        QStringLiteral("<dl class=\"props\"><dt>%1</dt><dd>%2</dd><dt>%3</dt><dd>%4</dd></dl>\n")
            .arg(escape(tr("Kind")), escape(familyTitle(channel.family)), escape(tr("Type")));
    QStringList types;
    for (const QString &t : channel.types)
        types << code(t);
    body = body.arg(types.isEmpty() ? escape(tr("unknown")) : types.join(QStringLiteral(", ")));
    if (channel.types.size() > 1)
        body += QStringLiteral("<p class=\"note\">%1</p>\n")
                    .arg(escape(tr("The ports on this name do not agree on its type.")));

    QString system;
    QList<QStringList> rows;
    const auto flush = [&] {
        if (system.isEmpty())
            return;
        const SiteSystem *s = model.system(system);
        const QString title = s ? s->root.stem : system;
        body += QStringLiteral("<section aria-labelledby=\"s-%1\">\n<h2 id=\"s-%1\">%2</h2>\n")
                    .arg(escape(system), link(path, model.systemPage(system), title));
        body += SiteHtml::table(tr("Ports on %1 in %2").arg(channel.name, title),
                                {tr("Role"), tr("Node"), tr("Class"), tr("Name as written"),
                                 tr("Remapped"), tr("Source")},
                                rows);
        body += QStringLiteral("</section>\n");
        rows.clear();
    };
    for (const SitePortUse &use : channel.uses) {
        if (use.system != system) {
            flush();
            system = use.system;
        }
        const PartPort &port = *use.port;
        const bool provides = isProvidingPort(port.kind);
        const QString role = topic ? (provides ? tr("publisher") : tr("subscriber"))
                                   : (provides ? tr("server") : tr("client"));
        const QString classId = use.instance ? use.instance->classId : use.part->typeId;
        const AtomicNode *arc = model.recovery().nodes.node(classId);
        QString remap;
        if (port.remapped) {
            const QString rule = remapRule(model, use.instance, port);
            remap = rule.isEmpty() ? escape(tr("yes")) : code(rule);
            if (use.instance)
                remap += u' ' + SiteHtml::source(context, path, use.instance->evidence);
        }
        rows << QStringList{
            escape(role) + (port.active ? QString()
                                        : QStringLiteral(" <span class=\"tag off\">%1</span>")
                                              .arg(escape(tr("inactive")))),
            code(SiteModel::qualifiedName(*use.part)),
            link(path, model.partPage(*use.part), arc ? arc->className : use.part->typeName),
            code(port.nameAsWritten),
            remap,
            SiteHtml::source(context, path, port.evidence)};
    }
    flush();
    return SiteHtml::page(context, path, channel.name,
                          {{tr("Home"), QStringLiteral("index.html")},
                           {familyTitle(channel.family), QString()},
                           {channel.name, path}},
                          body);
}

} // namespace rosarch
