#pragma once

#include "app/correctionelement.h"
#include "widgets/inspectorpanel.h"

#include <QList>
#include <QObject>

#include <functional>

class QAction;
class QModelIndex;

namespace rosarch {

class AtomicNodePanel;
class CorrectionTargets;
class DiagramPanel;
class Document;
class LaunchTreePanel;

/// Keeps the inspector on the element last selected in the node list, launch tree or diagram.
class InspectorPresenter : public QObject
{
    Q_OBJECT
public:
    /// The correction actions the inspector offers for an element, parented to the given object.
    using Actions = std::function<QList<QAction *>(const CorrectionElement &, QObject *)>;

    InspectorPresenter(Document *document, CorrectionTargets *targets, AtomicNodePanel *nodePanel,
                       LaunchTreePanel *launchPanel, DiagramPanel *diagramPanel,
                       InspectorPanel *inspector, QObject *parent);

    /// Where the inspector's actions come from (none until set).
    void setActions(Actions actions);
    /// The element the inspector shows (the last one selected in any view).
    const CorrectionElement &current() const { return m_current; }
    void setCurrent(const CorrectionElement &element);
    /// Shows the current element again, as the model and its corrections are now.
    void refreshInspector();
    /// What the inspector shows for `element`.
    InspectorInfo describe(const CorrectionElement &element);
    /// Fills the description of class `classId` in effect, and its source, into `info`.
    void describeClass(InspectorInfo &info, const QString &classId) const;

    /// The element of a row of the node list's model.
    CorrectionElement nodeElement(const QModelIndex &sourceIndex) const;
    /// The element of a row of the launch tree's model.
    CorrectionElement launchElement(const QModelIndex &sourceIndex) const;
    /// The diagram element `key` ("part:part1", "channel:q_x", "connection:3") of the shown
    /// composite as an element.
    CorrectionElement diagramElement(const QString &key) const;

private:
    Document *m_document;
    CorrectionTargets *m_targets;
    AtomicNodePanel *m_nodePanel;
    LaunchTreePanel *m_launchPanel;
    DiagramPanel *m_diagramPanel;
    InspectorPanel *m_inspector;
    Actions m_actions;
    CorrectionElement m_current;
};

} // namespace rosarch
