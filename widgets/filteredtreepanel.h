#pragma once

#include <QModelIndex>
#include <QWidget>

class QLineEdit;
class QTreeView;
class QVBoxLayout;

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

    /// The current row as an index of the source model.
    QModelIndex currentSourceIndex() const;
    /// Makes a row of the source model current, clearing a filter that hides it.
    void selectSourceIndex(const QModelIndex &sourceIndex);
    void focusFilter();

Q_SIGNALS:
    /// The current row changed, as an index of the source model (invalid for none).
    void currentSourceIndexChanged(const QModelIndex &sourceIndex);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    /// Expands the rows a person sees without asking (after a reset or a filter): all of them.
    virtual void expandRows();

    NodeFilterProxyModel *m_proxy;
    QLineEdit *m_filter;
    QTreeView *m_tree;
    QVBoxLayout *m_layout;

private:
    void applyFilter(const QString &text);

    QList<int> m_keptRows; ///< the current row's place, kept across a reshaping reset
};

} // namespace rosarch
