#pragma once

#include "project/correction.h"
#include "widgets/correctionindex.h"
#include "widgets/inspectorpanel.h"

#include <QObject>
#include <QPointer>

#include <functional>

class QAction;
class QMenu;
class QWidget;

namespace rosarch {

class AtomicNodePanel;
class CorrectionDialog;
class CorrectionPanel;
class DiagramPanel;
class Document;
class LaunchTreePanel;
class Traceability;

/// Corrections where the element is: builds the context-menu entries and keyboard
/// actions of the node list, the launch tree and the diagram, asks what a correction needs in
/// a CorrectionDialog and hands it to the Document (undoable); keeps the inspector on the
/// selected element and wires the Corrections panel (show, revert, re-target).
class CorrectionController : public QObject
{
    Q_OBJECT
public:
    /// An element the views show, by the id of the corrected model ("arc_3", "arc_3/p1", "n3",
    /// "lf2", "topic:/scan"); a connection is an instance id and its port ("arc_2/p1").
    struct Element
    {
        enum class Kind
        {
            None,
            Class,
            Port,
            Instance,
            LaunchFile,
            Channel,
            Connection
        };
        Kind kind = Kind::None;
        QString id;
        QString port;   ///< Connection: the class port ("arc_2/p1")
        QString rootId; ///< Instance from the diagram: the root launch-file instance shown
        bool operator==(const Element &) const = default;
    };

    CorrectionController(Document *document, AtomicNodePanel *nodePanel,
                         LaunchTreePanel *launchPanel, DiagramPanel *diagramPanel,
                         Traceability *traceability, InspectorPanel *inspector,
                         CorrectionPanel *corrections, QWidget *window);

    /// Replaces the modal dialog (tests): called with the dialog filled in as a person would
    /// see it; returning true accepts it.
    void setDialogHandler(std::function<bool(CorrectionDialog &)> handler);

    /// The element the inspector shows (the last one selected in any view).
    const Element &current() const { return m_current; }
    void setCurrent(const Element &element);
    /// The correction actions for `element`, parented to `parent` (menus and the inspector).
    QList<QAction *> actionsFor(const Element &element, QObject *parent);
    /// What the inspector shows for `element`.
    InspectorInfo describe(const Element &element);
    /// Fills the description of class `classId` in effect, and its source, into `info`.
    void describeClass(InspectorInfo &info, const QString &classId) const;

    // Each asks through a dialog and pushes one undoable correction; false when cancelled or
    // not applicable.
    bool rename(const Element &element);
    bool setType(const Element &element);
    bool remove(const Element &element);
    bool addPort(const Element &classElement);
    bool addPart(const Element &launchFile);
    bool addConnection(const Element &instance);
    /// Marks reviewed at once (no dialog); again on a reviewed element removes the mark.
    bool toggleReviewed(const Element &element);
    /// Groups node instances (ids) of one root launch-file instance into a named subsystem.
    bool group(const QStringList &instanceIds, const QString &rootId);
    /// Reverts the correction that removed `element`.
    bool restore(const Element &element);
    /// Replaces an orphaned correction by one naming another element of its family.
    bool retarget(const QString &correctionId);
    /// Selects the element of correction `id` in the views.
    void showCorrection(const QString &id);

    /// The diagram element `key` ("part:part1", "channel:q_x", "connection:3") of the shown
    /// composite as an Element.
    Element diagramElement(const QString &key) const;

Q_SIGNALS:
    void statusMessage(const QString &text, int timeout);

private:
    const CorrectionIndex &index();
    bool ask(CorrectionDialog &dialog);
    bool push(Correction c);
    /// The other unresolved ports of a port's class whose name is written as its is.
    QStringList twinPorts(const QString &portId);
    QString keyOf(const QString &id);
    /// True when keyOf(id) answers without waiting for the keys of a large model (made on a
    /// thread of their own after each recovery): the inspector does not wait for them.
    bool keysAtHand(const QString &id);
    QString nameOf(const Element &element);
    bool isRemoved(const Element &element);
    QStringList knownTypes();
    void installShortcuts();
    void refreshInspector();
    Element nodeElement(const QModelIndex &sourceIndex) const;
    Element launchElement(const QModelIndex &sourceIndex) const;
    void addMenuActions(QMenu *menu, const Element &element);

    Document *m_document;
    AtomicNodePanel *m_nodePanel;
    LaunchTreePanel *m_launchPanel;
    DiagramPanel *m_diagramPanel;
    Traceability *m_traceability;
    InspectorPanel *m_inspector;
    CorrectionPanel *m_corrections;
    QPointer<QWidget> m_window;
    std::function<bool(CorrectionDialog &)> m_dialogHandler;
    Element m_current;
    std::optional<CorrectionIndex> m_index; ///< until the Document changes
};

} // namespace rosarch
