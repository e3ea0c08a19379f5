#include "accepted/decisionstore.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QStandardPaths>

namespace rosarch::DecisionStore {

namespace {
const QString kFormat = QStringLiteral("rosarch-decisions");
}

QString path(const QString &workspaceRoot)
{
    if (workspaceRoot.isEmpty())
        return {};
    const QString absolute = QDir::cleanPath(QFileInfo(workspaceRoot).absoluteFilePath());
    const QByteArray hash =
        QCryptographicHash::hash(absolute.toUtf8(), QCryptographicHash::Sha1).toHex();
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("projects/%1/decisions.json").arg(QString::fromLatin1(hash)));
}

QMap<QString, SuggestionDecision> load(const QString &file, int *skipped)
{
    QMap<QString, SuggestionDecision> out;
    if (skipped)
        *skipped = 0;
    QFile f(file);
    if (file.isEmpty() || !f.open(QIODevice::ReadOnly))
        return out;
    const QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
    if (root.value(QLatin1String("format")).toString() != kFormat)
        return out;
    for (const QJsonValue &v : root.value(QLatin1String("decisions")).toArray()) {
        SuggestionDecision d;
        if (SuggestionDecision::fromJson(v.toObject(), &d))
            out.insert(d.key(), d);
        else if (skipped)
            ++*skipped;
    }
    return out;
}

bool save(const QString &file, const QString &workspaceRoot,
          const QMap<QString, SuggestionDecision> &decisions, QString *error)
{
    if (file.isEmpty())
        return true;
    QJsonArray list;
    for (const SuggestionDecision &d : decisions)
        list.append(d.toJson());
    const QJsonObject root{
        {QLatin1String("format"), kFormat},
        {QLatin1String("version"), 1},
        {QLatin1String("workspace"), QDir::cleanPath(QFileInfo(workspaceRoot).absoluteFilePath())},
        {QLatin1String("decisions"), list}};
    if (!QDir().mkpath(QFileInfo(file).path())) {
        *error = QStringLiteral("Cannot create the folder %1").arg(QFileInfo(file).path());
        return false;
    }
    QSaveFile out(file);
    if (!out.open(QIODevice::WriteOnly)) {
        *error = QStringLiteral("Cannot write %1: %2").arg(file, out.errorString());
        return false;
    }
    out.write(QJsonDocument(root).toJson(QJsonDocument::Indented));
    if (!out.commit()) {
        *error = QStringLiteral("Cannot write %1: %2").arg(file, out.errorString());
        return false;
    }
    return true;
}

} // namespace rosarch::DecisionStore
