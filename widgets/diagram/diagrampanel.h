#pragma once

#include "core/composition.h"
#include "diagram/diagrambuilder.h"
#include "diagram/graphlayout.h"
#include "diagram/rootchoice.h"
#include "jobs/jobrunner.h"
#include "widgets/diagram/diagramitem.h"

#include <QHash>
#include <QPointer>
#include <QSet>
#include <QWidget>

#include <functional>
#include <optional>

class QAction;
class QBoxLayout;
class QLabel;
class QLineEdit;
class QMenu;
class QToolBar;

namespace rosarch {

class DiagramBreadcrumbBar;
class DiagramLayouter;
class DiagramRootPicker;
class DiagramRootPrompt;
class DiagramScene;
class DiagramView;

/// The "Composed diagram" panel: one composite of the architecture, laid out by the
/// DiagramLayouter it is given (off the UI thread, cached there), with breadcrumbs down the
/// include tree, search, filters, zoom and export.
/// Element keys are DiagramBuilder's: "part:part1", "port:part1/s1", "channel:q_x",
/// "boundary:s1", "connection:3", "namespace:/robot1".
class DiagramPanel : public QWidget
{
    Q_OBJECT
public:
    /// `layouter` lays out what the panel shows.
    explicit DiagramPanel(DiagramLayouter *layouter, QWidget *parent = nullptr);
    ~DiagramPanel() override;

    /// The architecture to draw (a copy) and its roots for the header's picker (computed from
    /// the architecture when empty). Keeps the composite shown if it still exists, else starts
    /// on `start`'s root, asks which root when `start` says so, or shows the first root.
    void setArchitecture(const Architecture &architecture, const QList<LaunchRoot> &roots = {},
                         const RootChoice &start = {});
    const Architecture &architecture() const { return m_architecture; }
    /// Gives the text a node part's tooltip ends with: what its class (by id) does and where
    /// that comes from, or "No description in the code".
    void setDescriber(const std::function<QString(const QString &classId)> &describer);
    /// What the panel says while the architecture has no composite (no run yet, no launch
    /// file to compose, a run stopped before a result).
    void setEmptyText(const QString &text);
    /// Shows a composite by its launch-file instance id; the breadcrumbs follow its parents.
    void showComposite(const QString &instanceId);
    QString currentComposite() const { return m_current; }
    /// The instance ids on the breadcrumb bar, root first.
    QStringList breadcrumbIds() const;

    DiagramOptions options() const { return m_options; }
    void setOptions(const DiagramOptions &options);
    /// Draws a namespace of the current composite as one box, or as its parts again.
    void setNamespaceCollapsed(const QString &nameSpace, bool collapsed);
    bool isNamespaceCollapsed(const QString &nameSpace) const;
    /// Draws a part of the current composite without its port rows, or with them again.
    void setPartCompact(const QString &partId, bool compact);
    bool isPartCompact(const QString &partId) const;
    /// Draws the boundary ports of the current composite as one box per side, or each again.
    void setBoundaryCollapsed(bool collapsed);
    bool isBoundaryCollapsed() const { return m_boundaryCollapsed.contains(m_current); }
    /// The current composite as an overview: namespaces collapsed, parts without ports.
    void showOverview();
    /// Every namespace and part of the current composite drawn in full.
    void expandAll();
    /// True when something of the current composite is collapsed.
    bool isCollapsed() const;
    /// Text on screen is at least this tall at fit zoom (points).
    static constexpr double kLegiblePoints = 7.0;
    /// The zoom at which the diagram's names are kLegiblePoints tall.
    qreal legibleZoom() const;
    /// Lists the roots instead of a diagram for a person to choose one.
    void askForRoot();
    bool isAskingForRoot() const;

    /// Marks for a reference comparison of the current composite (cleared when another is
    /// shown), and the reference elements missing from it, listed in a banner.
    void setMarks(const QHash<QString, DiagramMark> &marks, const QStringList &missing = {});

    /// The whole current diagram, light paper, for documentation.
    bool exportSvg(const QString &path);
    bool exportPng(const QString &path);

