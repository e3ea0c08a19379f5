// LaunchExecutor's parameters: parameter files, what an instance ends up with, its plugins.
#include "core/parameter.h"
#include "core/parameterview.h"
#include "core/rosnames.h"
#include "launch/launchexecutor.h"
#include "workspace/sourcereader.h"

#include <QHash>
#include <QRegularExpression>
#include <QSet>

#include <algorithm>

namespace rosarch {

QList<ParameterSetting> LaunchExecutor::pluginsOf(const QList<ParameterSetting> &parameters)
{
    static const QRegularExpression cls(QStringLiteral(R"(^[A-Za-z_]\w*(::|/)[A-Za-z_][\w:/]*$)"));
    // The names the instance's parameters give (`plugins: [voxel_layer, inflation_layer]`,
    // `progress_checker_plugin: progress_checker`), also under the list's own prefix.
    QSet<QString> named;
    for (const ParameterSetting &p : parameters) {
        if (p.name.endsWith(QLatin1String(".plugin")))
            continue;
        const QString prefix =
            p.name.contains(u'.') ? p.name.section(u'.', 0, -2) + u'.' : QString();
        QStringList items = parameterListItems(p.value);
        if (items.isEmpty())
            items.append(QString(p.value).remove(u'"').remove(u'\'').trimmed());
        for (const QString &item : std::as_const(items)) {
            named.insert(item);
            named.insert(prefix + item);
        }
    }
    QList<ParameterSetting> out;
    for (const ParameterSetting &p : parameters) {
        if (!p.name.endsWith(QLatin1String(".plugin")))
            continue;
        if (!named.contains(p.name.chopped(int(qstrlen(".plugin")))))
            continue; // configured but not in the list that loads plugins: not loaded
        const QString value = p.value.trimmed().remove(QLatin1Char('"')).remove(QLatin1Char('\''));
        if (!cls.match(value).hasMatch())
            continue;
        ParameterSetting plugin = p;
        plugin.name = p.name.chopped(int(qstrlen(".plugin")));
        plugin.value = value;
        out.append(plugin);
    }
    return out;
}

const ParameterFile *LaunchExecutor::parameterFile(const QString &path, const Frame &frame,
                                                   const Evidence &evidence)
{
    const IncludeTarget target = resolveInclude(path, frame.file);
    if (target.file.isEmpty()) {
        if (!m_missingParameterFiles.contains(path)) {
            m_missingParameterFiles.insert(path);
            Diagnostic diag;
            diag.severity = Diagnostic::Severity::Info;
            diag.code = QStringLiteral("no-such-parameter-file");
            diag.message = path.trimmed().isEmpty()
                               ? QStringLiteral("A parameter file is given whose path is empty "
                                                "with the launch arguments' defaults.")
                           : target.external
                               ? QStringLiteral("The parameter file %1 belongs to package %2, "
                                                "which is not in the workspace; its values are "
                                                "not known.")
                                     .arg(path, target.package)
                               : QStringLiteral("The parameter file %1 is not in the workspace; "
                                                "its values are not known.")
                                     .arg(path);
            diag.evidence = evidence;
            m_out->diagnostics.append(diag);
        }
        return nullptr;
    }
    auto it = m_parameterFiles.find(target.file);
    if (it == m_parameterFiles.end()) {
        QByteArray content;
        QList<Diagnostic> problems;
        ParameterFile read;
        if (SourceReader(m_workspace.root).read(target.file, &content, &problems))
            read = ParameterFile::read(content, target.file);
        read.file = target.file;
        m_out->diagnostics.append(problems);
        m_out->diagnostics.append(read.diagnostics);
        it = m_parameterFiles.insert(target.file, read);
    }
    return &*it;
}

QList<ParameterSetting> LaunchExecutor::effectiveParameters(const LaunchAction &a,
                                                            const Scope &scope, const Frame &frame,
                                                            const NodeInstance &n,
                                                            const AtomicNode *cls,
                                                            QList<Unresolved> *u)
{
    QList<ParameterSetting> out;
    QHash<QString, qsizetype> at; // name -> index in `out`
    auto set = [&](const ParameterSetting &s) {
        const auto it = at.constFind(s.name);
        if (it != at.constEnd()) {
            out[*it] = s;
        } else {
            at.insert(s.name, out.size());
            out.append(s);
        }
    };
    for (const ParameterSetting &s : scope.parameters)
        if (!s.name.isEmpty())
            set(s);
    // a file analysed on its own stands at the root: its parameter keys match from there
    QString fqn = RosNames::scopeRelative(RosNames::fullyQualified(n.nameSpace, n.nodeName));
    if (!fqn.startsWith(QLatin1Char('/')))
        fqn.prepend(QLatin1Char('/'));
    for (const LaunchParameter &p : a.parameters) {
        if (!p.isFile) {
            ParameterSetting s{evaluate(p.name, scope, frame, nullptr, p.evidence),
                               evaluate(p.value, scope, frame, nullptr, p.evidence),
                               QStringLiteral("launch"), QString(), p.evidence};
            // launch_ros reads a value given as text as YAML: "10" is an integer
            s.type = parameterValueType(s.value);
            set(s);
            continue;
        }
        const bool rewritten = p.value.kind == Substitution::Kind::RewrittenYaml;
        const Substitution &source = rewritten ? p.value.parts.value(0) : p.value;
        QList<Unresolved> found;
        const QString path = evaluate(source, scope, frame, &found, p.evidence);
        const ParameterFile *file =
            found.isEmpty() ? parameterFile(path, frame, p.evidence) : nullptr;
        if (!file)
            continue; // an unresolved path is reported with the parameters as given
        if (!rewritten) {
            for (const ParameterSetting &s : file->forNode(fqn))
                set(s);
            continue;
        }
        QList<QPair<QString, QString>> rewrites;
        for (qsizetype i = 2; i + 1 < p.value.parts.size(); i += 2)
            rewrites.append({evaluate(p.value.parts.at(i), scope, frame, u, p.evidence),
                             evaluate(p.value.parts.at(i + 1), scope, frame, u, p.evidence)});
        const QString root = evaluate(p.value.parts.value(1), scope, frame, u, p.evidence);
        // one rewritten copy per file, root key and rewrites (a stack starts dozens of nodes
        // with the same one)
        QString key = file->file + QChar(0) + root;
        for (const auto &[name, value] : std::as_const(rewrites))
            key += QChar(0) + name + QChar(1) + value;
        auto it = m_rewrittenFiles.find(key);
        if (it == m_rewrittenFiles.end()) {
            ParameterFile copy = *file;
            copy.rewrite(rewrites, root);
            it = m_rewrittenFiles.insert(key, copy);
        }
        for (ParameterSetting s : it->forNode(fqn)) {
            if (s.source == QLatin1String("launch"))
                s.evidence = p.evidence; // the rewrite decided the value
            set(s);
        }
    }
    // `"~/" + declare_parameter("name", "report")`: the parameter's default is its own part of
    // the port's name, not the joined name.
    auto parameterPart = [](const Port &port) {
        const qsizetype inner =
            port.name.size() - port.parameterPrefix.size() - port.parameterSuffix.size();
        if (inner < 0 || !port.name.startsWith(port.parameterPrefix) ||
            !port.name.endsWith(port.parameterSuffix))
            return port.name;
        return port.name.mid(port.parameterPrefix.size(), inner);
    };
    if (cls) {
        // A name with a placeholder (`{sources}.topic`, `{plugin:CostmapLayer}`) is a pattern
        // the composer fills per item, no parameter of the instance.
        auto byDefault = [&](const QString &name, const QString &value, const Evidence &e) {
            if (!name.isEmpty() && !name.contains(u'{') && !at.contains(name))
                set({name, value, QStringLiteral("default"), QString(), e});
        };
        for (const Port &port : cls->ports) {
            if (port.nameOrigin == NameOrigin::Parameter)
                byDefault(port.parameter, parameterPart(port), port.evidence);
            byDefault(port.guardParameter, port.guardDefault, port.evidence);
        }
    }
    std::sort(out.begin(), out.end(),
              [](const ParameterSetting &x, const ParameterSetting &y) { return x.name < y.name; });
    return out;
}

} // namespace rosarch
