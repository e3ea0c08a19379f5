#include "launch/modelledports.h"
#include "core/rosnames.h"
#include "interfaces/interfacemodel.h"
#include "launch/launchexecutor.h"
#include "workspace/sourcereader.h"

#include <algorithm>

namespace rosarch {

ModelledPorts::ModelledPorts(QString workspaceRoot) : m_root(std::move(workspaceRoot)) {}

void ModelledPorts::forNode(NodeInstance *n, const QStringList &commandLine,
                            const Evidence &evidence, const Resolve &resolve,
                            QList<Diagnostic> *diagnostics)
{
    const InterfaceModel *model = InterfaceModels::builtIn().executable(n->package, n->execName);
    if (!model)
        return;
    n->interfaceModel = model->name;
    n->modelledPorts = model->portsAt(evidence);
    const qsizetype flag =
        model->configArgument.isEmpty() ? -1 : commandLine.indexOf(model->configArgument);
    if (flag < 0 || flag + 1 >= commandLine.size())
        return;
    const QString file = resolve(commandLine.at(flag + 1));
    if (file.isEmpty())
        return; // a file outside the workspace: only the model's own ports
    auto it = m_configFiles.constFind(file);
    if (it == m_configFiles.cend()) {
        QByteArray content;
        if (!SourceReader(m_root).read(file, &content, diagnostics))
            content.clear();
        it = m_configFiles.insert(file, content);
    }
    const auto expanded = [&](const QString &name) {
        return RosNames::expand(name, n->nameSpace, n->nodeName);
    };
    const QList<Port> read = model->portsFromConfig(*it, file, int(n->modelledPorts.size()) + 1);
    if (read.size() >= InterfaceModel::kMaxConfigPorts) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.code = QStringLiteral("launch-evaluation-limit");
        d.message = QStringLiteral("%1 names more than %2 topics; the interface model %3 reads "
                                   "the first %2.")
                        .arg(file)
                        .arg(InterfaceModel::kMaxConfigPorts)
                        .arg(model->name);
        d.evidence = evidence;
        diagnostics->append(d);
    }
    for (const Port &p : read) {
        const bool known =
            std::any_of(n->modelledPorts.cbegin(), n->modelledPorts.cend(), [&](const Port &q) {
                return q.kind == p.kind && expanded(q.name) == expanded(p.name);
            });
        if (!known) // a tool the model already lists (RViz's goal pose)
            n->modelledPorts.append(p);
    }
    n->modelConfig = file;
}

void ModelledPorts::forInclude(LaunchFileInstance *inst, const QString &package,
                               const QString &shareRelative, const QString &scopeNamespace)
{
    const InterfaceModel *model = InterfaceModels::builtIn().launchFile(package, shareRelative);
    if (!model)
        return;
    inst->interfaceModel = model->name;
    inst->modelledPorts = model->portsAt(inst->evidence);
    QString ns = scopeNamespace;
    for (const auto &[name, value] : inst->arguments)
        if (!model->namespaceArgument.isEmpty() && name == model->namespaceArgument)
            ns = joinNamespace(ns, value);
    inst->modelNamespace = ns.isEmpty() ? QStringLiteral("/") : ns;
}

} // namespace rosarch
