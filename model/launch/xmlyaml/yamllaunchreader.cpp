#include "launch/xmlyaml/yamllaunchreader.h"
#include "launch/xmlyaml/frontendactionmapper.h"
#include "launch/xmlyaml/yamlsupport.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>

namespace rosarch {

namespace {

// Launch files nest a handful of levels; deeper entities are skipped so that mapping them can
// never exhaust the stack.
constexpr int kMaxDepth = 200;

using Budget = YamlBudget;

struct Position
{
    int line = 0;
    int column = 0;
    bool operator<(const Position &o) const
    {
        return line != o.line ? line < o.line : column < o.column;
    }
};

Position startOf(const YAML::Node &n)
{
    const YAML::Mark m = n.Mark();
    if (m.is_null())
        return {};
    return {m.line + 1, m.column + 1};
}

// yaml-cpp keeps no end marks: the end is where the last scalar inside ends.
void extendEnd(const YAML::Node &n, Position *end, Budget *budget, int depth = 0)
{
    if (depth > kMaxDepth || !budget->spend())
        return;
    if (n.IsScalar()) {
        Position p = startOf(n);
        const bool quoted = n.Tag() == "!";
        p.column += int(n.Scalar().size()) + (quoted ? 2 : 0);
        *end = std::max(*end, p);
    } else if (n.IsSequence()) {
        for (const YAML::Node &item : n)
            extendEnd(item, end, budget, depth + 1);
    } else if (n.IsMap()) {
        for (const auto &kv : n) {
            extendEnd(kv.first, end, budget, depth + 1);
            extendEnd(kv.second, end, budget, depth + 1);
        }
    }
}

QString scalarText(const YAML::Node &n, Budget *budget)
{
    return yamlValueText(n, budget, kMaxDepth);
}

bool isListOfMappings(const YAML::Node &n)
{
    if (!n.IsSequence() || n.size() == 0)
        return false;
    return std::all_of(n.begin(), n.end(), [](const YAML::Node &item) { return item.IsMap(); });
}

class EntityBuilder
{
public:
    EntityBuilder(const QString &file, QList<Diagnostic> *diagnostics)
        : m_file(file), m_diagnostics(diagnostics)
    {
    }

    Evidence evidence(const YAML::Node &start, const YAML::Node &content)
    {
        Evidence e;
        e.file = m_file;
        const Position begin = startOf(start);
        Position end = begin;
        Budget local; // each range and value has its own budget: one large one cuts only itself
        extendEnd(content, &end, &local);
        m_cut = m_cut || local.exhausted;
        e.line = begin.line;
        e.column = begin.column;
        e.endLine = end.line;
        e.endColumn = end.column;
        return e;
    }

    /// Items of `children` (or of the root `launch` list): each a mapping {type: entity}.
    void appendChildren(const YAML::Node &list, QList<FrontendEntity> *out, int depth)
    {
        for (const YAML::Node &item : list) {
            if (!m_budget.spend())
                return;
            if (!item.IsMap() || item.size() != 1) {
                report(QStringLiteral("invalid-entity"),
                       QStringLiteral("A launch entity must be a mapping with one key, the "
                                      "entity type."),
                       evidence(item, item));
                continue;
            }
            const auto kv = *item.begin();
            *out << build(QString::fromStdString(kv.first.Scalar()), item, kv.second, depth + 1);
        }
    }

    FrontendEntity build(const QString &type, const YAML::Node &start, const YAML::Node &n,
                         int depth)
    {
        FrontendEntity e;
        e.type = type;
        e.evidence = evidence(start, n);
        if (depth > kMaxDepth) {
            report(
                QStringLiteral("nesting-too-deep"),
                QStringLiteral("Entities nested deeper than %1 levels are skipped.").arg(kMaxDepth),
                e.evidence);
            return e;
        }
        if (n.IsSequence()) { // `- group: [ ...children ]`
            appendChildren(n, &e.children, depth);
            return e;
        }
        if (!n.IsMap())
            return e;
        for (const auto &kv : n) {
            if (!m_budget.spend())
                break;
            const QString key =
                QString::fromStdString(kv.first.IsScalar() ? kv.first.Scalar() : std::string());
            const YAML::Node &v = kv.second;
            if (key == u"children" && v.IsSequence()) {
                appendChildren(v, &e.children, depth);
            } else if (isListOfMappings(v)) {
                for (const YAML::Node &item : v)
                    e.children << build(key, item, item, depth + 1);
            } else if (v.IsMap()) { // a single nested entity written without its list
                e.children << build(key, kv.first, v, depth + 1);
            } else {
                FrontendAttribute a;
                a.name = key;
                Budget local;
                a.value = scalarText(v, &local);
                m_cut = m_cut || local.exhausted;
                a.evidence = evidence(v.IsNull() ? kv.first : v, v.IsNull() ? kv.first : v);
                e.attributes << a;
            }
        }
        return e;
    }

