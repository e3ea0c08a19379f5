#include "project/project.h"
#include "suggestions/llm/llmschemavalidator.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>
#include <QStandardPaths>

#include <algorithm>
#include <mutex>

// Resources of a static library must be registered explicitly; outside any namespace.
static void initSchemaResources()
{
    static std::once_flag once;
    std::call_once(once, [] { Q_INIT_RESOURCE(schemas); });
}

namespace rosarch {

QString Project::nextCorrectionId() const
{
    int highest = 0;
    for (const Correction &c : corrections)
        if (c.id.startsWith(QLatin1Char('c')))
            highest = std::max(highest, c.id.mid(1).toInt());
    return QStringLiteral("c%1").arg(highest + 1);
}

const Correction *Project::correction(const QString &id) const
{
    for (const Correction &c : corrections)
        if (c.id == id)
            return &c;
    return nullptr;
}

const FindingMark *Project::finding(const QString &key) const
{
    for (const FindingMark &m : findings)
        if (m.key == key)
            return &m;
    return nullptr;
}

namespace ProjectFile {

QString defaultPath(const QString &workspaceRoot)
{
    return QDir(workspaceRoot).filePath(QStringLiteral("rosarch.project.json"));
}

QString locate(const QString &workspaceRoot)
{
    if (workspaceRoot.isEmpty())
        return {};
    const QString own = defaultPath(workspaceRoot);
    return QFileInfo::exists(own) ? own : appDataPath(workspaceRoot);
}

QString appDataPath(const QString &workspaceRoot)
{
    const QString absolute = QDir::cleanPath(QFileInfo(workspaceRoot).absoluteFilePath());
    const QByteArray hash =
        QCryptographicHash::hash(absolute.toUtf8(), QCryptographicHash::Sha1).toHex();
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(
            QStringLiteral("projects/%1/rosarch.project.json").arg(QString::fromLatin1(hash)));
}

QString workspaceField(const QString &file, const QString &workspaceRoot)
{
    const QString folder = QDir::cleanPath(QFileInfo(file).absolutePath());
    const QString root = QDir::cleanPath(QFileInfo(workspaceRoot).absoluteFilePath());
    if (folder == root)
        return {};
    if (folder.startsWith(root + QLatin1Char('/')))
        return QDir::cleanPath(QDir(folder).relativeFilePath(root));
    return root;
}

QString workspaceOf(const QString &file, const Project &project)
{
    const QDir folder = QFileInfo(file).absoluteDir();
    if (project.workspace.isEmpty())
        return QDir::cleanPath(folder.absolutePath());
    return QDir::cleanPath(folder.absoluteFilePath(project.workspace));
}

QString autosavePath(const QString &file)
{
    const QFileInfo info(file);
    return info.dir().filePath(QStringLiteral(".%1.autosave").arg(info.fileName()));
}

QJsonObject schema()
{
    initSchemaResources();
    QFile f(QStringLiteral(":/schemas/project.schema.json"));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

QByteArray toJson(const Project &project)
{
    QJsonObject o{{QLatin1String("version"), project.version()}};
    if (!QCoreApplication::applicationVersion().isEmpty())
        o.insert(QLatin1String("generator"),
                 QStringLiteral("rosarch ") + QCoreApplication::applicationVersion());
    if (!project.workspace.isEmpty())
        o.insert(QLatin1String("workspace"), project.workspace);
    QJsonObject launch;
    if (!project.launch.rootFile.isEmpty())
        launch.insert(QLatin1String("root"), project.launch.rootFile);
    if (!project.launch.arguments.isEmpty()) {
        QJsonObject args;
        for (auto it = project.launch.arguments.cbegin(); it != project.launch.arguments.cend();
             ++it)
            args.insert(it.key(), it.value());
        launch.insert(QLatin1String("arguments"), args);
    }
    if (!launch.isEmpty())
        o.insert(QLatin1String("launch"), launch);
    QList<SuggestionDecision> decisions = project.decisions;
    std::sort(decisions.begin(), decisions.end(),
              [](const auto &a, const auto &b) { return a.key() < b.key(); });
    QJsonArray d;
    for (const SuggestionDecision &decision : decisions)
        d.append(decision.toJson());
    if (!d.isEmpty())
        o.insert(QLatin1String("decisions"), d);
    QJsonArray c;
    for (const Correction &correction : project.corrections)
        c.append(correction.toJson());
    if (!c.isEmpty())
        o.insert(QLatin1String("corrections"), c);
    QList<FindingMark> marks = project.findings;
    std::sort(marks.begin(), marks.end(),
              [](const FindingMark &a, const FindingMark &b) { return a.key < b.key; });
    QJsonArray f;
    for (const FindingMark &mark : marks)
        f.append(mark.toJson());
    if (!f.isEmpty())
        o.insert(QLatin1String("findings"), f);
    QJsonArray externals;
    for (const ExpectedExternal &e : project.launch.externals) {
        QJsonObject x{{QLatin1String("name"), e.name},
                      {QLatin1String("direction"),
                       e.output ? QLatin1String("output") : QLatin1String("input")}};
        if (!e.reason.isEmpty())
            x.insert(QLatin1String("reason"), e.reason);
        externals.append(x);
    }
    if (!externals.isEmpty())
        o.insert(QLatin1String("externals"), externals);
    // QJsonObject keeps its keys sorted: the file diffs line by line
    return QJsonDocument(o).toJson(QJsonDocument::Indented);
}

bool fromJson(const QByteArray &data, Project *project, QString *error)
{
    QJsonParseError parse;
    const QJsonDocument doc = QJsonDocument::fromJson(data, &parse);
    if (parse.error != QJsonParseError::NoError) {
        const int line = int(data.left(parse.offset).count('\n')) + 1;
        *error = QStringLiteral("not valid JSON (line %1: %2)").arg(line).arg(parse.errorString());
        return false;
    }
    if (!doc.isObject()) {
        *error = QStringLiteral("not a rosarch project (the top level is not an object)");
        return false;
    }
    const QJsonObject o = doc.object();
    // the version first: a newer file may well not fit this build's schema
    const int version = o.value(QLatin1String("version")).toInt(0);
    if (version > Project::kVersion) {
        *error = QStringLiteral("written by a newer rosarch (project version %1; this build reads "
                                "up to version %2)")
                     .arg(version)
                     .arg(Project::kVersion);
        return false;
    }
    QString schemaError;
    if (!LlmSchemaValidator(schema()).validate(o, &schemaError)) {
        *error = QStringLiteral("does not match the project schema: %1").arg(schemaError);
        return false;
    }
    Project p;
    p.workspace = o.value(QLatin1String("workspace")).toString();
    const QJsonObject launch = o.value(QLatin1String("launch")).toObject();
    p.launch.rootFile = launch.value(QLatin1String("root")).toString();
    const QJsonObject args = launch.value(QLatin1String("arguments")).toObject();
    for (auto it = args.begin(); it != args.end(); ++it)
        p.launch.arguments.insert(it.key(), it.value().toString());
    for (const QJsonValue &v : o.value(QLatin1String("decisions")).toArray()) {
        SuggestionDecision d;
        if (!SuggestionDecision::fromJson(v.toObject(), &d)) {
            *error = QStringLiteral("a decision cannot be read: %1")
                         .arg(QString::fromUtf8(
                             QJsonDocument(v.toObject()).toJson(QJsonDocument::Compact)));
            return false;
        }
        p.decisions.append(d);
    }
    for (const QJsonValue &v : o.value(QLatin1String("corrections")).toArray()) {
        Correction c;
        if (!Correction::fromJson(v.toObject(), &c, error))
            return false;
        if (p.correction(c.id)) {
            *error = QStringLiteral("two corrections have the id %1").arg(c.id);
            return false;
        }
        p.corrections.append(c);
    }
    for (const QJsonValue &v : o.value(QLatin1String("findings")).toArray()) {
        FindingMark m;
        if (!FindingMark::fromJson(v.toObject(), &m, error))
            return false;
        if (p.finding(m.key)) {
            *error = QStringLiteral("two findings have the key %1").arg(m.key);
            return false;
        }
        p.findings.append(m);
    }
    std::sort(p.findings.begin(), p.findings.end(),
              [](const FindingMark &a, const FindingMark &b) { return a.key < b.key; });
    for (const QJsonValue &v : o.value(QLatin1String("externals")).toArray()) {
        const QJsonObject x = v.toObject();
        if (!x.value(QLatin1String("name")).toString().startsWith(QLatin1Char('/'))) {
            *error = QStringLiteral("the expected external %1 is not a fully qualified name")
                         .arg(x.value(QLatin1String("name")).toString());
            return false;
        }
        p.launch.externals.append(
            {x.value(QLatin1String("name")).toString(),
             x.value(QLatin1String("direction")).toString() == QLatin1String("output"),
             x.value(QLatin1String("reason")).toString()});
    }
    *project = p;
    return true;
}

bool read(const QString &file, Project *project, QString *error)
{
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: cannot be read (%2)").arg(file, f.errorString());
        return false;
    }
    constexpr qint64 kLimit = 64 * 1024 * 1024; // far beyond any real project
    if (f.size() > kLimit) {
        *error =
            QStringLiteral("%1: too large for a project file (%2 bytes)").arg(file).arg(f.size());
        return false;
    }
    QString why;
    if (!fromJson(f.readAll(), project, &why)) {
        *error = QStringLiteral("%1: %2").arg(file, why);
        return false;
    }
    return true;
}

bool write(const QString &file, const Project &project, QString *error)
{
    QDir().mkpath(QFileInfo(file).path());
    QSaveFile f(file);
    const QByteArray data = toJson(project);
    if (!f.open(QIODevice::WriteOnly) || f.write(data) != data.size() || !f.commit()) {
        *error = QStringLiteral("%1: cannot be written (%2)").arg(file, f.errorString());
        return false;
    }
    return true;
}

QString keepUnreadable(const QString &file)
{
    const QString copy =
        QStringLiteral("%1.unreadable-%2")
            .arg(file, QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    return QFile::copy(file, copy) ? copy : QString();
}

} // namespace ProjectFile

} // namespace rosarch
