#include "widgets/talkerspanel.h"
#include "widgets/icons.h"

#include <QDir>
#include <QHash>
#include <QHeaderView>
#include <QLabel>
#include <QScopedValueRollback>
#include <QSet>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rosarch {

namespace {

QString roleName(PortKind kind)
{
    switch (kind) {
    case PortKind::Publisher:
        return TalkersPanel::tr("publisher");
    case PortKind::Subscriber:
        return TalkersPanel::tr("subscriber");
    case PortKind::ServiceServer:
        return TalkersPanel::tr("service server");
    case PortKind::ServiceClient:
        return TalkersPanel::tr("service client");
    case PortKind::ActionServer:
        return TalkersPanel::tr("action server");
    case PortKind::ActionClient:
        break;
    }
    return TalkersPanel::tr("action client");
}

bool isProvider(PortKind kind)
{
    return kind == PortKind::Publisher || kind == PortKind::ServiceServer ||
           kind == PortKind::ActionServer;
}

/// "1 publisher, 2 subscribers" (or servers and clients): node instances, not ports, and only
/// the active ones; "1 inactive" adds the instances whose condition or guards are false.
QString counts(const TalkerGroup &group)
{
    QSet<QString> providers, users, active, all;
    for (const Talker &t : group.talkers) {
        all.insert(t.instanceId);
        if (!t.active)
            continue;
        active.insert(t.instanceId);
        (isProvider(t.port.kind) ? providers : users).insert(t.instanceId);
    }
    const qsizetype nProviders = providers.size();
    const qsizetype nUsers = users.size();
    const bool topic = group.family == QLatin1String("topic");
    const QString p = topic ? (nProviders == 1 ? TalkersPanel::tr("1 publisher")
                                               : TalkersPanel::tr("%1 publishers").arg(nProviders))
                            : (nProviders == 1 ? TalkersPanel::tr("1 server")
                                               : TalkersPanel::tr("%1 servers").arg(nProviders));
    const QString u = topic ? (nUsers == 1 ? TalkersPanel::tr("1 subscriber")
                                           : TalkersPanel::tr("%1 subscribers").arg(nUsers))
                            : (nUsers == 1 ? TalkersPanel::tr("1 client")
                                           : TalkersPanel::tr("%1 clients").arg(nUsers));
    const qsizetype inactive = all.size() - active.size();
    return inactive == 0 ? TalkersPanel::tr("%1, %2").arg(p, u)
                         : TalkersPanel::tr("%1, %2, %3 inactive").arg(p, u).arg(inactive);
}

QString familyLabel(const QString &family)
{
    if (family == QLatin1String("topic"))
        return TalkersPanel::tr("topic");
    if (family == QLatin1String("service"))
        return TalkersPanel::tr("service");
    return TalkersPanel::tr("action");
}

QString talkerToolTip(const Talker &t)
{
    QStringList lines{
        TalkersPanel::tr("%1 of %2 (%3)").arg(roleName(t.port.kind), t.nodeName, t.className)};
    if (!t.port.nameAsWritten.isEmpty())
        lines << TalkersPanel::tr("Port %1, written “%2”%3")
                     .arg(t.port.id, t.port.nameAsWritten,
                          t.port.remapped ? TalkersPanel::tr(", remapped") : QString());
    if (!t.port.type.isEmpty())
        lines << t.port.type;
    if (!t.port.resolved)
        lines << TalkersPanel::tr("The name is a guess: the analysis could not decide it.");
    if (!t.active)
        lines << TalkersPanel::tr("Inactive: its launch condition or guard is false.");
    if (t.port.evidence.isValid())
        lines << TalkersPanel::tr("Created at %1:%2")
                     .arg(QDir::toNativeSeparators(t.port.evidence.file))
                     .arg(t.port.evidence.line);
    return lines.join(QLatin1Char('\n'));
}

} // namespace

