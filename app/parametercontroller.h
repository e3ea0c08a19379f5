#pragma once

#include <QObject>

namespace rosarch {

class AtomicNodeModel;
class AtomicNodePanel;
class Document;
class LaunchTreeModel;
class LaunchTreePanel;
class ParameterPanel;
class Traceability;

/// Keeps the Parameters panel on the current selection: a node instance of the launch tree
/// shows its parameters (declarations joined with the values in effect, ParameterView), a node
/// class of the node list shows what it declares. A row opens where its value is set.
class ParameterController : public QObject
{
    Q_OBJECT
public:
    ParameterController(Document *document, AtomicNodeModel *nodeModel, AtomicNodePanel *nodePanel,
                        LaunchTreeModel *launchModel, LaunchTreePanel *launchPanel,
                        ParameterPanel *panel, Traceability *traceability, QObject *parent);

private:
    void showInstance(const QModelIndex &sourceIndex);
    void showClass(const QModelIndex &sourceIndex);

    Document *m_document;
    AtomicNodeModel *m_nodeModel;
    LaunchTreeModel *m_launchModel;
    ParameterPanel *m_panel;
};

} // namespace rosarch
