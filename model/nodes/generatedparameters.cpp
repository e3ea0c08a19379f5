#include "nodes/generatedparameters.h"

#include "workspace/sourcereader.h"

#include <QDir>
#include <QRegularExpression>

#include <functional>

#include <yaml-cpp/yaml.h>

namespace rosarch {

namespace {

constexpr int kMaxDepth = 16;
constexpr int kMaxEntries = 20000;

QString typeOf(const QString &written)
{
    QString t = written.trimmed();
    t.remove(QRegularExpression(QStringLiteral("_fixed_\\d+$")));
    if (t.startsWith(QLatin1String("int")))
        t.replace(0, 3, QStringLiteral("integer"));
    return t == QLatin1String("none") ? QString() : t; // a dynamically typed parameter
}

QString scalarText(const YAML::Node &n, int depth = 0)
{
    if (n.IsScalar())
        return QString::fromStdString(n.Scalar());
    if (!n.IsSequence() || depth > kMaxDepth)
        return {};
    QStringList items;
    for (const YAML::Node &item : n)
        items << scalarText(item, depth + 1);
    return QLatin1Char('[') + items.join(QStringLiteral(", ")) + QLatin1Char(']');
}

} // namespace

QList<ParameterDeclaration> GeneratedParameters::read(const QByteArray &content,
                                                      const QString &file,
                                                      QList<Diagnostic> *diagnostics)
{
    QList<ParameterDeclaration> out;
    YAML::Node root;
    try {
        root = YAML::Load(content.toStdString());
    } catch (const YAML::Exception &ex) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.code = QStringLiteral("malformed-yaml");
        d.message = QStringLiteral("The parameter definitions cannot be read: %1.")
                        .arg(QString::fromStdString(ex.msg));
        d.evidence = {file, ex.mark.is_null() ? 1 : ex.mark.line + 1, 1,
                      ex.mark.is_null() ? 1 : ex.mark.line + 1, 1};
        diagnostics->append(d);
        return out;
    }
    if (!root.IsMap())
        return out;
    int entries = 0;
    bool cut = false;
    std::function<void(const YAML::Node &, const QString &, int)> walk = [&](const YAML::Node &map,
                                                                             const QString &prefix,
                                                                             int depth) {
        if (!map.IsMap())
            return;
        if (depth > kMaxDepth) {
            cut = true;
            return;
        }
        for (const auto &kv : map) {
            if (++entries > kMaxEntries) {
                cut = true;
                return;
            }
            if (!kv.first.IsScalar())
                continue;
            QString key = QString::fromStdString(kv.first.Scalar());
            if (key.startsWith(QLatin1String("__map_")))
                key = QStringLiteral("{%1}").arg(key.mid(6));
            const QString name = prefix.isEmpty() ? key : prefix + QLatin1Char('.') + key;
            const YAML::Node &value = kv.second;
            if (!value.IsMap())
                continue;
            const YAML::Node type = value["type"];
            if (!type || !type.IsScalar()) {
                walk(value, name, depth + 1);
                continue;
            }
            ParameterDeclaration p;
            p.name = name;
            p.type = typeOf(QString::fromStdString(type.Scalar()));
            p.via = QStringLiteral("generate_parameter_library");
            if (const YAML::Node v = value["default_value"]) {
                p.hasDefault = true;
                p.defaultValue = scalarText(v);
            }
            if (const YAML::Node v = value["description"]; v && v.IsScalar())
                p.description = QString::fromStdString(v.Scalar()).simplified();
            if (const YAML::Node v = value["read_only"]; v && v.IsScalar())
                p.readOnly = v.Scalar() == "true" || v.Scalar() == "True";
            if (const YAML::Node v = value["validation"]; v && v.IsMap()) {
                for (const auto &rule : v) {
                    if (!rule.first.IsScalar())
                        continue;
                    const std::string r = rule.first.Scalar();
                    const QString args = scalarText(rule.second);
                    if (r == "bounds<>" && rule.second.IsSequence() && rule.second.size() == 2)
                        p.range = args;
                    else if (r == "one_of<>" && rule.second.IsSequence() && rule.second.size() == 1)
                        p.range = QStringLiteral("one of ") + scalarText(rule.second[0]);
                }
            }
            const YAML::Mark m = kv.first.Mark();
            p.evidence = {file, m.line + 1, m.column + 1, m.line + 1,
                          m.column + 1 + int(kv.first.Scalar().size())};
            out.append(p);
        }
    };
    // the top-level key names the generated namespace, not a parameter prefix
    try {
        for (const auto &top : root)
            walk(top.second, QString(), 0);
    } catch (const YAML::Exception &) {
        cut = true;
    }
    if (cut) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Info;
        d.code = QStringLiteral("evaluation-limit");
        d.message = QStringLiteral("The parameter definitions nest deeper than %1 levels, have "
                                   "more than %2 entries or cannot be read to the end; the rest "
                                   "is not read, so the nodes using them lack those parameters.")
                        .arg(kMaxDepth)
                        .arg(kMaxEntries);
        d.evidence = Evidence::startOf(file);
        diagnostics->append(d);
    }
    return out;
}

void GeneratedParameters::apply(const Workspace &workspace, AtomicNodeList *list)
{
    static const QRegularExpression call(
        QStringLiteral("generate_parameter_library\\s*\\(\\s*([A-Za-z0-9_\\-]+)\\s+([^\\s)]+)"));
    const SourceReader reader(workspace.root);
    for (const RosPackage &pkg : workspace.packages) {
        const QString cmake = QDir(pkg.path).filePath(QStringLiteral("CMakeLists.txt"));
        QByteArray content;
        QList<Diagnostic> ignored;
        if (!reader.read(cmake, &content, &ignored) ||
            !content.contains("generate_parameter_library"))
            continue;
        const QString text = QString::fromUtf8(content);
        for (auto it = call.globalMatch(text); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            const QString target = m.captured(1);
            QString yaml = m.captured(2).remove(u'"');
            if (yaml.contains(u'$'))
                continue; // a path a variable decides
            yaml = QDir::cleanPath(QDir(pkg.path).filePath(yaml));
            QByteArray definitions;
            if (!reader.read(yaml, &definitions, &list->diagnostics))
                continue;
            const QList<ParameterDeclaration> declared =
                read(definitions, yaml, &list->diagnostics);
            const QByteArray header = (target + QStringLiteral(".hpp")).toUtf8();
            for (AtomicNode &n : list->nodes) {
                if (n.packageName != pkg.name)
                    continue;
                bool includes = false;
                for (const QString &f : n.headerFiles + n.sourceFiles) {
                    QByteArray source;
                    QList<Diagnostic> skipped;
                    includes =
                        includes || (reader.read(f, &source, &skipped) && source.contains(header));
                }
                if (!includes)
                    continue;
                for (const ParameterDeclaration &d : declared)
                    if (std::none_of(
                            n.parameters.begin(), n.parameters.end(),
                            [&](const ParameterDeclaration &e) { return e.name == d.name; }))
                        n.parameters.append(d);
            }
        }
    }
}

} // namespace rosarch