TalkersPanel::TalkersPanel(QWidget *parent)
    : QWidget(parent), m_summary(new QLabel(this)), m_tree(new QTreeWidget(this))
{
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_tree->setColumnCount(4);
    m_tree->setHeaderLabels({tr("Node"), tr("Role"), tr("Port"), tr("Class")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_tree->header()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    m_tree->setUniformRowHeights(true);
    m_tree->setAlternatingRowColors(true);
    m_tree->setRootIsDecorated(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_summary);
    layout->addWidget(m_tree, 1);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, &TalkersPanel::onCurrentItemChanged);
    // Activating the current row again (Enter, double-click) goes there again.
    connect(m_tree, &QTreeWidget::itemActivated, this,
            [this](QTreeWidgetItem *item) { onCurrentItemChanged(item); });
    setMessage(tr("Click a topic, service or action in the composed diagram, or a port in the "
                  "node list, to see who talks on it."));
}

void TalkersPanel::setMessage(const QString &message)
{
    const QScopedValueRollback guard(m_filling, true);
    m_tree->clear();
    m_summary->setText(message);
}

QString TalkersPanel::summary() const
{
    return m_summary->text();
}

void TalkersPanel::showTalkers(const QString &subject, const QString &scope,
                               const QList<TalkerGroup> &groups, const QString &note)
{
    const QScopedValueRollback guard(m_filling, true);
    m_tree->clear();
    int total = 0;
    for (const TalkerGroup &g : groups) {
        auto *head = new QTreeWidgetItem(m_tree);
        const QString what = tr("%1 %2").arg(familyLabel(g.family), g.name);
        head->setText(0, g.type.isEmpty() ? tr("%1 · %2").arg(what, counts(g))
                                          : tr("%1 · %2 · %3").arg(what, g.type, counts(g)));
        head->setToolTip(0, head->text(0));
        head->setFlags(Qt::ItemIsEnabled);
        QFont bold = head->font(0);
        bold.setBold(true);
        head->setFont(0, bold);
        head->setFirstColumnSpanned(true);
        // One row per node instance, its ports under it.
        QHash<QString, QTreeWidgetItem *> instances;
        QHash<QString, bool> anyActive;
        for (const Talker &t : g.talkers) {
            anyActive[t.instanceId] = anyActive.value(t.instanceId) || t.active;
            QTreeWidgetItem *node = instances.value(t.instanceId);
            if (!node) {
                node = new QTreeWidgetItem(head);
                node->setText(0, t.nodeName);
                node->setText(3, t.className);
                node->setData(0, InstanceIdRole, t.instanceId);
                node->setData(0, PortIdRole, t.port.id);
                instances.insert(t.instanceId, node);
                ++total;
            }
            auto *row = new QTreeWidgetItem(node);
            row->setIcon(0, Icons::port(t.port.kind));
            row->setText(1, roleName(t.port.kind));
            row->setText(2, t.port.nameAsWritten.isEmpty()
                                ? t.port.id
                                : tr("%1  %2").arg(t.port.id, t.port.nameAsWritten));
            row->setData(0, InstanceIdRole, t.instanceId);
            row->setData(0, PortIdRole, t.port.id);
            const QString tip = talkerToolTip(t);
            for (int column = 0; column < 4; ++column) {
                row->setToolTip(column, tip);
                if (!t.active)
                    row->setForeground(column, palette().brush(QPalette::Disabled, QPalette::Text));
            }
        }
        for (QTreeWidgetItem *node : std::as_const(instances)) {
            // The instance's row says what its ports do; inactive when none of them is active.
            QStringList roles;
            for (int i = 0; i < node->childCount(); ++i)
                if (!roles.contains(node->child(i)->text(1)))
                    roles.append(node->child(i)->text(1));
            const bool active = anyActive.value(node->data(0, InstanceIdRole).toString());
            node->setText(1, roles.join(tr(", ")));
            node->setText(2, node->childCount() == 1 ? node->child(0)->text(2)
                                                     : tr("%1 ports").arg(node->childCount()));
            node->setIcon(0, node->child(0)->icon(0));
            node->setToolTip(0, node->child(0)->toolTip(0));
            for (int column = 0; column < 4 && !active; ++column)
                node->setForeground(column, palette().brush(QPalette::Disabled, QPalette::Text));
            node->setExpanded(node->childCount() > 1);
        }
        head->setExpanded(true);
    }
    QString text;
    if (groups.isEmpty())
        text = tr("%1 talks on nothing in %2.").arg(subject, scope);
    else if (total == 0)
        text = tr("No node in %2 talks on %1.").arg(subject, scope);
    else
        text = tr("Talkers on %1 in %2").arg(subject, scope);
    m_summary->setText(note.isEmpty() ? text : tr("%1\n%2").arg(text, note));
}

void TalkersPanel::onCurrentItemChanged(QTreeWidgetItem *current)
{
    if (m_filling || !current)
        return;
    const QString instanceId = current->data(0, InstanceIdRole).toString();
    if (!instanceId.isEmpty())
        Q_EMIT talkerSelected(instanceId, current->data(0, PortIdRole).toString());
}

} // namespace rosarch