    /// After the walk: a diagnostic when the budget ran out, naming where reading stopped.
    void reportBudget()
    {
        if (!m_budget.exhausted && !m_cut)
            return;
        const Evidence e = Evidence::startOf(m_file);
        report(QStringLiteral("launch-evaluation-limit"),
               QStringLiteral("The YAML in %1 expands (through aliases) to more than %2 nodes; "
                              "%3")
                   .arg(m_file)
                   .arg(Budget::kVisits)
                   .arg(m_budget.exhausted
                            ? QStringLiteral("reading stopped there, so later entities are "
                                             "missing.")
                            : QStringLiteral("the values and ranges that large were cut "
                                             "short.")),
               e);
    }

private:
    void report(const QString &code, const QString &message, const Evidence &evidence)
    {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.code = code;
        d.message = message;
        d.evidence = evidence;
        m_diagnostics->append(d);
    }

    QString m_file;
    QList<Diagnostic> *m_diagnostics;
    Budget m_budget;    ///< entities and attributes of the whole file
    bool m_cut = false; ///< a value or an evidence range ran out of its own budget
};

} // namespace

bool YamlLaunchReader::isLaunchFile(const QByteArray &content)
{
    // A top-level `launch:` key holding a list of entities. Looking at lines is enough, and
    // cheap: parameter files have no such key, and other YAML with a `launch:` mapping (design
    // files, configs) is told apart by what follows.
    bool afterKey = false;
    qsizetype pos = 0;
    while (pos < content.size()) {
        qsizetype eol = content.indexOf('\n', pos);
        if (eol < 0)
            eol = content.size();
        const QByteArray line = content.mid(pos, eol - pos);
        pos = eol + 1;
        const QByteArray trimmed = line.trimmed();
        if (afterKey) {
            if (trimmed.isEmpty() || trimmed.startsWith('#'))
                continue;
            return trimmed == "-" || trimmed.startsWith("- ") || trimmed.startsWith("-\t");
        }
        if (!line.startsWith("launch"))
            continue;
        const QByteArray rest = line.mid(6).trimmed();
        if (!rest.startsWith(':'))
            continue;
        const QByteArray value = rest.mid(1).trimmed();
        if (value.startsWith('['))
            return true;
        afterKey = value.isEmpty() || value.startsWith('#');
    }
    return false;
}

LaunchFileDescription YamlLaunchReader::read(const QByteArray &content, const QString &file)
{
    LaunchFileDescription d;
    d.file = file;
    d.format = LaunchFileDescription::Format::Yaml;

    Diagnostic error;
    const YAML::Node root = loadYaml(content, file, &error);

    const YAML::Node &r = root;
    const YAML::Node launch = r.IsMap() ? r["launch"] : YAML::Node();
    if (launch.IsDefined() && (launch.IsSequence() || (launch.IsMap() && launch["children"]))) {
        EntityBuilder builder(file, &d.diagnostics);
        FrontendEntity entity;
        try {
            entity = builder.build(QStringLiteral("launch"), launch, launch, 0);
            builder.reportBudget();
        } catch (const YAML::Exception &ex) { // not expected on a loaded tree; never fatal
            Diagnostic diag;
            diag.code = QStringLiteral("malformed-yaml");
            diag.message = QStringLiteral("Cannot read the YAML tree: %1.")
                               .arg(QString::fromStdString(ex.msg));
            diag.evidence = Evidence::startOf(file);
            d.diagnostics << diag;
        }
        FrontendActionMapper mapper(&d.diagnostics);
        d.actions = mapper.map(entity.children);
    } else if (error.code.isEmpty()) {
        Diagnostic diag;
        diag.code = QStringLiteral("not-a-launch-file");
        diag.message = QStringLiteral("The YAML file has no top-level 'launch' list.");
        diag.evidence = Evidence::startOf(file);
        d.diagnostics << diag;
    }
    if (!error.code.isEmpty())
        d.diagnostics << error;
    return d;
}

} // namespace rosarch
