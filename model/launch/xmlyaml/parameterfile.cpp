#include "launch/xmlyaml/parameterfile.h"

#include "core/parameter.h"
#include "launch/xmlyaml/yamlsupport.h"

#include <QHash>
#include <QStringList>

#include <functional>

namespace rosarch {

namespace {

constexpr int kMaxDepth = 64; // parameter files nest a few levels; deeper keys are skipped
const QLatin1String kParameters("ros__parameters");

Evidence evidenceAt(const QString &file, const YAML::Node &key)
{
    const YAML::Mark m = key.Mark();
    if (m.is_null())
        return Evidence::startOf(file);
    return {file, m.line + 1, m.column + 1, m.line + 1,
            m.column + 1 + int(key.IsScalar() ? key.Scalar().size() : 0)};
}

/// The node key a path of YAML keys stands for: "ns", "node" -> "/ns/node".
QString patternOf(const QStringList &path)
{
    QStringList segments;
    for (const QString &key : path)
        for (const QString &s : key.split(QLatin1Char('/'), Qt::SkipEmptyParts))
            segments << s;
    return QLatin1Char('/') + segments.join(QLatin1Char('/'));
}

bool matchSegments(const QStringList &pattern, qsizetype p, const QStringList &name, qsizetype n,
                   int depth)
{
    if (depth > 64)
        return false;
    if (p == pattern.size())
        return n == name.size();
    if (pattern.at(p) == QLatin1String("**")) {
        for (qsizetype k = n; k <= name.size(); ++k)
            if (matchSegments(pattern, p + 1, name, k, depth + 1))
                return true;
        return false;
    }
    if (n == name.size())
        return false;
    if (pattern.at(p) != QLatin1String("*") && pattern.at(p) != name.at(n))
        return false;
    return matchSegments(pattern, p + 1, name, n + 1, depth + 1);
}

} // namespace

ParameterFile ParameterFile::read(const QByteArray &content, const QString &file)
{
    ParameterFile out;
    out.file = file;
    Diagnostic error;
    const YAML::Node root = loadYaml(content, file, &error);
    if (!error.code.isEmpty())
        out.diagnostics << error;
    YamlBudget budget;
    bool deep = false;
    std::function<void(const YAML::Node &, const QString &, QList<ParameterSetting> *, int)>
        flatten = [&](const YAML::Node &map, const QString &prefix, QList<ParameterSetting> *into,
                      int depth) {
            for (const auto &kv : map) {
                if (!budget.spend())
                    return;
                if (depth > kMaxDepth) {
                    deep = true;
                    return;
                }
                const QString name = prefix + QString::fromStdString(kv.first.Scalar());
                if (kv.second.IsMap()) {
                    flatten(kv.second, name + QLatin1Char('.'), into, depth + 1);
                    continue;
                }
                ParameterSetting s;
                s.name = name;
                s.value = yamlValueText(kv.second, &budget, kMaxDepth, depth + 1);
                s.source = QStringLiteral("file");
                // a quoted scalar is a string whatever it reads as ("10")
                s.type =
                    parameterValueType(s.value, kv.second.IsScalar() && kv.second.Tag() == "!");
                if (kv.second.IsSequence() && kv.second.size() > 0 && kv.second[0].IsScalar() &&
                    kv.second[0].Tag() == "!")
                    s.type = QStringLiteral("string_array"); // ['0', '1']
                s.file = file;
                s.evidence = evidenceAt(file, kv.first);
                *into << s;
            }
        };
    std::function<void(const YAML::Node &, QStringList, int)> walk =
        [&](const YAML::Node &map, QStringList path, int depth) {
            for (const auto &kv : map) {
                if (!budget.spend())
                    return;
                if (depth > kMaxDepth) {
                    deep = true;
                    return;
                }
                if (!kv.first.IsScalar())
                    continue;
                const QString key = QString::fromStdString(kv.first.Scalar());
                if (key == kParameters) {
                    Entry e;
                    e.pattern = patternOf(path);
                    if (kv.second.IsMap())
                        flatten(kv.second, QString(), &e.parameters, depth + 1);
                    out.entries << e;
                } else if (kv.second.IsMap()) {
                    walk(kv.second, path + QStringList{key}, depth + 1);
                }
            }
        };
    try {
        if (root.IsMap())
            walk(root, {}, 0);
    } catch (const YAML::Exception &ex) { // not expected on a loaded tree; never fatal
        Diagnostic diag;
        diag.code = QStringLiteral("malformed-yaml");
        diag.message =
            QStringLiteral("Cannot read the YAML tree: %1.").arg(QString::fromStdString(ex.msg));
        diag.evidence = Evidence::startOf(file);
        out.diagnostics << diag;
    }
    if (budget.exhausted || deep) {
        Diagnostic diag;
        diag.code = QStringLiteral("launch-evaluation-limit");
        diag.message =
            budget.exhausted
                ? QStringLiteral("The parameter file has more than %1 YAML nodes "
                                 "(counting shared aliases); the rest is not read.")
                      .arg(YamlBudget::kVisits)
                : QStringLiteral("Keys nested deeper than %1 levels are not read.").arg(kMaxDepth);
        diag.evidence = Evidence::startOf(file);
        out.diagnostics << diag;
    }
    if (out.entries.isEmpty() && error.code.isEmpty()) {
        Diagnostic diag;
        diag.severity = Diagnostic::Severity::Warning;
        diag.code = QStringLiteral("parameter-file-unused");
        diag.message = QStringLiteral("%1 has no ros__parameters section, so it gives no node a "
                                      "parameter.")
                           .arg(file);
        diag.evidence = Evidence::startOf(file);
        out.diagnostics << diag;
    }
    return out;
}

void ParameterFile::rewrite(const QList<QPair<QString, QString>> &rewrites, const QString &rootKey)
{
    for (Entry &e : entries) {
        for (ParameterSetting &s : e.parameters) {
            const QString leaf = s.name.section(QLatin1Char('.'), -1);
            for (const auto &[key, value] : rewrites) {
                const bool byValue = key.startsWith(QLatin1Char('='));
                if (byValue ? s.value == key.mid(1) : key == s.name || key == leaf) {
                    s.value = value;
                    s.type = parameterValueType(value);  // RewrittenYaml converts the text
                    s.source = QStringLiteral("launch"); // the launch file decides it now
                }
            }
        }
        const QString root = rootKey.trimmed();
        if (!root.isEmpty())
            e.pattern = patternOf({root, e.pattern});
    }
}

QList<ParameterSetting> ParameterFile::forNode(const QString &fqn) const
{
    QList<ParameterSetting> out;
    QHash<QString, qsizetype> at; // name -> index in `out`
    auto apply = [&](const Entry &e) {
        for (const ParameterSetting &s : e.parameters) {
            const auto it = at.constFind(s.name);
            if (it != at.constEnd()) {
                out[*it] = s;
            } else {
                at.insert(s.name, out.size());
                out << s;
            }
        }
    };
    for (const Entry &e : entries) {
        if (!e.pattern.contains(QLatin1Char('*')) || !matches(e.pattern, fqn))
            continue;
        Entry many = e;
        for (ParameterSetting &s : many.parameters)
            s.wildcard = true;
        apply(many);
    }
    for (const Entry &e : entries)
        if (!e.pattern.contains(QLatin1Char('*')) && matches(e.pattern, fqn))
            apply(e);
    return out;
}

bool ParameterFile::matches(const QString &pattern, const QString &fqn)
{
    const QStringList p = pattern.split(QLatin1Char('/'), Qt::SkipEmptyParts);
    const QStringList n = fqn.split(QLatin1Char('/'), Qt::SkipEmptyParts);
    return matchSegments(p, 0, n, 0, 0);
}

} // namespace rosarch
