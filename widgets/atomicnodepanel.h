#pragma once

#include <QModelIndex>
#include <QWidget>

class QLineEdit;
class QTreeView;

namespace rosarch {

class AtomicNodeModel;
class NodeFilterProxyModel;

/// The "Atomic nodes" panel: a filter field over the package → node → port tree.
/// Speaks in indexes of the AtomicNodeModel; the filter proxy stays inside.
class AtomicNodePanel : public QWidget
{
    Q_OBJECT
public:
    explicit AtomicNodePanel(QWidget *parent = nullptr);

    void setModel(AtomicNodeModel *model);
    AtomicNodeModel *model() const { return m_model; }
    QTreeView *treeView() const { return m_tree; }
    QLineEdit *filterEdit() const { return m_filter; }
    NodeFilterProxyModel *proxyModel() const { return m_proxy; }

    /// The current row as an index of the AtomicNodeModel.
    QModelIndex currentSourceIndex() const;
    /// Makes a row of the AtomicNodeModel current, clearing a filter that hides it.
    void selectSourceIndex(const QModelIndex &sourceIndex);
    /// Focuses the filter field and selects its text (Find).
    void focusFilter();

Q_SIGNALS:
    /// The current row changed, as an index of the AtomicNodeModel (invalid for none).
    void currentSourceIndexChanged(const QModelIndex &sourceIndex);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void onModelReset();
    void applyFilter(const QString &text);

    AtomicNodeModel *m_model = nullptr;
    NodeFilterProxyModel *m_proxy;
    QLineEdit *m_filter;
    QTreeView *m_tree;
};

} // namespace rosarch
