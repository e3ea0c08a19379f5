#pragma once

#include "diff/architecturediff.h"

#include <QWidget>

class QLabel;
class QTreeWidget;

namespace rosarch {

/// What changed between two recoveries, as a tree: one group per node class or launch file,
/// one row per change, marked + (added), − (removed) and ~ (changed or renamed) and coloured
/// to match, with before and after in the tooltip. A summary line says what was compared.
class ArchitectureDiffView : public QWidget
{
    Q_OBJECT
public:
    explicit ArchitectureDiffView(QWidget *parent = nullptr);

    /// Shows `changes` from `before` to `after` (labels for a person: a folder, a revision).
    void setChanges(const QList<ArchitectureChange> &changes, const QString &before,
                    const QString &after);
    /// A message instead of changes (comparing, or what went wrong).
    void setMessage(const QString &message);

    QTreeWidget *tree() const { return m_tree; }
    QString summary() const;

Q_SIGNALS:
    /// A person made the row of `change` current: show what it is about.
    void changeSelected(const rosarch::ArchitectureChange &change);

private:
    QList<ArchitectureChange> m_changes; ///< the rows' changes, by the index in their data
    QLabel *m_summary;
    QTreeWidget *m_tree;
};

} // namespace rosarch
