#pragma once

#include "filteredtreepanel.h"

namespace rosarch {

class AtomicNodeModel;

/// The "Atomic nodes" panel: a filter field over the package → node → port tree.
/// Speaks in indexes of the AtomicNodeModel.
class AtomicNodePanel : public FilteredTreePanel
{
    Q_OBJECT
public:
    explicit AtomicNodePanel(QWidget *parent = nullptr);

    void setModel(AtomicNodeModel *model);
    AtomicNodeModel *model() const { return m_model; }

private:
    void onModelReset();

    AtomicNodeModel *m_model = nullptr;
};

} // namespace rosarch
