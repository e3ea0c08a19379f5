#include "launch/substitutionevaluator.h"

#include "core/valuebudget.h"
#include "launch/python/pythonlauncheval.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace rosarch {

namespace {

QString joinPath(const QString &a, const QString &b)
{
    if (a.isEmpty())
        return b;
    if (b.isEmpty())
        return a;
    if (b.startsWith(QLatin1Char('/')) && !b.startsWith(QLatin1String("$(")))
        return b; // os.path.join semantics: an absolute part restarts the path
    if (a.endsWith(QLatin1Char('/')))
        return a + b;
    return a + QLatin1Char('/') + b;
}

/// A launch function's boolean argument: "true"/"1" or "false"/"0" (any case), as launch's
/// typed substitutions read them; anything else is no boolean.
std::optional<bool> launchBool(const QString &value)
{
    const QString v = value.trimmed().toLower();
    if (v == QLatin1String("true") || v == QLatin1String("1"))
        return true;
    if (v == QLatin1String("false") || v == QLatin1String("0"))
        return false;
    return std::nullopt;
}

/// $(equals a b) as launch compares: two booleans as booleans, two numbers as close floats,
/// anything else as text.
bool launchEquals(const QString &a, const QString &b)
{
    const QString la = a.toLower(), lb = b.toLower();
    auto isBool = [](const QString &v) {
        return v == QLatin1String("true") || v == QLatin1String("false") ||
               v == QLatin1String("1") || v == QLatin1String("0");
    };
    if (isBool(la) && isBool(lb))
        return (la == QLatin1String("true") || la == QLatin1String("1")) ==
               (lb == QLatin1String("true") || lb == QLatin1String("1"));
    bool okA = false, okB = false;
    const double x = a.trimmed().toDouble(&okA), y = b.trimmed().toDouble(&okB);
    if (okA && okB && !a.trimmed().isEmpty() && !b.trimmed().isEmpty())
        return x == y || std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y));
    return a == b;
}

QString boolText(bool b)
{
    return b ? QStringLiteral("true") : QStringLiteral("false");
}

} // namespace

SubstitutionEvaluator::SubstitutionEvaluator(const QMap<QString, QString> &configurations,
                                             QString launchFileDir, const QSet<QString> *guessed)
    : m_configurations(configurations), m_launchFileDir(std::move(launchFileDir)),
      m_guessed(guessed)
{
}

SubstitutionEvaluator::Result SubstitutionEvaluator::evaluate(const Substitution &s) const
{
    Result r;
    evaluateInto(s, &r, 0);
    return r;
}

void SubstitutionEvaluator::evaluateInto(const Substitution &s, Result *r, int depth) const
{
    const qsizetype before = r->value.size();
    evaluateOne(s, r, depth);
    // Every part is bounded, so a value exceeds the budget by at most its parts' sizes.
    if (r->value.size() > kMaxValueChars) {
        r->value.truncate(before);
        r->unresolved.append(
            {QString::fromLatin1(kEvaluationLimit),
             QStringLiteral("a value longer than %1 characters").arg(kMaxValueChars),
             QString(),
             {}});
    }
}

