#pragma once

#include "core/evidence.h"
#include "widgets/filteredtreepanel.h"

class QMenu;

namespace rosarch {

class AtomicNodeModel;

/// The "Atomic nodes" panel: a filter field over the package → node → port tree, with each
/// node's declared parameters under a "Parameters" row. Speaks in indexes of the
/// AtomicNodeModel.
class AtomicNodePanel : public FilteredTreePanel
{
    Q_OBJECT
public:
    explicit AtomicNodePanel(QWidget *parent = nullptr);

    void setModel(AtomicNodeModel *model);
    AtomicNodeModel *model() const { return m_model; }

    /// Adds to `menu` one entry per step from the node to the port at `sourceIndex` (a port
    /// made through helpers), each asking to show its place; nothing for other rows.
    void addChainActions(QMenu *menu, const QModelIndex &sourceIndex);

Q_SIGNALS:
    /// The person asked to see a place in the source: a call site on the way from the node to
    /// a port made by a helper, the call that creates it, or (double-click, Enter) the
    /// creation of a port or the declaration of a parameter.
    void evidenceRequested(const Evidence &evidence);
    /// A context menu is about to open on `sourceIndex` (maybe invalid): add to `menu`.
    void contextMenuRequested(QMenu *menu, const QModelIndex &sourceIndex);
    /// F2 on a port: rename it (a correction).
    void renameRequested(const QModelIndex &sourceIndex);

protected:
    /// A "Parameters" row opens when a person asks, or when the filter matches a parameter
    /// in it: navigation2's classes declare thousands.
    bool isExpandable(const QModelIndex &proxyIndex) const override;
    /// With the filter cleared, the "Parameters" rows it opened close again (all but the one
    /// holding the current row): else a short search leaves thousands of rows open.
    void expandRows() override;
    QString stableKeyOf(const QModelIndex &sourceIndex) const override;
    QModelIndex sourceIndexOfKey(const QString &key) const override;

private:
    void onModelReset();
    void showContextMenu(const QPoint &at);

    AtomicNodeModel *m_model = nullptr;
    QAction *m_editDescription = nullptr;
};

} // namespace rosarch
