#include "widgets/correctiondialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCompleter>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace rosarch {

namespace {
QString kindText(PortKind kind)
{
    switch (kind) {
    case PortKind::Publisher:
        return CorrectionDialog::tr("Publisher");
    case PortKind::Subscriber:
        return CorrectionDialog::tr("Subscriber");
    case PortKind::ServiceServer:
        return CorrectionDialog::tr("Service server");
    case PortKind::ServiceClient:
        return CorrectionDialog::tr("Service client");
    case PortKind::ActionServer:
        return CorrectionDialog::tr("Action server");
    case PortKind::ActionClient:
        return CorrectionDialog::tr("Action client");
    }
    return {};
}
} // namespace

CorrectionDialog::CorrectionDialog(const QString &title, const QString &what, Fields fields,
                                   QWidget *parent)
    : QDialog(parent), m_fields(fields), m_what(new QLabel(what, this)), m_form(new QFormLayout),
      m_reason(new QLineEdit(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setWindowTitle(title);
    m_what->setWordWrap(true);
    m_what->setTextFormat(Qt::PlainText);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_what);
    layout->addLayout(m_form);
    if (fields & Name) {
        m_name = new QLineEdit(this);
        m_form->addRow(tr("&Name:"), m_name);
        connect(m_name, &QLineEdit::textChanged, this, &CorrectionDialog::updateOk);
    }
    if (fields & Kind) {
        m_kind = new QComboBox(this);
        setPortKinds({PortKind::Publisher, PortKind::Subscriber, PortKind::ServiceServer,
                      PortKind::ServiceClient, PortKind::ActionServer, PortKind::ActionClient});
        m_form->addRow(tr("&Kind:"), m_kind);
    }
    if (fields & Type) {
        m_type = new QComboBox(this);
        m_type->setEditable(true);
        m_type->setInsertPolicy(QComboBox::NoInsert);
        m_type->lineEdit()->setPlaceholderText(tr("package/msg/Type"));
        m_type->completer()->setFilterMode(Qt::MatchContains);
        m_type->completer()->setCaseSensitivity(Qt::CaseInsensitive);
        m_form->addRow(tr("&Type:"), m_type);
        connect(m_type, &QComboBox::currentTextChanged, this, &CorrectionDialog::updateOk);
    }
    if (fields & Choice) {
        m_choice = new QComboBox(this);
        m_choice->setEditable(true); // type to filter a long list
        m_choice->setInsertPolicy(QComboBox::NoInsert);
        m_choice->completer()->setFilterMode(Qt::MatchContains);
        m_choice->completer()->setCaseSensitivity(Qt::CaseInsensitive);
        m_choice->completer()->setCompletionMode(QCompleter::PopupCompletion);
        m_form->addRow(tr("&Element:"), m_choice);
        connect(m_choice, &QComboBox::currentTextChanged, this, &CorrectionDialog::updateOk);
    }
    if (fields & Namespace) {
        m_nameSpace = new QLineEdit(this);
        m_nameSpace->setPlaceholderText(tr("as the launch file's other nodes"));
        m_form->addRow(tr("Name&space:"), m_nameSpace);
    }
    m_reason->setPlaceholderText(tr("optional: why (kept in the project)"));
    m_form->addRow(tr("&Reason:"), m_reason);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    setMinimumWidth(440);
    updateOk();
}

QString CorrectionDialog::what() const
{
    return m_what->text();
}

void CorrectionDialog::setName(const QString &name)
{
    if (m_name) {
        m_name->setText(name);
        m_name->selectAll();
        m_name->setFocus(); // F2 and type: the name, not the reason (created first)
    }
}

QString CorrectionDialog::name() const
{
    return m_name ? m_name->text().trimmed() : QString();
}

void CorrectionDialog::setNameLabel(const QString &label)
{
    if (m_name)
        if (auto *l = qobject_cast<QLabel *>(m_form->labelForField(m_name)))
            l->setText(label);
}

void CorrectionDialog::setType(const QString &type)
{
    if (m_type)
        m_type->setCurrentText(type);
}

QString CorrectionDialog::type() const
{
    return m_type ? m_type->currentText().trimmed() : QString();
}

void CorrectionDialog::setTypeChoices(const QStringList &types)
{
    if (!m_type)
        return;
    const QString current = m_type->currentText();
    m_type->clear();
    m_type->addItems(types);
    m_type->setCurrentText(current);
}

void CorrectionDialog::setTypeRequired(bool required)
{
    m_typeRequired = required;
    updateOk();
}

void CorrectionDialog::setPortKind(PortKind kind)
{
    if (m_kind)
        m_kind->setCurrentIndex(std::max(0, m_kind->findData(int(kind))));
}

PortKind CorrectionDialog::portKind() const
{
    return m_kind ? PortKind(m_kind->currentData().toInt()) : PortKind::Publisher;
}

void CorrectionDialog::setPortKinds(const QList<PortKind> &kinds)
{
    if (!m_kind)
        return;
    m_kind->clear();
    for (PortKind k : kinds)
        m_kind->addItem(kindText(k), int(k));
}

void CorrectionDialog::setChoices(const QString &label,
                                  const QList<QPair<QString, QString>> &choices)
{
    if (!m_choice)
        return;
    if (auto *l = qobject_cast<QLabel *>(m_form->labelForField(m_choice)))
        l->setText(label);
    m_choice->clear();
    for (const auto &[text, value] : choices)
        m_choice->addItem(text, value);
    updateOk();
}

QString CorrectionDialog::choice() const
{
    if (!m_choice)
        return {};
    // the typed text must name one of the choices
    const int i = m_choice->findText(m_choice->currentText());
    return i < 0 ? QString() : m_choice->itemData(i).toString();
}

bool CorrectionDialog::setChoice(const QString &value)
{
    const int i = m_choice ? m_choice->findData(value) : -1;
    if (i < 0)
        return false;
    m_choice->setCurrentIndex(i);
    return true;
}

void CorrectionDialog::setNameSpace(const QString &nameSpace)
{
    if (m_nameSpace)
        m_nameSpace->setText(nameSpace);
}

QString CorrectionDialog::nameSpace() const
{
    return m_nameSpace ? m_nameSpace->text().trimmed() : QString();
}

void CorrectionDialog::setReason(const QString &reason)
{
    m_reason->setText(reason);
}

QString CorrectionDialog::reason() const
{
    return m_reason->text().trimmed();
}

void CorrectionDialog::setAlso(const QString &text)
{
    if (!m_also) {
        m_also = new QCheckBox(this);
        m_also->setChecked(true);
        m_form->addRow(QString(), m_also);
    }
    m_also->setText(text);
}

bool CorrectionDialog::also() const
{
    return m_also && m_also->isChecked();
}

void CorrectionDialog::setAlsoChecked(bool checked)
{
    if (m_also)
        m_also->setChecked(checked);
}

bool CorrectionDialog::isComplete() const
{
    if (m_name && name().isEmpty())
        return false;
    if (m_type && m_typeRequired && type().isEmpty())
        return false;
    return !m_choice || !choice().isEmpty();
}

void CorrectionDialog::updateOk()
{
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(isComplete());
}

} // namespace rosarch
