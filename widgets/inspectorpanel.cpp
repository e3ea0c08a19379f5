#include "widgets/inspectorpanel.h"

#include <QAction>
#include <QFormLayout>
#include <QGridLayout>
#include <QLabel>
#include <QScrollArea>
#include <QToolButton>
#include <QVBoxLayout>

namespace rosarch {

namespace {
QLabel *valueLabel(QWidget *parent)
{
    auto *l = new QLabel(parent);
    l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    l->setWordWrap(true);
    l->setTextFormat(Qt::PlainText);
    return l;
}
} // namespace

InspectorPanel::InspectorPanel(QWidget *parent)
    : QWidget(parent), m_placeholder(new QLabel(this)), m_body(new QWidget(this)),
      m_kind(valueLabel(m_body)), m_name(valueLabel(m_body)), m_type(valueLabel(m_body)),
      m_key(valueLabel(m_body)), m_provenance(valueLabel(m_body)), m_reviewed(valueLabel(m_body)),
      m_corrections(valueLabel(m_body)), m_descriptionLabel(new QLabel(tr("Description:"), m_body)),
      m_descriptionField(new QWidget(m_body)), m_description(valueLabel(m_descriptionField)),
      m_descriptionSource(valueLabel(m_descriptionField)), m_buttons(new QWidget(m_body)),
      m_buttonLayout(new QGridLayout(m_buttons))
{
    m_placeholder->setAlignment(Qt::AlignCenter);
    m_placeholder->setWordWrap(true);
    m_placeholder->setObjectName(QStringLiteral("inspectorHint"));
    m_placeholder->setMargin(4); // whole in the short dock of a 700-pixel-high window
    m_placeholder->setForegroundRole(QPalette::PlaceholderText);
    m_placeholder->setText(tr("Select an element to see where it comes from and to correct it."));
    QFont name = m_name->font();
    name.setBold(true);
    m_name->setFont(name);
    m_key->setForegroundRole(QPalette::PlaceholderText);
    m_corrections->setForegroundRole(QPalette::PlaceholderText);

    auto *form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(tr("Kind:"), m_kind);
    form->addRow(tr("Name:"), m_name);
    form->addRow(tr("Type:"), m_type);
    form->addRow(tr("Key:"), m_key);
    form->addRow(tr("Provenance:"), m_provenance);
    form->addRow(tr("Review:"), m_reviewed);
    // what the class does, then where that comes from, quieter
    m_descriptionSource->setForegroundRole(QPalette::PlaceholderText);
    auto *described = new QVBoxLayout(m_descriptionField);
    described->setContentsMargins(0, 0, 0, 0);
    described->setSpacing(0);
    described->addWidget(m_description);
    described->addWidget(m_descriptionSource);
    form->addRow(m_descriptionLabel, m_descriptionField);
    m_buttonLayout->setContentsMargins(0, 4, 0, 0);
    m_buttonLayout->setSpacing(4);
    auto *body = new QVBoxLayout(m_body);
    body->addLayout(form);
    body->addWidget(m_corrections);
    body->addWidget(m_buttons);
    body->addStretch(1);

    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(m_body);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_placeholder, 1);
    layout->addWidget(scroll, 1);
    setElement({}, {});
}

void InspectorPanel::setElement(const InspectorInfo &info, const QList<QAction *> &actions)
{
    m_info = info;
    // later: one of them may be the button whose click changed the element
    while (QLayoutItem *item = m_buttonLayout->takeAt(0)) {
        if (QWidget *w = item->widget()) {
            w->hide();
            w->deleteLater();
        }
        delete item;
    }
    for (QAction *a : std::as_const(m_actions))
        a->deleteLater();
    m_actions = actions;
    const bool empty = info.kind.isEmpty();
    m_placeholder->setVisible(empty);
    m_body->parentWidget()->parentWidget()->setVisible(!empty); // the scroll area
    m_kind->setText(info.kind);
    m_name->setText(info.name);
    m_type->setText(info.type.isEmpty() ? tr("\u2014") : info.type);
    m_key->setText(info.key);
    m_provenance->setText(info.provenance);
    m_reviewed->setText(info.reviewed ? tr("\u2713 reviewed") : tr("not reviewed"));
    m_corrections->setText(info.corrections);
    m_corrections->setVisible(!info.corrections.isEmpty());
    m_descriptionLabel->setVisible(info.describable);
    m_descriptionField->setVisible(info.describable);
    // never blank: where nothing describes the class, the panel says so
    m_description->setText(info.description.isEmpty() ? info.descriptionSource : info.description);
    m_descriptionSource->setText(info.description.isEmpty() ? QString() : info.descriptionSource);
    m_descriptionSource->setVisible(!info.description.isEmpty());
    int i = 0;
    for (QAction *a : actions) {
        a->setParent(this);
        if (a->isSeparator())
            continue;
        auto *button = new QToolButton(m_buttons);
        button->setDefaultAction(a);
        button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        m_buttonLayout->addWidget(button, i / 2, i % 2);
        ++i;
    }
}

QString InspectorPanel::fieldText(const QString &field) const
{
    const QHash<QString, QLabel *> labels{
        {QStringLiteral("kind"), m_kind},
        {QStringLiteral("name"), m_name},
        {QStringLiteral("type"), m_type},
        {QStringLiteral("key"), m_key},
        {QStringLiteral("provenance"), m_provenance},
        {QStringLiteral("reviewed"), m_reviewed},
        {QStringLiteral("description"), m_description},
        {QStringLiteral("descriptionSource"), m_descriptionSource}};
    const QLabel *l = labels.value(field);
    return l ? l->text() : QString();
}

} // namespace rosarch
