#pragma once

#include <QObject>

class QMainWindow;

namespace rosarch {

class Document;
class LogView;
class StageController;

/// Writes the accepted model out of the window: the artifacts (JSON and PlantUML), the NoDL
/// descriptions and the architecture site, each after asking where; a failure is explained
/// in a dialog and in the Log.
class ExportController : public QObject
{
    Q_OBJECT
public:
    ExportController(QMainWindow *window, Document *document, const StageController *stages,
                     LogView *log);

    /// File → Export Artifacts…: asks for a folder (the last one first), then exports to it.
    void exportArtifactsDialog();
    /// Writes the artifacts of the current model into `folder`; false (and a dialog) on error.
    bool exportArtifactsTo(const QString &folder);
    /// File → Export NoDL…: asks for a folder, then exports to it.
    void exportNodlDialog();
    /// Writes one NoDL description per node class of the accepted model into `folder`.
    bool exportNodlTo(const QString &folder);
    /// File → Export Architecture Site…: asks for the options, then writes the site in a
    /// worker with a progress dialog.
    void exportSiteDialog();

private:
    void showError(const QString &title, const QString &text);

    QMainWindow *m_window;
    Document *m_document;
    const StageController *m_stages;
    LogView *m_log;
};

} // namespace rosarch
