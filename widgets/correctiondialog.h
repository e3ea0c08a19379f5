#pragma once

#include "core/port.h"

#include <QDialog>
#include <QFlags>
#include <QList>
#include <QPair>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QFormLayout;
class QLabel;
class QLineEdit;

namespace rosarch {

/// The small dialog every correction asks through: what it needs (a name, a type, a port kind,
/// a choice among elements, a namespace) and, always, an optional reason. Shows only the
/// fields it is given; OK stays disabled until the required ones are filled in.
class CorrectionDialog : public QDialog
{
    Q_OBJECT
public:
    enum Field : unsigned
    {
        NoField = 0,
        Name = 1u << 0,
        Type = 1u << 1,
        Kind = 1u << 2,
        Choice = 1u << 3,
        Namespace = 1u << 4,
    };
    Q_DECLARE_FLAGS(Fields, Field)

    /// `what` says in a sentence what the correction does and to which element.
    CorrectionDialog(const QString &title, const QString &what, Fields fields,
                     QWidget *parent = nullptr);

    Fields fields() const { return m_fields; }
    QString what() const;

    void setName(const QString &name);
    QString name() const;
    void setNameLabel(const QString &label);
    void setType(const QString &type);
    QString type() const;
    /// Types to pick from (the workspace's); any other may be typed.
    void setTypeChoices(const QStringList &types);
    /// A type is required (Set Type); otherwise an empty type means unknown.
    void setTypeRequired(bool required);
    void setPortKind(PortKind kind);
    PortKind portKind() const;
    /// Limits the port kinds offered (default: all six).
    void setPortKinds(const QList<PortKind> &kinds);
    /// The elements to choose among: (shown text, value) pairs; `label` names the field.
    void setChoices(const QString &label, const QList<QPair<QString, QString>> &choices);
    /// The value of the chosen element ("" when none).
    QString choice() const;
    /// Chooses the element with `value`; false when it is not among the choices.
    bool setChoice(const QString &value);
    void setNameSpace(const QString &nameSpace);
    QString nameSpace() const;
    void setReason(const QString &reason);
    QString reason() const;

    /// Offers to do the same elsewhere too, as a check box under the fields ("Also name the 2
    /// other ports written `topic_` so"), checked to begin with.
    void setAlso(const QString &text);
    /// True when the offer of setAlso() is there and checked.
    bool also() const;
    void setAlsoChecked(bool checked);
    /// True when OK may be pressed.
    bool isComplete() const;

private:
    void updateOk();

    Fields m_fields;
    bool m_typeRequired = false;
    QLabel *m_what;
    QFormLayout *m_form;
    QLineEdit *m_name = nullptr;
    QComboBox *m_type = nullptr;
    QComboBox *m_kind = nullptr;
    QComboBox *m_choice = nullptr;
    QLineEdit *m_nameSpace = nullptr;
    QLineEdit *m_reason;
    QCheckBox *m_also = nullptr;
    QDialogButtonBox *m_buttons;
};

Q_DECLARE_OPERATORS_FOR_FLAGS(CorrectionDialog::Fields)

} // namespace rosarch
