#pragma once

#include "core/composition.h"
#include "core/subsystemgroup.h"
#include "evaluation/evaluation.h"
#include "widgets/talkersearch.h"

#include <QObject>

#include <QPointer>
#include <functional>

class QAction;
class QWidget;

namespace rosarch {

class DiagramPanel;
class Document;
class LaunchTreePanel;
class LogView;
class TalkersPanel;
class Traceability;

/// Wires the composed-diagram panel into the window: the Document's architecture into the
/// panel, launch tree selection into the shown composite and part, clicks in the diagram
/// back to the launch tree and the source, the talkers of a clicked topic, service, action
/// or port (and a talker back to its instance everywhere), the diagram exports, and the
/// comparison with a reference PlantUML model (extra elements marked, missing ones listed).
class DiagramController : public QObject
{
    Q_OBJECT
public:
    DiagramController(Document *document, DiagramPanel *panel, LaunchTreePanel *launchPanel,
                      Traceability *traceability, TalkersPanel *talkers, LogView *log,
                      QWidget *window);

    QAction *exportSvgAction() const { return m_exportSvg; }
    QAction *exportPngAction() const { return m_exportPng; }
    QAction *compareAction() const { return m_compare; }
    QAction *clearComparisonAction() const { return m_clearComparison; }

    /// Scores the current model against the reference at `path` (a folder or a .puml file),
    /// marks the diagram and returns the report text; "" with `error` set when unreadable.
    QString compareWithReference(const QString &path, QString *error);
    /// The evaluation of the last comparison (empty when none).
    const Evaluation &comparison() const { return m_evaluation; }
    /// Draws a pending grouping as it would look once accepted (a preview; nothing changes in
    /// the model) and shows the composite of its first member; an empty name ends the preview.
    void previewGrouping(const QString &name, const QStringList &memberIds, const QString &rootId);
    /// Writes the shown diagram; false with a message in the log on failure.
    bool exportDiagram(const QString &path);

Q_SIGNALS:
    void statusMessage(const QString &text, int timeout);
    /// The talkers panel shows the talkers of what the user just clicked.
    void talkersShown();

private:
    void onModelReset();
    /// Asks the talkers shown again of the model as it is now (after a correction).
    void refreshTalkers();
    std::function<void()> m_talkersQuery; ///< what the talkers shown answer, to ask again
    bool m_refreshingTalkers = false;
    void onLaunchItemSelected(const QString &instanceId);
    void onPartActivated(const QString &instanceId);
    void onPortActivated(const QString &instanceId, const QString &portId);
    void onElementActivated(const QString &key);
    void onClassPortSelected(const QString &classId, const QString &portId);
    void onTalkerSelected(const QString &instanceId, const QString &portId);
    void showTalkers(const QString &subject, const QString &scopeId,
                     const QList<TalkerGroup> &groups);
    void showArchitecture();
    /// Remembers a root a person chose in the diagram for this workspace.
    void rememberRoot(const QString &instanceId);
    void applyMarks();
    void exportDialog(const QString &suffix);
    void compareDialog();
    void updateActions();

    Document *m_document;
    DiagramPanel *m_panel;
    LaunchTreePanel *m_launchPanel;
    Traceability *m_traceability;
    TalkersPanel *m_talkers;
    LogView *m_log;
    QPointer<QWidget> m_window;
    QString m_pendingInstance;  ///< select once the layout of its composite is done
    bool m_fromDiagram = false; ///< a diagram click is being forwarded to the launch tree
    bool m_fromTalkers = false; ///< a talker is being selected in the other views
    Evaluation m_evaluation;
    QString m_referencePath;
    QList<SubsystemGroup> m_preview; ///< a pending grouping drawn as if accepted

    QAction *m_exportSvg;
    QAction *m_exportPng;
    QAction *m_compare;
    QAction *m_clearComparison;
};

} // namespace rosarch
