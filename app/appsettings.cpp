#include "app/appsettings.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace rosarch {

namespace {
const QString kRecent = QStringLiteral("workspaces/recent");
const QString kLast = QStringLiteral("workspaces/last");
const QString kRecentProjects = QStringLiteral("projects/recent");
const QString kExport = QStringLiteral("workspaces/lastExportFolder");
const QString kGeometry = QStringLiteral("window/geometry");
const QString kState = QStringLiteral("window/state");
const QString kStateSize = QStringLiteral("window/stateSize");
const QString kSelWorkspace = QStringLiteral("session/workspace");
const QString kSelNode = QStringLiteral("session/node");
const QString kSelPort = QStringLiteral("session/port");
const QString kSelLaunch = QStringLiteral("session/launchItem");
// One map for every workspace: workspace paths hold '/', which QSettings keys cannot.
const QString kLaunchOptions = QStringLiteral("launch/options");
const QString kRootKey = QStringLiteral("root");
const QString kArgumentsKey = QStringLiteral("arguments");
// The root launch file the composed diagram shows, per workspace (workspace-relative).
const QString kDiagramRoots = QStringLiteral("diagram/roots");
// The site export dialog's fields, per workspace.
const QString kSiteExports = QStringLiteral("site/exports");
// The LLM; the API key has no key here on purpose: it only comes from the environment.
const QString kLlmEndpoint = QStringLiteral("llm/endpoint");
const QString kLlmModel = QStringLiteral("llm/model");
const QString kLlmTemperature = QStringLiteral("llm/temperature");
const QString kLlmConnectTimeout = QStringLiteral("llm/connectTimeoutMs");
const QString kLlmRequestTimeout = QStringLiteral("llm/requestTimeoutMs");
const QString kLlmUse = QStringLiteral("llm/use");
const QString kWatchWorkspace = QStringLiteral("workspace/watch");
const QString kLogFilter = QStringLiteral("log/filter");

QString normalized(const QString &path)
{
    const QFileInfo info(path);
    const QString canonical = info.canonicalFilePath();
    return QDir::cleanPath(canonical.isEmpty() ? info.absoluteFilePath() : canonical);
}
} // namespace

AppSettings::AppSettings()
{
    const QString organization = QCoreApplication::organizationName();
    m_settings = std::make_unique<QSettings>(organization.isEmpty() ? QStringLiteral("rosarch")
                                                                    : organization,
                                             QCoreApplication::applicationName());
}

AppSettings::~AppSettings() = default;

QStringList AppSettings::recentWorkspaces()
{
    const QStringList stored = m_settings->value(kRecent).toStringList();
    QStringList existing;
    for (const QString &path : stored)
        if (QFileInfo(path).isDir() && !existing.contains(path))
            existing.append(path);
    if (existing.size() > kMaxRecent)
        existing.resize(kMaxRecent);
    if (existing != stored)
        m_settings->setValue(kRecent, existing);
    return existing;
}

void AppSettings::addRecentWorkspace(const QString &path)
{
    addRecent(kRecent, path);
}

void AppSettings::removeRecentWorkspace(const QString &path)
{
    removeRecent(kRecent, path);
}

void AppSettings::clearRecentWorkspaces()
{
    m_settings->remove(kRecent);
}

QStringList AppSettings::recentProjects() const
{
    QStringList list = m_settings->value(kRecentProjects).toStringList();
    list.removeDuplicates();
    if (list.size() > kMaxRecent)
        list.resize(kMaxRecent);
    return list;
}

void AppSettings::addRecentProject(const QString &file)
{
    addRecent(kRecentProjects, file);
}

void AppSettings::removeRecentProject(const QString &file)
{
    removeRecent(kRecentProjects, file);
}

void AppSettings::addRecent(const QString &key, const QString &path)
{
    const QString p = normalized(path);
    QStringList list = m_settings->value(key).toStringList();
    list.removeAll(p);
    list.prepend(p);
    if (list.size() > kMaxRecent)
        list.resize(kMaxRecent);
    m_settings->setValue(key, list);
}

void AppSettings::removeRecent(const QString &key, const QString &path)
{
    QStringList list = m_settings->value(key).toStringList();
    list.removeAll(path);
    list.removeAll(normalized(path));
    m_settings->setValue(key, list);
}

void AppSettings::clearRecentProjects()
{
    m_settings->remove(kRecentProjects);
}

QString AppSettings::lastWorkspace() const
{
    return m_settings->value(kLast).toString();
}

void AppSettings::setLastWorkspace(const QString &path)
{
    m_settings->setValue(kLast, normalized(path));
}

QString AppSettings::lastExportFolder() const
{
    return m_settings->value(kExport).toString();
}

void AppSettings::setLastExportFolder(const QString &path)
{
    m_settings->setValue(kExport, path);
}

QByteArray AppSettings::windowGeometry() const
{
    return m_settings->value(kGeometry).toByteArray();
}

void AppSettings::setWindowGeometry(const QByteArray &geometry)
{
    m_settings->setValue(kGeometry, geometry);
}

QByteArray AppSettings::windowState() const
{
    return m_settings->value(kState).toByteArray();
}

void AppSettings::setWindowState(const QByteArray &state)
{
    m_settings->setValue(kState, state);
}

QSize AppSettings::windowStateSize() const
{
    return m_settings->value(kStateSize).toSize();
}

