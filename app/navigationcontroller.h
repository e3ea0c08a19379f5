#pragma once

#include "app/navigationhistory.h"

#include <QObject>

class QAction;
class QMainWindow;
class QWidget;

namespace rosarch {

class AtomicNodePanel;
class DiagramPanel;
class Document;
class FilteredTreePanel;
class LaunchTreePanel;
class LogView;
class SourceView;

/// Back and forward over every panel: a row chosen in the node list or the launch tree, an
/// element clicked in the composed diagram (or a composite entered), a finding chosen in the
/// Log, a line the person moved to in the source. One action of the person is one place, named
/// by the panel that started it (the views that follow it are kept with it). Going back or
/// forward shows the place again in every view it was seen in, found by stable key; Alt+Left,
/// Alt+Right and the mouse's back and forward buttons step through them.
class NavigationController : public QObject
{
    Q_OBJECT
public:
    struct Panels
    {
        AtomicNodePanel *nodes = nullptr;
        LaunchTreePanel *launch = nullptr;
        DiagramPanel *diagram = nullptr;
        SourceView *source = nullptr;
        LogView *log = nullptr;
    };
    NavigationController(Document *document, const Panels &panels, QMainWindow *window);
    ~NavigationController() override;

    QAction *backAction() const { return m_back; }
    QAction *forwardAction() const { return m_forward; }
    NavigationHistory *history() const { return m_history; }

    void goBack();
    void goForward();
    /// Forgets every place (another workspace was opened).
    void clear();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    /// A panel reports a place; the places of one turn of the event loop are one visit.
    void offer(const NavigationPlace &place, int priority);
    void commit();
    /// Whether `place` is only what the current place shows already, reported by a view late.
    bool echoesCurrent(const NavigationPlace &place) const;
    /// Where the source pane stands now, into `place`.
    void snapshotSource(NavigationPlace *place) const;
    void show(const NavigationPlace &place);
    void restoreDiagram(const NavigationPlace &place);
    /// The element of `place` (when its composite is `drawn`), then the source position.
    void restoreElement(const NavigationPlace &place, bool drawn);
    /// The place is shown: what the views report from the next turn on is the person's.
    void endRestoring();
    void selectDiagramElement(const QString &element);
    void restoreSource(const NavigationPlace &place);
    /// Selects the row of `key`, or announces it again when it is current already.
    void showRow(FilteredTreePanel *panel, const QString &key);
    void raisePanel(NavigationPlace::Panel panel);
    void updateActions();

    void onTreeRow(FilteredTreePanel *panel, NavigationPlace::Panel which, int priority);
    void onDiagramElement(const QString &diagramKey);
    void onCompositeShown(const QString &instanceId);
    void onFinding();
    void onSourceLine(const QString &file, int line);

    /// The stable key of an element id, or "id:" and the id while keys are being made.
    QString keyOf(const QString &id) const;
    /// The element a stable key (or an "id:" key) names now; "" for none.
    QString idOf(const QString &key) const;
    /// What a person calls the place: "navigator (launch tree)".
    QString describe(const NavigationPlace &place) const;

    Document *m_document;
    Panels m_panels;
    QMainWindow *m_window;
    NavigationHistory *m_history;
    QAction *m_back;
    QAction *m_forward;
    NavigationPlace m_candidate; ///< the place of this turn with the highest priority so far
    int m_candidatePriority = -1;
    QString m_turnNodeKey;   ///< the node list's row chosen in this turn
    QString m_turnLaunchKey; ///< the launch tree's row chosen in this turn
    bool m_commitQueued = false;
    bool m_restoring = false;    ///< a place is shown again: what the views report is not a visit
    int m_restoreGeneration = 0; ///< counts show(); a later one keeps m_restoring on
    QMetaObject::Connection m_waitForLayout;
};

} // namespace rosarch
