#include "diff/gitrevision.h"

#include <QDir>
#include <QFile>
#include <QProcess>

namespace rosarch {

bool GitRevision::run(const QString &folder, const QStringList &arguments, QByteArray *output,
                      QString *error, int timeoutMs)
{
    QProcess p;
    p.setWorkingDirectory(folder);
    p.start(QStringLiteral("git"), arguments);
    const auto fail = [&](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    if (!p.waitForStarted(10000))
        return fail(QStringLiteral("git could not be started: %1").arg(p.errorString()));
    p.closeWriteChannel();
    if (!p.waitForFinished(timeoutMs) || p.exitStatus() != QProcess::NormalExit ||
        p.exitCode() != 0)
        return fail(QStringLiteral("git %1 failed: %2")
                        .arg(arguments.join(QLatin1Char(' ')),
                             QString::fromLocal8Bit(p.readAllStandardError()).trimmed()));
    if (output)
        *output = p.readAllStandardOutput();
    return true;
}

bool GitRevision::checkout(const QString &workspace, const QString &revision, const QString &into,
                           QString *error)
{
    QByteArray prefix, top;
    if (!run(workspace, {QStringLiteral("rev-parse"), QStringLiteral("--show-prefix")}, &prefix,
             error) ||
        !run(workspace, {QStringLiteral("rev-parse"), QStringLiteral("--show-toplevel")}, &top,
             error))
        return false;
    // The workspace's own tree at the revision ("rev:path/in/repo/"), unpacked as the folder.
    const QString tar = QDir(into).filePath(QStringLiteral(".rosarch-tree.tar"));
    if (!run(QString::fromLocal8Bit(top.trimmed()),
             {QStringLiteral("archive"), QStringLiteral("--format=tar"), QStringLiteral("-o"), tar,
              revision + QLatin1Char(':') + QString::fromUtf8(prefix.trimmed())},
             nullptr, error))
        return false;
    QProcess untar;
    untar.start(QStringLiteral("tar"), {QStringLiteral("-xf"), tar, QStringLiteral("-C"), into});
    const bool unpacked = untar.waitForFinished(300000) &&
                          untar.exitStatus() == QProcess::NormalExit && untar.exitCode() == 0;
    QFile::remove(tar);
    if (!unpacked) {
        *error = QStringLiteral("Cannot unpack revision %1: %2")
                     .arg(revision, QString::fromLocal8Bit(untar.readAllStandardError()).trimmed());
        return false;
    }
    return true;
}

} // namespace rosarch
