#include "artifactwriter.h"
#include "acdwriter.h"
#include "architecturejson.h"
#include "atomicnodesjson.h"
#include "ccdwriter.h"
#include "communicationgraph.h"
#include "launchdependenciesjson.h"
#include "mermaidwriter.h"

#include <QDir>
#include <QSaveFile>

namespace rosarch {

namespace {
bool writeFile(const QString &path, const QByteArray &content, QStringList *written, QString *error)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(content) != content.size() || !f.commit()) {
        *error = QStringLiteral("Cannot write %1: %2").arg(path, f.errorString());
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
    if (!out.mkpath(QStringLiteral("acd"))) {
        *error =
            QStringLiteral("Cannot create the folder %1.").arg(out.filePath(QStringLiteral("acd")));
        return false;
    }
    for (const QString &sub :
         {QStringLiteral("ccd"), QStringLiteral("mermaid"), QStringLiteral("graph")})
        if (withLaunch && !out.mkpath(sub)) {
            *error = QStringLiteral("Cannot create the folder %1.").arg(out.filePath(sub));
            return false;
        }
    // Diagrams of an earlier run would otherwise linger beside the new ones.
    QDir acd(out.filePath(QStringLiteral("acd")));
    QDir ccd(out.filePath(QStringLiteral("ccd")));
    QDir mermaid(out.filePath(QStringLiteral("mermaid")));
    QDir graph(out.filePath(QStringLiteral("graph")));
    for (QDir *d : {&acd, &ccd, &mermaid, &graph})
        for (const QString &old : d->entryList({QStringLiteral("*.puml"), QStringLiteral("*.md"),
                                                QStringLiteral("*.dot"), QStringLiteral("*.svg"),
                                                QStringLiteral("*.png")},
                                               QDir::Files))
            d->remove(old);
    if (!writeFile(out.filePath(QStringLiteral("atomic_nodes.json")), AtomicNodesJson::write(nodes),
                   written, error))
        return false;
    if (withLaunch && !writeFile(out.filePath(QStringLiteral("launch_dependencies.json")),
                                 LaunchDependenciesJson::write(recovery.launch), written, error))
        return false;
    QList<Diagnostic> diagnostics = nodes.diagnostics;
    if (withLaunch) {
        diagnostics.append(recovery.launch.diagnostics);
        diagnostics.append(recovery.architecture.diagnostics);
    }
    if (!writeFile(out.filePath(QStringLiteral("diagnostics.json")),
                   DiagnosticsJson::write(diagnostics), written, error))
        return false;
    const QMap<QString, QString> stems = AcdWriter::fileStems(nodes);
    for (const AtomicNode &n : nodes.nodes) {
        const QString path = acd.filePath(stems.value(n.id) + QStringLiteral(".puml"));
        if (!writeFile(path, AcdWriter::write(n).toUtf8(), written, error))
            return false;
    }
    if (!withLaunch)
        return true;
    const QMap<QString, QString> ccdStems = CcdWriter::fileStems(recovery.architecture);
    if (!writeFile(out.filePath(QStringLiteral("architecture.json")),
                   ArchitectureJson::write(recovery.architecture, ccdStems), written, error))
        return false;
    for (const Composite *c : recovery.architecture.representatives()) {
        const QString path = ccd.filePath(ccdStems.value(c->instanceId) + QStringLiteral(".puml"));
        if (!writeFile(path, CcdWriter::write(*c).toUtf8(), written, error))
            return false;
        const QString md = mermaid.filePath(ccdStems.value(c->instanceId) + QStringLiteral(".md"));
        if (!writeFile(md, MermaidWriter::write(*c).toUtf8(), written, error))
            return false;
        if (!c->parentId.isEmpty())
            continue;
        const QString dot = graph.filePath(ccdStems.value(c->instanceId) + QStringLiteral(".dot"));
        if (!writeFile(dot, CommunicationGraph::dot(recovery.architecture, *c).toUtf8(), written,
                       error))
            return false;
    }
    return true;
}

} // namespace rosarch
