#include "gitrevision.h"

#include <QDir>
#include <QFile>
#include <QProcess>

namespace rosarch {

namespace {

/// Runs git in `folder`; its standard output in `output`, or false with `error` set.
bool git(const QString &folder, const QStringList &args, QByteArray *output, QString *error)
{
    QProcess p;
    p.setWorkingDirectory(folder);
    p.start(QStringLiteral("git"), args);
    if (!p.waitForStarted(10000)) {
        *error = QStringLiteral("git could not be started: %1").arg(p.errorString());
        return false;
    }
    p.closeWriteChannel();
    if (!p.waitForFinished(300000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
        *error = QStringLiteral("git %1 failed: %2")
                     .arg(args.join(QLatin1Char(' ')),
                          QString::fromLocal8Bit(p.readAllStandardError()).trimmed());
        return false;
    }
    if (output)
        *output = p.readAllStandardOutput();
    return true;
}

} // namespace

bool GitRevision::checkout(const QString &workspace, const QString &revision, const QString &into,
                           QString *error)
{
    QByteArray prefix, top;
    if (!git(workspace, {QStringLiteral("rev-parse"), QStringLiteral("--show-prefix")}, &prefix,
             error) ||
        !git(workspace, {QStringLiteral("rev-parse"), QStringLiteral("--show-toplevel")}, &top,
             error))
        return false;
    // The workspace's own tree at the revision ("rev:path/in/repo/"), unpacked as the folder.
    const QString tar = QDir(into).filePath(QStringLiteral(".rosarch-tree.tar"));
    if (!git(QString::fromLocal8Bit(top.trimmed()),
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
