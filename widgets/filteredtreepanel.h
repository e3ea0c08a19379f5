#pragma once

#include <QModelIndex>
#include <QSet>
#include <QWidget>

class QLineEdit;
class QTreeView;
class QVBoxLayout;

class QLabel;

namespace rosarch {

class NodeFilterProxyModel;

/// A filter field over a tree view, speaking in indexes of the source model: the filter proxy
/// stays inside. The common part of the atomic node and launch tree panels.
class FilteredTreePanel : public QWidget
{
    Q_OBJECT
public:
    explicit FilteredTreePanel(QWidget *parent = nullptr);

    QTreeView *treeView() const { return m_tree; }
    QLineEdit *filterEdit() const { return m_filter; }
    NodeFilterProxyModel *proxyModel() const { return m_proxy; }

    /// The text shown instead of the tree while it is empty (no run yet, nothing found, a run
    /// stopped before a result).
    void setPlaceholderText(const QString &text);
    QLabel *placeholderLabel() const { return m_placeholder; }

    /// The current row as an index of the source model.
    QModelIndex currentSourceIndex() const;
    /// Makes a row of the source model current, clearing a filter that hides it.
    void selectSourceIndex(const QModelIndex &sourceIndex);
    /// The stable key of the current row (blueprint §5); "" for none.
    QString currentStableKey() const;
    /// Makes the row of a stable key current as selectSourceIndex() does; false when no row
    /// has that key now.
    bool selectStableKey(const QString &key);
    void focusFilter();

Q_SIGNALS:
    /// The current row changed, as an index of the source model (invalid for none).
    void currentSourceIndexChanged(const QModelIndex &sourceIndex);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    /// Expands the rows a person sees without asking (after a filter): with a filter, every
    /// row that matches; without, the top of the tree (expandTop).
    virtual void expandRows();
    /// Expands every row (that isExpandable), making them all: "Expand All".
    void expandAllRows();
    /// Expands the top of the tree, breadth first, while fewer than kExpandBudget rows show:
    /// a small workspace opens fully, a large one as far as a screen or two, so a new result
    /// costs the same on any system size.
    void expandTop();
    /// Whether expanding opens `proxyIndex` (a launch tree's "Parameters" row does not).
    virtual bool isExpandable(const QModelIndex &proxyIndex) const;
    /// The stable key of a row of the source model (blueprint §5), by which the current row is
    /// found again when a correction reshapes the rows; "" when the row has none (it is then
    /// found by the names on the way to it).
    virtual QString stableKeyOf(const QModelIndex &sourceIndex) const;
    /// The row of the source model stableKeyOf() gave `key`; invalid when there is none now.
    virtual QModelIndex sourceIndexOfKey(const QString &key) const;

    static constexpr int kExpandBudget = 400;

    /// Shows the placeholder instead of the tree while the source model has no rows;
    /// subclasses call it when their model is reset.
    void updatePlaceholder();

    NodeFilterProxyModel *m_proxy;
    QLineEdit *m_filter;
    QTreeView *m_tree;
    QVBoxLayout *m_layout;
    QLabel *m_placeholder;

private:
    /// With a filter: opens the way to every row that matches (the rows kept only because a
    /// descendant matches), then the matching rows themselves, breadth first, while fewer
    /// than kExpandBudget rows show. Expanding every kept row of a large tree (a one-letter
    /// filter keeps most of navigation2's launch tree) froze the window for seconds.
    void expandToMatches();

    /// The key of a row: the names of the rows from the root down to it.
    QString rowKey(const QModelIndex &proxyIndex) const;
    void rememberExpanded();
    void restoreExpanded();

    /// The current row and the scrolled place, kept across a reshaping reset.
    struct Kept
    {
        bool valid = false;
        QString key;       ///< stableKeyOf() the current row
        QStringList names; ///< without a key: the names from the root down to it
        int scroll = 0;
    };
    Kept m_kept;
    bool m_restoring = false; ///< the kept row is made current again: not a change to announce
    void keepCurrent();
    void restoreCurrent();
    QModelIndex sourceIndexOfNames(const QStringList &names) const;
    QSet<QString> m_expanded; ///< the expanded rows by key, kept across a reset
};

} // namespace rosarch
