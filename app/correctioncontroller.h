#pragma once

#include "app/correctionelement.h"

#include <QList>
#include <QObject>

class QAction;
class QMenu;
class QWidget;

namespace rosarch {

class AtomicNodePanel;
class CorrectionEditor;
class CorrectionPanel;
class CorrectionTargets;
class DiagramPanel;
class Document;
class InspectorPanel;
class InspectorPresenter;
class LaunchTreePanel;
class Traceability;

/// Puts corrections where the element is: the context menus, keys and Corrections panel.
class CorrectionController : public QObject
{
    Q_OBJECT
public:
    using Element = CorrectionElement;

    CorrectionController(Document *document, AtomicNodePanel *nodePanel,
                         LaunchTreePanel *launchPanel, DiagramPanel *diagramPanel,
                         Traceability *traceability, InspectorPanel *inspector,
                         CorrectionPanel *corrections, QWidget *window);

    /// Asks for and pushes the corrections.
    CorrectionEditor *editor() const { return m_editor; }
    /// Keeps the inspector on the selected element.
    InspectorPresenter *presenter() const { return m_presenter; }

    /// The correction actions for `element`, parented to `parent` (menus and the inspector).
    QList<QAction *> actionsFor(const Element &element, QObject *parent);
    /// Selects the element of correction `id` in the views.
    void showCorrection(const QString &id);

    /// The element the inspector shows (the Model menu acts on it).
    const Element &current() const;

Q_SIGNALS:
    void statusMessage(const QString &text, int timeout);

private:
    void installShortcuts();
    void addMenuActions(QMenu *menu, const Element &element);

    Document *m_document;
    AtomicNodePanel *m_nodePanel;
    LaunchTreePanel *m_launchPanel;
    DiagramPanel *m_diagramPanel;
    Traceability *m_traceability;
    CorrectionTargets *m_targets;
    CorrectionEditor *m_editor;
    InspectorPresenter *m_presenter;
};

} // namespace rosarch
