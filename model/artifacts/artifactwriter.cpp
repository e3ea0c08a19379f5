#include "artifactwriter.h"
#include "acdwriter.h"
#include "architecturejson.h"
#include "atomicnodesjson.h"
#include "ccdwriter.h"
#include "communicationgraph.h"
#include "launchdependenciesjson.h"
#include "mermaidwriter.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>
#include <QTemporaryDir>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace rosarch {

namespace {
bool writeFile(const QString &path, const QByteArray &content, QStringList *written, QString *error)
{
    QSaveFile f(path);
    errno = 0;
    if (!f.open(QIODevice::WriteOnly) || f.write(content) != content.size() || !f.commit()) {
        // Qt says "Unknown error" for a full disk or a file-size limit; the system knows.
        const int why = errno;
        const QString reason = f.errorString() == QLatin1String("Unknown error") && why != 0
                                   ? QString::fromLocal8Bit(std::strerror(why))
                                   : f.errorString();
        *error = QStringLiteral("Cannot write %1: %2").arg(path, reason);
        return false;
    }
    if (written)
        written->append(path);
    return true;
}
} // namespace

bool ArtifactWriter::writeAll(const AtomicNodeList &nodes, const QString &dir, QStringList *written,
                              QString *error)
{
    Recovery r;
    r.nodes = nodes;
    return writeAll(r, dir, written, error, false);
}

bool ArtifactWriter::writeAll(const Recovery &recovery, const QString &dir, QStringList *written,
                              QString *error)
{
    return writeAll(recovery, dir, written, error, true);
}

bool ArtifactWriter::writeAll(const Recovery &recovery, const QString &dir, QStringList *written,
                              QString *error, bool withLaunch)
{
    const AtomicNodeList &nodes = recovery.nodes;
    QDir out(dir);
    if (!out.mkpath(QStringLiteral("."))) {
        *error = QStringLiteral("Cannot create the folder %1.").arg(dir);
        return false;
    }
    // Everything is written into a staging folder inside the output folder first (same file
    // system) and moved into place only when every file was written: a full disk or another
    // failure leaves the previous artifacts as they were, never a half-written mix.
    QTemporaryDir staging(out.filePath(QStringLiteral(".rosarch-writing-XXXXXX")));
    if (!staging.isValid()) {
        *error = QStringLiteral("Cannot write into %1: %2").arg(dir, staging.errorString());
        return false;
    }
    QStringList files; // relative paths, in writing order
    const auto stage = [&](const QString &relative, const QByteArray &content) {
        const QString path = staging.filePath(relative);
        if (!QDir().mkpath(QFileInfo(path).path())) {
            *error = QStringLiteral("Cannot create the folder %1.").arg(QFileInfo(path).path());
            return false;
        }
        if (!writeFile(path, content, nullptr, error)) {
            // Name the file as it was meant to be, not the staging copy.
            error->replace(path, out.filePath(relative));
            return false;
        }
        files << relative;
        return true;
    };
    if (!stage(QStringLiteral("atomic_nodes.json"), AtomicNodesJson::write(nodes)))
        return false;
    if (withLaunch && !stage(QStringLiteral("launch_dependencies.json"),
                             LaunchDependenciesJson::write(recovery.launch)))
        return false;
    QList<Diagnostic> diagnostics = nodes.diagnostics;
    if (withLaunch) {
        diagnostics.append(recovery.launch.diagnostics);
        diagnostics.append(recovery.architecture.diagnostics);
    }
    if (!stage(QStringLiteral("diagnostics.json"), DiagnosticsJson::write(diagnostics)))
        return false;
    const QMap<QString, QString> stems = AcdWriter::fileStems(nodes);
    for (const AtomicNode &n : nodes.nodes)
        if (!stage(QStringLiteral("acd/%1.puml").arg(stems.value(n.id)),
                   AcdWriter::write(n).toUtf8()))
            return false;
    if (withLaunch) {
        const QMap<QString, QString> ccdStems = CcdWriter::fileStems(recovery.architecture);
        if (!stage(QStringLiteral("architecture.json"),
                   ArchitectureJson::write(recovery.architecture, ccdStems)))
            return false;
        for (const Composite *c : recovery.architecture.representatives()) {
            const QString stem = ccdStems.value(c->instanceId);
            if (!stage(QStringLiteral("ccd/%1.puml").arg(stem), CcdWriter::write(*c).toUtf8()) ||
                !stage(QStringLiteral("mermaid/%1.md").arg(stem),
                       MermaidWriter::write(*c).toUtf8()))
                return false;
        }
        // The communication graph is the running system's: one per root, as launched.
        for (const Composite &c : recovery.architecture.composites)
            if (c.parentId.isEmpty() &&
                !stage(QStringLiteral("graph/%1.dot").arg(ccdStems.value(c.instanceId, c.stem)),
                       CommunicationGraph::dot(recovery.architecture, c).toUtf8()))
                return false;
    }

    // Every file is written: diagrams of an earlier run (and their pictures) would otherwise
    // linger beside the new ones; then each file replaces its old version by a rename.
    for (const QString &sub : {QStringLiteral("acd"), QStringLiteral("ccd"),
                               QStringLiteral("mermaid"), QStringLiteral("graph")}) {
        QDir d(out.filePath(sub));
        if (!d.exists())
            continue;
        for (const QString &old :
             d.entryList({QStringLiteral("*.puml"), QStringLiteral("*.md"), QStringLiteral("*.dot"),
                          QStringLiteral("*.svg"), QStringLiteral("*.png")},
                         QDir::Files))
            d.remove(old);
    }
    for (const QString &relative : std::as_const(files)) {
        const QString target = out.filePath(relative);
        if (!out.mkpath(QFileInfo(relative).path()) ||
            std::rename(QFile::encodeName(staging.filePath(relative)).constData(),
                        QFile::encodeName(target).constData()) != 0) {
            *error = QStringLiteral("Cannot move %1 into place: %2")
                         .arg(target, QString::fromLocal8Bit(std::strerror(errno)));
            return false;
        }
        if (written)
            written->append(target);
    }
    return true;
}

} // namespace rosarch