    /// True while the diagram of what the panel should show is still being built or laid out.
    bool isLayingOut() const { return m_pending || m_building; }
    /// True while the layout graph of a big composite is built off the UI thread.
    bool isBuilding() const { return m_building; }
    /// Composites with more elements (parts, channels, boundary ports, connections) than this
    /// are built off the UI thread; smaller ones take well under a millisecond inline.
    static constexpr int kInlineBuildElements = 300;
    /// Graphs with more boxes are not laid out: Graphviz 2.4x took 40 s for 600 boxes (one
    /// root including 3,000 launch files, as its overview); the panel says so instead.
    static constexpr int kMaxLayoutNodes = 400;
    /// The text shown instead of a drawing (errors, empty states); "" while a diagram shows.
    QString message() const;
    qint64 lastLayoutMs() const { return m_lastLayoutMs; }
    /// The context-menu actions for an element (collapse/expand a namespace, open an include).
    QList<QAction *> elementActions(const QString &key);
    /// The keys of the selected elements of the shown composite, sorted.
    QStringList selectedKeys() const;
    /// Selects and centres an element of the shown composite by its key.
    void selectElement(const QString &key);
    /// Selects and centres an element and tells the window, as a click on it does.
    void activateElement(const QString &key);

    DiagramScene *scene() const { return m_scene; }
    DiagramView *view() const { return m_view; }
    DiagramBreadcrumbBar *breadcrumbBar() const { return m_breadcrumbs; }
    DiagramRootPicker *rootPicker() const { return m_rootPicker; }
    DiagramRootPrompt *rootPrompt() const { return m_rootPrompt; }
    QAction *overviewAction() const { return m_overviewAction; }
    QAction *expandAllAction() const { return m_expandAllAction; }
    QLineEdit *searchField() const { return m_search; }
    /// Where the search stands: "3 of 7", "No match", or "" without a search.
    QString matchText() const;
    QAction *showParametersAction() const { return m_showParameters; }
    QAction *showInactiveAction() const { return m_showInactive; }
    QAction *showExternalAction() const { return m_showExternal; }
    /// The toolbar's "Export…" (a file dialog); hide it when the window offers its own.
    QAction *exportAction() const { return m_exportAction; }

public Q_SLOTS:
    /// Highlights and centres the part of a node (or launch-file) instance, if it is drawn.
    bool selectInstance(const QString &instanceId);
    /// Selects and centres the next search match.
    void findNext();
    void focusSearch();

Q_SIGNALS:
    /// A part, or a connection at its part's end, was clicked: its node or launch-file
    /// instance id.
    void partActivated(const QString &instanceId);
    void portActivated(const QString &instanceId, const QString &portId);
    /// Where the clicked element comes from: a part's launch line, a port's (or a
    /// connection's port's) creation in code.
    void evidenceActivated(const rosarch::Evidence &evidence);
    /// Any element of the current composite was clicked (after partActivated and
    /// portActivated, before evidenceActivated): its key.
    void elementActivated(const QString &key);
    void compositeShown(const QString &instanceId);
    /// A person chose the root to show, in the header's picker or when asked.
    void rootChosen(const QString &instanceId);
    /// A context menu is about to open on the element `key` ("" for none): add to `menu`.
    void elementMenuRequested(const QString &key, QMenu *menu);
    /// A layout finished and the scene shows it (ok), or the message says why not.
    void layoutFinished(bool ok);

protected:
    void changeEvent(QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    /// A composite's layout graph and its DOT text, and what the overview check decided.
    struct Built
    {
        LayoutGraph graph;
        QString dot;
        std::optional<DiagramOptions> overview; ///< switched to these (first view) options
    };
    /// The fonts of the drawing as text: a worker builds its own QFonts from them (a QFont
    /// shared with the UI thread caches its engine there).
    struct Fonts
    {
        QString title, text, small;
    };

    const Composite *composite() const;
    DiagramMetrics metrics() const;
    static DiagramMetrics metrics(const Fonts &fonts);
    /// Builds the graph of `composite` (pure; runs on any thread). When its boxes alone cover
    /// more than `overviewArea` (points², < 0 for no check), it cannot be read at the legible
    /// zoom: then the graph is that of the first DiagramFirstView step after `options` whose
    /// boxes fit, built from `base` (the filters), else of the overview.
    static Built build(const Composite &composite, const DiagramOptions &options,
                       const DiagramOptions &base, const DiagramMetrics &metrics,
                       double overviewArea);
    void relayout();
    /// Takes a built graph on: the overview decision, then the layout (cached or started).
    void onBuilt(const Built &built);
    void applyLayout(const LayoutGraph &graph, const LayoutResult &result, bool fit);
    void showMessage(const QString &text);
    void updateBreadcrumbs();
    void updateSearch(bool centre);
    void selectKey(const QString &key);
    /// The key of what draws `part`: its box, or the collapsed namespace around it.
    QString drawnKey(const RosNodePart &part) const;
    void onElementClicked(const QString &key);
    void onElementDoubleClicked(const QString &key);
    void onContextMenu(const QString &key, const QPoint &screenPos);
    void onFilterToggled();
    void onRootChosen(const QString &instanceId);
    /// The options for the current composite: filters, collapsed namespaces, compact parts.
    DiagramOptions currentOptions() const;
    /// Draws less of the current composite when it is first shown too big to read at the
    /// legible zoom (the next DiagramFirstView step that should fit); true when it does (the
    /// caller lays out again).
    bool overviewInstead(const QSizeF &size);
    /// Collapses what `options` collapse in the current composite.
    void setCollapse(const DiagramOptions &options);
    /// Keeps an element where it was in the view after it is expanded, and all of it in view
    /// when it fits.
    void keepInView(const QString &key);
    /// Moves the view onto an element expanded in place, once it is drawn.
    void showExpanded(const DiagramItem &item);

    /// A first view tries at most this many steps to find one that can be read.
    static constexpr int kFirstViewTries = 3;

    QString m_emptyText;
    Architecture m_architecture;
    QString m_current;
    DiagramOptions m_options;
    QHash<QString, QStringList> m_collapsed; // per composite
    QHash<QString, QStringList> m_compact;   // per composite: parts drawn without ports
    QSet<QString> m_boundaryCollapsed;       ///< composites whose boundary is one box per side
    QSet<QString> m_sizeChecked;             ///< composites whose size was checked for the overview
    QHash<QString, QHash<int, qreal>> m_firstViewFits; ///< first view steps tried: fit zoom
    double m_lastBoxArea = 0;                          ///< of the graph built last (points²)
    double m_retryArea = -1; ///< the box area a first view laid out again needs
    QString m_expanded;      ///< the element expanded, kept in view once drawn
    QPointF m_expandedAt;    ///< where its corner was in the viewport
    QList<LaunchRoot> m_roots;
    QHash<QString, DiagramMark> m_marks;
    QStringList m_missing;
    QStringList m_matches;
    int m_matchIndex = -1;
    QPointer<DiagramLayouter> m_layouter; ///< may go first when both belong to one window
    bool m_pending = false;               ///< a layout runs
    bool m_building = false;              ///< a graph is built on m_builds
    int m_buildGeneration = 0;            ///< builds that finish under an older number are dropped
    bool m_fitPending = true;
    qint64 m_lastLayoutMs = 0;

    DiagramRootPicker *m_rootPicker;
    DiagramBreadcrumbBar *m_breadcrumbs;
    DiagramRootPrompt *m_rootPrompt;
    QAction *m_overviewAction = nullptr;
    QAction *m_expandAllAction = nullptr;
    QToolBar *m_toolBar; ///< search and filters
    QToolBar *m_viewBar; ///< zoom, fit, overview, export
    QBoxLayout *m_tools; ///< the two bars in a row, or one above the other when narrow
    QLineEdit *m_search;
    std::function<QString(const QString &)> m_describer;
    QLabel *m_matchCount = nullptr; ///< beside the search field
    QAction *m_showParameters;
    QAction *m_showInactive;
    QAction *m_showExternal;
    QAction *m_exportAction;
    DiagramScene *m_scene;
    DiagramView *m_view;
    JobRunner m_builds; ///< last: destroyed first, it waits for a build still running
};

} // namespace rosarch