void AppSettings::setWindowStateSize(const QSize &size)
{
    m_settings->setValue(kStateSize, size);
}

void AppSettings::selection(const QString &workspace, QString *nodeId, QString *portId) const
{
    const bool same = m_settings->value(kSelWorkspace).toString() == normalized(workspace);
    *nodeId = same ? m_settings->value(kSelNode).toString() : QString();
    *portId = same ? m_settings->value(kSelPort).toString() : QString();
}

void AppSettings::setSelection(const QString &workspace, const QString &nodeId,
                               const QString &portId)
{
    m_settings->setValue(kSelWorkspace, normalized(workspace));
    m_settings->setValue(kSelNode, nodeId);
    m_settings->setValue(kSelPort, portId);
}

QString AppSettings::launchSelection(const QString &workspace) const
{
    const bool same = m_settings->value(kSelWorkspace).toString() == normalized(workspace);
    return same ? m_settings->value(kSelLaunch).toString() : QString();
}

void AppSettings::setLaunchSelection(const QString &workspace, const QString &instanceId)
{
    m_settings->setValue(kSelWorkspace, normalized(workspace));
    m_settings->setValue(kSelLaunch, instanceId);
}

LaunchOptions AppSettings::launchOptions(const QString &workspace) const
{
    const QVariantMap all = m_settings->value(kLaunchOptions).toMap();
    const QVariantMap stored = all.value(normalized(workspace)).toMap();
    LaunchOptions options;
    options.rootFile = stored.value(kRootKey).toString();
    const QVariantMap arguments = stored.value(kArgumentsKey).toMap();
    for (auto it = arguments.cbegin(); it != arguments.cend(); ++it)
        options.arguments.insert(it.key(), it.value().toString());
    return options;
}

void AppSettings::setLaunchOptions(const QString &workspace, const LaunchOptions &options)
{
    QVariantMap all = m_settings->value(kLaunchOptions).toMap();
    if (options == LaunchOptions()) {
        all.remove(normalized(workspace));
    } else {
        QVariantMap arguments;
        for (auto it = options.arguments.cbegin(); it != options.arguments.cend(); ++it)
            arguments.insert(it.key(), it.value());
        all.insert(normalized(workspace),
                   QVariantMap{{kRootKey, options.rootFile}, {kArgumentsKey, arguments}});
    }
    m_settings->setValue(kLaunchOptions, all);
}

LlmSettings AppSettings::llmSettings() const
{
    LlmSettings s = LlmSettings::fromEnvironment();
    s.endpoint = m_settings->value(kLlmEndpoint, s.endpoint).toString();
    s.model = m_settings->value(kLlmModel, s.model).toString();
    s.temperature = m_settings->value(kLlmTemperature, s.temperature).toDouble();
    s.connectTimeoutMs = m_settings->value(kLlmConnectTimeout, s.connectTimeoutMs).toInt();
    s.requestTimeoutMs = m_settings->value(kLlmRequestTimeout, s.requestTimeoutMs).toInt();
    return s;
}

void AppSettings::setLlmSettings(const LlmSettings &settings)
{
    m_settings->setValue(kLlmEndpoint, settings.endpoint);
    m_settings->setValue(kLlmModel, settings.model);
    m_settings->setValue(kLlmTemperature, settings.temperature);
    m_settings->setValue(kLlmConnectTimeout, settings.connectTimeoutMs);
    m_settings->setValue(kLlmRequestTimeout, settings.requestTimeoutMs);
}

bool AppSettings::useLlm() const
{
    return m_settings->value(kLlmUse, false).toBool();
}

void AppSettings::setUseLlm(bool use)
{
    m_settings->setValue(kLlmUse, use);
}

bool AppSettings::watchWorkspace() const
{
    return m_settings->value(kWatchWorkspace, true).toBool();
}

void AppSettings::setWatchWorkspace(bool watch)
{
    m_settings->setValue(kWatchWorkspace, watch);
}

QString AppSettings::plantUmlJar() const
{
    return m_settings->value(QStringLiteral("plantuml/jar")).toString();
}

void AppSettings::setPlantUmlJar(const QString &path)
{
    m_settings->setValue(QStringLiteral("plantuml/jar"), path);
}

QString AppSettings::diagramRoot(const QString &workspace) const
{
    return m_settings->value(kDiagramRoots).toMap().value(normalized(workspace)).toString();
}

void AppSettings::setDiagramRoot(const QString &workspace, const QString &rootFile)
{
    QVariantMap all = m_settings->value(kDiagramRoots).toMap();
    if (rootFile.isEmpty())
        all.remove(normalized(workspace));
    else
        all.insert(normalized(workspace), rootFile);
    m_settings->setValue(kDiagramRoots, all);
}

QVariantMap AppSettings::siteExport(const QString &workspace) const
{
    return m_settings->value(kSiteExports).toMap().value(normalized(workspace)).toMap();
}

void AppSettings::setSiteExport(const QString &workspace, const QVariantMap &values)
{
    QVariantMap all = m_settings->value(kSiteExports).toMap();
    all.insert(normalized(workspace), values);
    m_settings->setValue(kSiteExports, all);
}

QVariantMap AppSettings::logFilter() const
{
    return m_settings->value(kLogFilter).toMap();
}

void AppSettings::setLogFilter(const QVariantMap &filter)
{
    m_settings->setValue(kLogFilter, filter);
}

} // namespace rosarch
