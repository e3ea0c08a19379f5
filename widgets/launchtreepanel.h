#pragma once

#include <QModelIndex>
#include <QWidget>

class QAction;
class QLabel;
class QLineEdit;
class QTreeView;

namespace rosarch {

class LaunchTreeModel;
class NodeFilterProxyModel;

/// The "Launch tree" panel: a filter field over the launch file → include → node tree.
/// Speaks in indexes of the LaunchTreeModel; the filter proxy stays inside.
class LaunchTreePanel : public QWidget
{
    Q_OBJECT
public:
    explicit LaunchTreePanel(QWidget *parent = nullptr);

    void setModel(LaunchTreeModel *model);
    LaunchTreeModel *model() const { return m_model; }
    QTreeView *treeView() const { return m_tree; }
    QLineEdit *filterEdit() const { return m_filter; }
    NodeFilterProxyModel *proxyModel() const { return m_proxy; }
    QAction *goToClassAction() const { return m_goToClass; }
    QLabel *placeholderLabel() const { return m_placeholder; }

    /// The text shown instead of the tree while it is empty (no run yet, no launch files).
    void setPlaceholderText(const QString &text);

    /// The current row as an index of the LaunchTreeModel.
    QModelIndex currentSourceIndex() const;
    /// Makes a row of the LaunchTreeModel current, clearing a filter that hides it.
    void selectSourceIndex(const QModelIndex &sourceIndex);
    void focusFilter();

Q_SIGNALS:
    /// The current row changed, as an index of the LaunchTreeModel (invalid for none).
    void currentSourceIndexChanged(const QModelIndex &sourceIndex);
    /// A person asked to see the atomic node class a node instance runs (double-click,
    /// context menu "Go to Class").
    void classRequested(const QString &classId);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void onModelReset();
    void applyFilter(const QString &text);
    void updateActions();
    void updatePlaceholder();
    QString currentClassId() const;

    LaunchTreeModel *m_model = nullptr;
    NodeFilterProxyModel *m_proxy;
    QLineEdit *m_filter;
    QTreeView *m_tree;
    QLabel *m_placeholder;
    QAction *m_goToClass;
};

} // namespace rosarch
