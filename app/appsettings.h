#pragma once

#include "launch/launchanalyzer.h"
#include "suggestions/llm/llmsettings.h"

#include <QByteArray>
#include <QSize>
#include <QStringList>
#include <QVariantMap>

#include <memory>

class QSettings;

namespace rosarch {

/// What the application remembers between runs: recent workspaces, the window layout, the
/// last selection and the launch options of each workspace. One place that knows the keys.
class AppSettings
{
public:
    static constexpr int kMaxRecent = 10;

    AppSettings();
    ~AppSettings();

    /// Recent workspace folders, newest first; folders that no longer exist are dropped.
    QStringList recentWorkspaces();
    void addRecentWorkspace(const QString &path);
    void removeRecentWorkspace(const QString &path);
    void clearRecentWorkspaces();

    /// Recent project files, newest first (missing ones included: the menu greys them).
    QStringList recentProjects() const;
    void addRecentProject(const QString &file);
    void removeRecentProject(const QString &file);
    void clearRecentProjects();

    QString lastWorkspace() const;
    void setLastWorkspace(const QString &path);
    QString lastExportFolder() const;
    void setLastExportFolder(const QString &path);

    QByteArray windowGeometry() const;
    void setWindowGeometry(const QByteArray &geometry);
    QByteArray windowState() const;
    void setWindowState(const QByteArray &state);
    /// The window size the dock state was saved at (invalid when not known).
    QSize windowStateSize() const;
    void setWindowStateSize(const QSize &size);

    /// The node (and port) selected when the window closed on `workspace`.
    void selection(const QString &workspace, QString *nodeId, QString *portId) const;
    void setSelection(const QString &workspace, const QString &nodeId, const QString &portId);

    /// The launch-tree row (a launch-file or node instance id) selected on `workspace`.
    QString launchSelection(const QString &workspace) const;
    void setLaunchSelection(const QString &workspace, const QString &instanceId);

    /// The root launch file and argument values a person chose for `workspace` (empty when
    /// never chosen).
    LaunchOptions launchOptions(const QString &workspace) const;
    void setLaunchOptions(const QString &workspace, const LaunchOptions &options);

    /// The root launch file (workspace-relative) a person chose for the composed diagram of
    /// `workspace` ("" when never chosen).
    QString diagramRoot(const QString &workspace) const;
    /// The Log's filter and grouping (DiagnosticFilterBar::state), for every workspace.
    QVariantMap logFilter() const;
    void setLogFilter(const QVariantMap &filter);
    void setDiagramRoot(const QString &workspace, const QString &rootFile);

    /// What File → Export Architecture Site was last given for `workspace` (folder, title,
    /// sourceUrl, commit); empty when never.
    QVariantMap siteExport(const QString &workspace) const;
    void setSiteExport(const QString &workspace, const QVariantMap &values);

    /// The LLM endpoint, model, temperature and timeouts (never the API key); when nothing
    /// was stored, $ROSARCH_LLM_ENDPOINT / $ROSARCH_LLM_MODEL or the defaults.
    LlmSettings llmSettings() const;
    void setLlmSettings(const LlmSettings &settings);
    /// The PlantUML jar a person chose for rendering ("" = look in the usual places).
    QString plantUmlJar() const;
    void setPlantUmlJar(const QString &path);
    /// Whether suggestion runs ask the LLM (off until a person turns it on).
    bool useLlm() const;
    void setUseLlm(bool use);
    /// Whether the open workspace is watched and re-run on changes (default on).
    bool watchWorkspace() const;
    void setWatchWorkspace(bool watch);

private:
    /// A recent list under `key`: `path` made canonical and put first, at most kMaxRecent.
    void addRecent(const QString &key, const QString &path);
    void removeRecent(const QString &key, const QString &path);

    std::unique_ptr<QSettings> m_settings;
};

} // namespace rosarch
