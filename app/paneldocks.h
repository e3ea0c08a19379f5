#pragma once

#include <QList>
#include <QObject>

class QAction;
class QDockWidget;
class QMainWindow;
class QSize;
class QWidget;

namespace rosarch {

class ArchitectureDiffView;
class AtomicNodePanel;
class CorrectionPanel;
class DiagramFocus;
class DiagramLayouter;
class DiagramPanel;
class InspectorPanel;
class LaunchTreePanel;
class LogView;
class ParameterPanel;
class SourceView;
class SuggestionPanel;
class TalkersPanel;

/// The main window's panels and the docks they sit in: where each dock goes by default (in a
/// large and in a small window), and the layout remembered between runs.
class PanelDocks : public QObject
{
    Q_OBJECT
public:
    enum class Dock
    {
        Nodes,
        Launch,
        Diagram,
        Source,
        Log,
        Suggestions,
        Changes,
        Talkers,
        Parameters,
        Corrections,
        Inspector
    };

    /// Makes the panels and their docks in `window` and lays them out by default.
    explicit PanelDocks(QMainWindow *window);

    AtomicNodePanel *nodePanel() const { return m_nodePanel; }
    LaunchTreePanel *launchPanel() const { return m_launchPanel; }
    DiagramPanel *diagramPanel() const { return m_diagramPanel; }
    SourceView *sourceView() const { return m_sourceView; }
    LogView *logView() const { return m_logView; }
    SuggestionPanel *suggestionPanel() const { return m_suggestionPanel; }
    ArchitectureDiffView *changesView() const { return m_changesView; }
    TalkersPanel *talkersPanel() const { return m_talkersPanel; }
    ParameterPanel *parameterPanel() const { return m_parameterPanel; }
    CorrectionPanel *correctionPanel() const { return m_correctionPanel; }
    InspectorPanel *inspector() const { return m_inspector; }
    QDockWidget *dock(Dock which) const;
    /// View → Focus Diagram.
    DiagramFocus *diagramFocus() const { return m_diagramFocus; }

    /// Shows `which` in front of the docks that share its place.
    void bringForward(Dock which);
    /// The docks' show and hide actions, in the order of the View menu.
    QList<QAction *> toggleViewActions() const;

    /// Lays the docks out as on a first start, for the window's size class.
    void resetLayout();
    /// The window's geometry, dock layout and log filter of the last session; a first start
    /// gets a size fit for the screen and the default layout.
    void restoreLayout();
    /// Remembers the window's geometry, dock layout and log filter for the next session.
    void saveLayout();
    /// Whether a window of `size` gets the small layout (the Log across the bottom).
    static bool isSmallLayout(const QSize &size);

private:
    QDockWidget *addDock(QWidget *widget, const QString &title, const QString &name);
    void takeOutDock(QDockWidget *dock);
    void placeCorrectionDocks();

    QMainWindow *m_window;
    AtomicNodePanel *m_nodePanel = nullptr;
    LaunchTreePanel *m_launchPanel = nullptr;
    DiagramLayouter *m_diagramLayouter = nullptr; ///< the panel's layouts, off the UI thread
    DiagramPanel *m_diagramPanel = nullptr;
    SourceView *m_sourceView = nullptr;
    LogView *m_logView = nullptr;
    SuggestionPanel *m_suggestionPanel = nullptr;
    ArchitectureDiffView *m_changesView = nullptr;
    TalkersPanel *m_talkersPanel = nullptr;
    ParameterPanel *m_parameterPanel = nullptr;
    CorrectionPanel *m_correctionPanel = nullptr;
    InspectorPanel *m_inspector = nullptr;
    QList<QDockWidget *> m_docks; ///< indexed by Dock
    DiagramFocus *m_diagramFocus = nullptr;
};

} // namespace rosarch
