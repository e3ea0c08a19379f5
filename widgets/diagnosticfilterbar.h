#pragma once

#include "widgets/diagnosticmodel.h"

#include <QVariantMap>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QToolButton;

namespace rosarch {

/// The filter above the findings table: severity toggles, kind and package (with counts), a
/// text search, "show hidden" and "show accepted", and the grouping. It edits the model's
/// filter and grouping directly and refreshes its counts when the findings change.
class DiagnosticFilterBar : public QWidget
{
    Q_OBJECT
public:
    explicit DiagnosticFilterBar(DiagnosticModel *model, QWidget *parent = nullptr);

    QToolButton *severityButton(Diagnostic::Severity severity) const;
    QComboBox *kindCombo() const { return m_kind; }
    QComboBox *packageCombo() const { return m_package; }
    QLineEdit *searchEdit() const { return m_search; }
    QCheckBox *showHiddenBox() const { return m_hidden; }
    QCheckBox *showAcceptedBox() const { return m_accepted; }
    QComboBox *groupingCombo() const { return m_grouping; }

    /// The filter and grouping chosen, to remember between sessions (AppSettings keeps it).
    QVariantMap state() const;
    /// Chooses a remembered filter and grouping again (unknown keys are ignored).
    void restoreState(const QVariantMap &state);

private:
    void apply();
    void refreshCounts();

    DiagnosticModel *m_model;
    QToolButton *m_errors;
    QToolButton *m_warnings;
    QToolButton *m_infos;
    QComboBox *m_kind;
    QComboBox *m_package;
    QLineEdit *m_search;
    QCheckBox *m_hidden;
    QCheckBox *m_accepted;
    QComboBox *m_grouping;
};

} // namespace rosarch
