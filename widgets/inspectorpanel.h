#pragma once

#include <QList>
#include <QWidget>

class QAction;
class QFormLayout;
class QGridLayout;
class QLabel;

namespace rosarch {

/// What the inspector shows of one element.
struct InspectorInfo
{
    QString kind; ///< "Node class", "Port", "Node instance", ... ("" = nothing selected)
    QString name;
    QString type;
    QString key;        ///< the stable key
    QString provenance; ///< "recovered", "corrected by c3", "removed by c6", ...
    bool reviewed = false;
    QString corrections; ///< one line per correction that touches it
    /// Node classes and instances: what the class does, and where that comes from ("from the
    /// code", "written by a person", ...; NodeDescription::sourceText).
    bool describable = false;
    QString description; ///< "" when nothing describes it
    QString descriptionSource;
};

/// The "Inspector" panel: the selected element's kind, name, type, stable key, provenance and
/// review state, with buttons for the corrections that apply to it. Forwards intent through
/// the actions it is given.
class InspectorPanel : public QWidget
{
    Q_OBJECT
public:
    explicit InspectorPanel(QWidget *parent = nullptr);

    /// Shows `info` with a button per action; the panel takes the actions (the previous ones
    /// are deleted).
    void setElement(const InspectorInfo &info, const QList<QAction *> &actions);
    const InspectorInfo &info() const { return m_info; }
    QList<QAction *> actions() const { return m_actions; }
    /// The text of a field as shown ("kind", "name", "type", "key", "provenance", "reviewed",
    /// "description", "descriptionSource").
    QString fieldText(const QString &field) const;

private:
    InspectorInfo m_info;
    QList<QAction *> m_actions;
    QLabel *m_placeholder;
    QWidget *m_body;
    QLabel *m_kind;
    QLabel *m_name;
    QLabel *m_type;
    QLabel *m_key;
    QLabel *m_provenance;
    QLabel *m_reviewed;
    QLabel *m_corrections;
    QLabel *m_descriptionLabel; ///< the row's label
    QWidget *m_descriptionField;
    QLabel *m_description;
    QLabel *m_descriptionSource;
    QWidget *m_buttons;
    QGridLayout *m_buttonLayout;
};

} // namespace rosarch
