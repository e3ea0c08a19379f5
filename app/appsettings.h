#pragma once

#include <QByteArray>
#include <QStringList>

#include <memory>

class QSettings;

namespace rosarch {

/// What the application remembers between runs: recent workspaces, the window layout and
/// the last selection. One place that knows the keys.
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

    QString lastWorkspace() const;
    void setLastWorkspace(const QString &path);
    QString lastExportFolder() const;
    void setLastExportFolder(const QString &path);

    QByteArray windowGeometry() const;
    void setWindowGeometry(const QByteArray &geometry);
    QByteArray windowState() const;
    void setWindowState(const QByteArray &state);

    /// The node (and port) selected when the window closed on `workspace`.
    void selection(const QString &workspace, QString *nodeId, QString *portId) const;
    void setSelection(const QString &workspace, const QString &nodeId, const QString &portId);

private:
    std::unique_ptr<QSettings> m_settings;
};

} // namespace rosarch
