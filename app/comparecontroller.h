#pragma once

#include "diff/architecturediff.h"
#include "jobs/jobrunner.h"

#include <QObject>

class QAction;
class QDockWidget;
class QWidget;

namespace rosarch {

class ArchitectureDiffView;
class Document;
class LogView;

/// File › Compare Architecture: the model as shown (with accepted decisions) against an
/// earlier recovery, an artifact folder or a workspace, or against a git revision of the open
/// workspace; the other side is read or recovered off the UI thread, and the changes appear
/// in the Architecture Changes dock (ArchitectureDiffView).
class CompareController : public QObject
{
    Q_OBJECT
public:
    CompareController(Document *document, ArchitectureDiffView *view, QDockWidget *dock,
                      LogView *log, QWidget *window);

    QAction *compareFolderAction() const { return m_folderAction; }
    QAction *compareRevisionAction() const { return m_revisionAction; }

    /// Compares with an artifact folder `rosarch recover` wrote, or a workspace to recover.
    void compareWithFolder(const QString &folder);
    /// Compares with the open workspace as it was at a git revision.
    void compareWithRevision(const QString &revision);
    bool isRunning() const { return m_jobs.isRunning(); }
    const QList<ArchitectureChange> &changes() const { return m_changes; }

Q_SIGNALS:
    /// A comparison ended: shown, or failed with a message in the view.
    void finished();

private:
    struct Other
    {
        ArchitectureSnapshot before;
        ArchitectureSnapshot after;
        QString error;
    };
    void start(const QString &label, std::function<Other(const JobControl &)> readOther);
    void chooseFolder();
    void askRevision();

    Document *m_document;
    ArchitectureDiffView *m_view;
    QDockWidget *m_dock;
    LogView *m_log;
    QWidget *m_window;
    QAction *m_folderAction;
    QAction *m_revisionAction;
    JobRunner m_jobs;
    QList<ArchitectureChange> m_changes;
};

} // namespace rosarch
