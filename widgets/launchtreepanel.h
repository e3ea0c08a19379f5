#pragma once

#include "widgets/filteredtreepanel.h"

class QAction;
class QLabel;
class QMenu;

namespace rosarch {

class LaunchTreeModel;

/// The "Launch tree" panel: a filter field over the launch file → include → node tree.
/// Speaks in indexes of the LaunchTreeModel.
class LaunchTreePanel : public FilteredTreePanel
{
    Q_OBJECT
public:
    explicit LaunchTreePanel(QWidget *parent = nullptr);

    void setModel(LaunchTreeModel *model);
    LaunchTreeModel *model() const { return m_model; }
    QAction *goToClassAction() const { return m_goToClass; }

Q_SIGNALS:
    /// A person asked to see the atomic node class a node instance runs (double-click,
    /// context menu "Go to Class").
    void classRequested(const QString &classId);
    /// A context menu is about to open on `sourceIndex` (maybe invalid): add to `menu`.
    void contextMenuRequested(QMenu *menu, const QModelIndex &sourceIndex);

protected:
    /// Not the nodes' "Parameters" rows: a navigation stack has ten thousands.
    bool isExpandable(const QModelIndex &proxyIndex) const override;
    QString stableKeyOf(const QModelIndex &sourceIndex) const override;
    QModelIndex sourceIndexOfKey(const QString &key) const override;

private:
    void onModelReset();
    void updateActions();
    QString currentClassId() const;

    LaunchTreeModel *m_model = nullptr;
    QAction *m_goToClass;
};

} // namespace rosarch
