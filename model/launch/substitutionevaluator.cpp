#include "substitutionevaluator.h"

#include <QRegularExpression>

namespace rosarch {

namespace {

/// A recursive-descent evaluator for the tiny Python subset launch files use in conditions.
class PyExpr
{
public:
    explicit PyExpr(const QString &text) : m_s(text) {}

    bool parse(QString *out)
    {
        Value v;
        if (!orExpr(&v))
            return false;
        skip();
        if (m_i != m_s.size())
            return false;
        *out = v.text();
        return true;
    }

private:
    struct Value
    {
        enum Kind
        {
            Str,
            Num,
            Bool,
            List
        } kind = Str;
        QString s;
        double n = 0;
        bool b = false;
        QList<Value> items;
        bool truthy() const
        {
            switch (kind) {
            case Str:
                return !s.isEmpty();
            case Num:
                return n != 0;
            case Bool:
                return b;
            case List:
                return !items.isEmpty();
            }
            return false;
        }
        QString text() const
        {
            switch (kind) {
            case Str:
                return s;
            case Num:
                return QString::number(n);
            case Bool:
                return b ? QStringLiteral("true") : QStringLiteral("false");
            case List:
                return QStringLiteral("[...]");
            }
            return {};
        }
        bool equals(const Value &o) const
        {
            if (kind == Num && o.kind == Num)
                return n == o.n;
            if (kind == Bool && o.kind == Bool)
                return b == o.b;
            return kind == o.kind && s == o.s;
        }
    };

    void skip()
    {
        while (m_i < m_s.size() && m_s[m_i].isSpace())
            ++m_i;
    }
    bool keyword(const char *kw)
    {
        skip();
        const QString k = QString::fromLatin1(kw);
        if (!m_s.mid(m_i).startsWith(k))
            return false;
        const qsizetype end = m_i + k.size();
        if (end < m_s.size() && (m_s[end].isLetterOrNumber() || m_s[end] == QLatin1Char('_')))
            return false;
        m_i = end;
        return true;
    }
    bool symbol(const char *sym)
    {
        skip();
        const QString k = QString::fromLatin1(sym);
        if (!m_s.mid(m_i).startsWith(k))
            return false;
        m_i += k.size();
        return true;
    }
    static Value boolean(bool b)
    {
        Value v;
        v.kind = Value::Bool;
        v.b = b;
        return v;
    }
    bool orExpr(Value *v)
    {
        if (!andExpr(v))
            return false;
        while (keyword("or")) {
            Value r;
            if (!andExpr(&r))
                return false;
            *v = boolean(v->truthy() || r.truthy());
        }
        return true;
    }
    bool andExpr(Value *v)
    {
        if (!notExpr(v))
            return false;
        while (keyword("and")) {
            Value r;
            if (!notExpr(&r))
                return false;
            *v = boolean(v->truthy() && r.truthy());
        }
        return true;
    }
    bool notExpr(Value *v)
    {
        if (keyword("not")) {
            if (!notExpr(v))
                return false;
            *v = boolean(!v->truthy());
            return true;
        }
        return comparison(v);
    }
    bool comparison(Value *v)
    {
        if (!atom(v))
            return false;
        for (;;) {
            if (symbol("==") || symbol("!=")) {
                const bool eq = m_s.mid(m_i - 2, 2) == QLatin1String("==");
                Value r;
                if (!atom(&r))
                    return false;
                *v = boolean(v->equals(r) == eq);
            } else if (bool negated = false; keyword("in") || (negated = keyword("not"))) {
                if (negated && !keyword("in"))
                    return false;
                Value r;
                if (!atom(&r) || r.kind != Value::List)
                    return false;
                bool found = false;
                for (const Value &i : r.items)
                    found = found || i.equals(*v);
                *v = boolean(found != negated);
            } else {
                return true;
            }
        }
    }
    bool atom(Value *v)
    {
        skip();
        if (m_i >= m_s.size())
            return false;
        const QChar c = m_s[m_i];
        if (c == QLatin1Char('(')) {
            ++m_i;
            if (!orExpr(v) || !symbol(")"))
                return false;
            return true;
        }
        if (c == QLatin1Char('[')) {
            ++m_i;
            v->kind = Value::List;
            v->items.clear();
            if (symbol("]"))
                return true;
            for (;;) {
                Value item;
                if (!orExpr(&item))
                    return false;
                v->items.append(item);
                if (symbol("]"))
                    return true;
                if (!symbol(","))
                    return false;
            }
        }
        if (c == QLatin1Char('\'') || c == QLatin1Char('"')) {
            const qsizetype end = m_s.indexOf(c, m_i + 1);
            if (end < 0)
                return false;
            v->kind = Value::Str;
            v->s = m_s.mid(m_i + 1, end - m_i - 1);
            m_i = end + 1;
            return true;
        }
        if (keyword("True") || keyword("true")) {
            *v = boolean(true);
            return true;
        }
        if (keyword("False") || keyword("false")) {
            *v = boolean(false);
            return true;
        }
        static const QRegularExpression number(QStringLiteral("^-?\\d+(\\.\\d+)?"));
        const auto m = number.match(m_s.mid(m_i));
        if (m.hasMatch()) {
            v->kind = Value::Num;
            v->n = m.captured(0).toDouble();
            m_i += m.capturedLength();
            return true;
        }
        return false;
    }

    QString m_s;
    qsizetype m_i = 0;
};

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

} // namespace

SubstitutionEvaluator::SubstitutionEvaluator(const QMap<QString, QString> &configurations,
                                             QString launchFileDir)
    : m_configurations(configurations), m_launchFileDir(std::move(launchFileDir))
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
        if (evaluatePython(expression, &value)) {
            r->value += value;
        } else {
            r->unresolved.append({QStringLiteral("eval"), expression, expression, {}});
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
    }
}

bool SubstitutionEvaluator::isTrue(const Substitution &s, QList<Unresolved> *unresolved) const
{
    const Result r = evaluate(s);
    const QString v = r.value.trimmed().toLower();
    if (!r.isResolved()) {
        for (Unresolved u : r.unresolved) {
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
    return PyExpr(expression).parse(value);
}

} // namespace rosarch
