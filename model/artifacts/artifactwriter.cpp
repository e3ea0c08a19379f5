#include "artifacts/artifactwriter.h"
#include "artifacts/architecturejson.h"
#include "artifacts/artifactcommit.h"
#include "artifacts/atomicnodesjson.h"
#include "artifacts/diagnosticsjson.h"
#include "artifacts/launchdependenciesjson.h"
#include "core/visibletext.h"
#include "pipeline/recoverystream.h"
#include "plantuml/acdwriter.h"
#include "plantuml/ccdwriter.h"
#include "plantuml/communicationgraph.h"
#include "plantuml/mermaidwriter.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDataStream>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>

#include <dlfcn.h>

namespace rosarch {

namespace {

/// What the artifacts are made from: the recovery (as the worker sends it) and this build of
/// the writers (the program's and this library's files). Equal stamps, equal artifacts.
QByteArray stampOf(const Recovery &recovery, bool withLaunch, const QByteArray &madeFrom)
{
    QByteArray bytes = madeFrom;
    if (madeFrom.isEmpty()) {
        QDataStream out(&bytes, QIODevice::WriteOnly);
        out.setVersion(stagestream::kStreamVersion);
        stagestream::writeParts(out, withLaunch ? stagestream::AllParts : stagestream::NodesPart,
                                recovery, Recovery{});
    }
    QCryptographicHash hash(QCryptographicHash::Sha1);
    hash.addData(bytes);
    hash.addData(QCoreApplication::applicationVersion().toUtf8());
    QString library;
    Dl_info info = {};
    if (dladdr(reinterpret_cast<const void *>(&stampOf), &info) != 0 && info.dli_fname)
        library = QFile::decodeName(info.dli_fname);
    for (const QString &binary : {QCoreApplication::applicationFilePath(), library}) {
        const QFileInfo f(binary);
        hash.addData(QByteArray::number(f.lastModified().toMSecsSinceEpoch()) +
                     f.filePath().toUtf8());
    }
    return QByteArrayLiteral("rosarch-artifacts 1 ") + hash.result().toHex();
}

} // namespace

bool ArtifactWriter::writeAll(const AtomicNodeList &nodes, const QString &dir, QStringList *written,
                              QString *error)
{
    Recovery r;
    r.nodes = nodes;
    return writeAll(r, dir, written, error, false, {}, nullptr);
}

bool ArtifactWriter::writeAll(const Recovery &recovery, const QString &dir, QStringList *written,
                              QString *error, const QByteArray &madeFrom, QString *notice)
{
    return writeAll(recovery, dir, written, error, true, madeFrom, notice);
}

bool ArtifactWriter::writeAll(const Recovery &recovery, const QString &dir, QStringList *written,
                              QString *error, bool withLaunch, const QByteArray &madeFrom,
                              QString *notice)
{
    const AtomicNodeList &nodes = recovery.nodes;
    if (notice)
        notice->clear();
    // The folder holds these artifacts already, untouched since: nothing to write (a warm run).
    const QByteArray stamp = stampOf(recovery, withLaunch, madeFrom);
    if (ArtifactCommit::unchanged(dir, stamp, written)) {
        // Nothing to write, but what killed runs left beside the folder goes all the same.
        ArtifactCommit(dir).removeStale();
        return true;
    }
    // Everything goes into a fresh folder first, swapped in when every file is written: a
    // full disk, a failure or a kill leaves the previous artifacts as they were, never a mix.
    ArtifactCommit commit(dir);
    if (!commit.begin(error))
        return false;
    const auto stage = [&](const QString &relative, const QByteArray &content) {
        return commit.add(relative, content, error);
    };
    // Diagrams quote names from the workspace: no control character reaches them raw.
    const auto text = [](const QString &diagram) {
        return visibleText(diagram, Newlines::Keep).toUtf8();
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
        if (!stage(QStringLiteral("acd/%1.puml").arg(stems.value(n.id)), text(AcdWriter::write(n))))
            return false;
    if (withLaunch) {
        const QMap<QString, QString> ccdStems = CcdWriter::fileStems(recovery.architecture);
        if (!stage(QStringLiteral("architecture.json"),
                   ArchitectureJson::write(recovery.architecture, ccdStems, &recovery.nodes,
                                           &recovery.launch)))
            return false;
        for (const Composite *c : recovery.architecture.representatives()) {
            const QString stem = ccdStems.value(c->instanceId);
            if (!stage(QStringLiteral("ccd/%1.puml").arg(stem), text(CcdWriter::write(*c))) ||
                !stage(QStringLiteral("mermaid/%1.md").arg(stem), text(MermaidWriter::write(*c))))
                return false;
        }
        // The communication graph is the running system's: one per root, as launched.
        for (const Composite &c : recovery.architecture.composites)
            if (c.parentId.isEmpty() &&
                !stage(QStringLiteral("graph/%1.dot")
                           .arg(ccdStems.value(c.instanceId, fileStemOf(c.stem))),
                       text(CommunicationGraph::dot(recovery.architecture, c))))
                return false;
    }

    if (!commit.commit(written, error, stamp))
        return false;
    if (notice && !commit.inPlaceReason().isEmpty())
        *notice = QStringLiteral("The artifacts in %1 were replaced file by file, not in one step, "
                                 "because %2: a run killed meanwhile could have left old and new "
                                 "files mixed.")
                      .arg(dir, commit.inPlaceReason());
    return true;
}

} // namespace rosarch
