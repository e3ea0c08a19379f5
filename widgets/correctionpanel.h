#pragma once

#include <QWidget>

class QAction;
class QLabel;
class QTableView;

namespace rosarch {

class CorrectionModel;

/// The "Corrections" panel: the project's corrections in a table (orphaned ones in a quiet
/// warning style, with the reason), and what can be done with them: show the element, revert
/// (remove) one, re-target an orphaned one. Forwards intent; the Document changes.
class CorrectionPanel : public QWidget
{
    Q_OBJECT
public:
    explicit CorrectionPanel(QWidget *parent = nullptr);

    void setModel(CorrectionModel *model);
    CorrectionModel *model() const { return m_model; }
    QTableView *tableView() const { return m_table; }
    QAction *removeAction() const { return m_remove; }
    QAction *retargetAction() const { return m_retarget; }
    /// The ids of the selected corrections, in table order.
    QStringList selectedIds() const;
    /// The current correction's id ("" for none).
    QString currentId() const;
    /// Makes correction `id` current, which shows its element (correctionActivated); false when
    /// it is not listed.
    bool selectCorrection(const QString &id);
    /// Makes correction `id` current without showing its element: a correction just made is
    /// listed where a person can see and revert it, while the views stay where the person is.
    bool listCorrection(const QString &id);

Q_SIGNALS:
    /// A correction became current: show its element.
    void correctionActivated(const QString &id);
    /// Revert these corrections (Delete, the Remove button or the context menu).
    void removeRequested(const QStringList &ids);
    /// Point an orphaned correction at another element.
    void retargetRequested(const QString &id);

private:
    void updateActions();
    void updatePlaceholder();

    CorrectionModel *m_model = nullptr;
    bool m_listing = false; ///< listCorrection() makes a row current: nothing is shown
    QTableView *m_table;
    QLabel *m_placeholder;
    QAction *m_remove;
    QAction *m_retarget;
};

} // namespace rosarch