void SubstitutionEvaluator::evaluateOne(const Substitution &s, Result *r, int depth) const
{
    if (depth > 32) {
        r->unresolved.append({QStringLiteral("substitution"), s.describe(), QString(), {}});
        return;
    }
    auto sub = [&](const Substitution &p) {
        Result inner;
        evaluateInto(p, &inner, depth + 1);
        r->unresolved.append(inner.unresolved);
        return inner.value;
    };
    switch (s.kind) {
    case Substitution::Kind::Text:
        r->value += s.text;
        return;
    case Substitution::Kind::LaunchConfiguration: {
        const auto it = m_configurations.constFind(s.text);
        if (it != m_configurations.constEnd()) {
            r->value += *it;
            if (m_guessed && m_guessed->contains(s.text))
                r->unresolved.append(
                    {QStringLiteral("launch-configuration"), s.describe(), *it, {}});
        } else if (!s.parts.isEmpty()) {
            r->value += sub(s.parts.first());
        } else {
            r->unresolved.append(
                {QStringLiteral("launch-configuration"), s.describe(), QString(), {}});
        }
        return;
    }
    case Substitution::Kind::EnvironmentVariable:
        // The analyst's environment is not the robot's: use the default, never the local value.
        if (!s.parts.isEmpty()) {
            r->value += sub(s.parts.first());
        } else {
            r->unresolved.append({QStringLiteral("environment"), s.describe(), QString(), {}});
        }
        return;
    case Substitution::Kind::FindPackageShare:
    case Substitution::Kind::FindPackagePrefix: {
        QString pkg;
        for (const Substitution &p : s.parts)
            pkg += sub(p);
        r->value += QStringLiteral("$(%1 %2)")
                        .arg(s.kind == Substitution::Kind::FindPackageShare
                                 ? QStringLiteral("find-pkg-share")
                                 : QStringLiteral("find-pkg-prefix"),
                             pkg);
        return;
    }
    case Substitution::Kind::PathJoin: {
        QString path;
        for (const Substitution &p : s.parts)
            path = joinPath(path, sub(p));
        r->value += path;
        return;
    }
    case Substitution::Kind::Concat:
        for (const Substitution &p : s.parts)
            r->value += sub(p);
        return;
    case Substitution::Kind::Eval: {
        QString expression;
        for (const Substitution &p : s.parts)
            expression += sub(p);
        QString value;
        const PythonLaunchEval::Outcome outcome = PythonLaunchEval::evaluate(expression, &value);
        if (outcome == PythonLaunchEval::Outcome::Value) {
            r->value += value;
        } else {
            // Past the nesting bound the expression is said to be so, not only unknown.
            const bool tooDeep = outcome == PythonLaunchEval::Outcome::TooDeep;
            r->unresolved.append(
                {tooDeep ? QStringLiteral("eval-too-deep") : QStringLiteral("eval"),
                 expression,
                 expression,
                 {}});
            r->value += expression;
        }
        return;
    }
    case Substitution::Kind::ThisLaunchFileDir:
        r->value += m_launchFileDir;
        return;
    case Substitution::Kind::ThisLaunchFile:
        r->value += m_launchFileDir + QStringLiteral("/$(filename)");
        return;
    case Substitution::Kind::RewrittenYaml: // the rewrites apply when the file is read
        if (!s.parts.isEmpty())
            r->value += sub(s.parts.first());
        return;
    case Substitution::Kind::Unknown:
        r->unresolved.append({QStringLiteral("substitution"), s.text, s.text, {}});
        r->value += s.text;
        return;
    case Substitution::Kind::Function:
        r->value += function(s, r, depth);
        return;
    }
}

QString SubstitutionEvaluator::function(const Substitution &s, Result *r, int depth) const
{
    QStringList args;
    for (const Substitution &p : s.parts) {
        Result inner;
        evaluateInto(p, &inner, depth + 1);
        r->unresolved.append(inner.unresolved); // a guess in, a guess out
        args << inner.value;
    }
    const QString &name = s.text;
    const auto count = args.size();
    // Booleans of all arguments from `first` on; empty when one is no boolean.
    auto booleans = [&](qsizetype first) {
        QList<bool> out;
        for (qsizetype i = first; i < count; ++i) {
            const std::optional<bool> b = launchBool(args.at(i));
            if (!b)
                return QList<bool>{};
            out << *b;
        }
        return out;
    };
    if ((name == QLatin1String("equals") || name == QLatin1String("not-equals")) && count == 2)
        return boolText(launchEquals(args.at(0), args.at(1)) == (name == QLatin1String("equals")));
    if (name == QLatin1String("if") && (count == 2 || count == 3)) {
        if (const std::optional<bool> c = launchBool(args.at(0)))
            return *c ? args.at(1) : (count == 3 ? args.at(2) : QString());
    } else if (const QList<bool> b = booleans(0); !b.isEmpty() || count == 0) {
        if (name == QLatin1String("not") && count == 1)
            return boolText(!b.first());
        if ((name == QLatin1String("and") && count == 2) || name == QLatin1String("all"))
            return boolText(!b.contains(false));
        if ((name == QLatin1String("or") && count == 2) || name == QLatin1String("any"))
            return boolText(b.contains(true));
    }
    // Not a form launch evaluates (a non-boolean operand, a wrong argument count): undecided.
    r->unresolved.append({QStringLiteral("substitution"), s.describe(), s.describe(), {}});
    return s.describe();
}

bool SubstitutionEvaluator::isTrue(const Substitution &s, QList<Unresolved> *unresolved) const
{
    const Result r = evaluate(s);
    const QString v = r.value.trimmed().toLower();
    if (!r.isResolved()) {
        for (Unresolved u : r.unresolved) {
            if (u.kind != QLatin1String("eval-too-deep")) // a bound hit keeps saying so
                u.kind = QStringLiteral("condition");
            u.guess = QStringLiteral("true");
            unresolved->append(u);
        }
        return true;
    }
    if (v == QLatin1String("true") || v == QLatin1String("1"))
        return true;
    if (v == QLatin1String("false") || v == QLatin1String("0") || v.isEmpty())
        return false;
    unresolved->append({QStringLiteral("condition"), r.value, QStringLiteral("true"), {}});
    return true;
}

bool SubstitutionEvaluator::evaluatePython(const QString &expression, QString *value)
{
    return PythonLaunchEval::evaluate(expression, value) == PythonLaunchEval::Outcome::Value;
}

} // namespace rosarch
