#include "pythonexpression.h"

#include <QList>

#include <cmath>
#include <optional>
#include <utility>

namespace rosarch {

namespace {

struct Value
{
    enum Kind
    {
        Str,
        Num,
        Bool,
        List,
        None
    } kind = Str;
    QString s;
    double n = 0;
    bool b = false;
    QList<Value> items;

    static Value string(QString text)
    {
        Value v;
        v.s = std::move(text);
        return v;
    }
    static Value number(double n)
    {
        Value v;
        v.kind = Num;
        v.n = n;
        return v;
    }
    static Value boolean(bool b)
    {
        Value v;
        v.kind = Bool;
        v.b = b;
        return v;
    }

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
        case None:
            return false;
        }
        return false;
    }
    /// As str() prints it; booleans as launch conditions read them.
    QString text() const
    {
        switch (kind) {
        case Str:
            return s;
        case Num:
            if (std::floor(n) == n && std::abs(n) < 1e15)
                return QString::number(qint64(n));
            return QString::number(n);
        case Bool:
            return b ? QStringLiteral("true") : QStringLiteral("false");
        case List: {
            QStringList parts;
            for (const Value &i : items)
                parts << i.repr();
            return QLatin1Char('[') + parts.join(QStringLiteral(", ")) + QLatin1Char(']');
        }
        case None:
            return QStringLiteral("None");
        }
        return {};
    }
    QString repr() const
    {
        if (kind == Str)
            return QLatin1Char('\'') + s + QLatin1Char('\'');
        if (kind == Bool)
            return b ? QStringLiteral("True") : QStringLiteral("False");
        return text();
    }
    bool equals(const Value &o) const
    {
        if ((kind == Num || kind == Bool) && (o.kind == Num || o.kind == Bool))
            return (kind == Num ? n : double(b)) == (o.kind == Num ? o.n : double(o.b));
        if (kind != o.kind)
            return false;
        if (kind == List) {
            if (items.size() != o.items.size())
                return false;
            for (qsizetype i = 0; i < items.size(); ++i)
                if (!items.at(i).equals(o.items.at(i)))
                    return false;
            return true;
        }
        return kind == None || s == o.s;
    }
};

/// Recursive descent over the subset, with Python's precedence: conditional expression, or,
/// and, not, comparisons, + and -, subscripts and method calls, atoms.
class Parser
{
public:
    explicit Parser(const QString &text) : m_s(text) {}

    /// Whether the nesting bound refused the expression.
    bool wentTooDeep() const { return m_tooDeep; }

    bool parse(Value *v)
    {
        if (!expression(v))
            return false;
        skip();
        return m_i == m_s.size() && m_unknown == 0;
    }

private:
    void skip()
    {
        while (m_i < m_s.size() && m_s[m_i].isSpace())
            ++m_i;
    }
    bool keyword(QLatin1StringView kw)
    {
        skip();
        if (!QStringView(m_s).mid(m_i).startsWith(kw))
            return false;
        const qsizetype end = m_i + kw.size();
        if (end < m_s.size() && (m_s[end].isLetterOrNumber() || m_s[end] == QLatin1Char('_')))
            return false;
        m_i = end;
        return true;
    }
    bool symbol(QLatin1StringView sym)
    {
        skip();
        if (!QStringView(m_s).mid(m_i).startsWith(sym))
            return false;
        m_i += sym.size();
        return true;
    }
    QString name()
    {
        skip();
        const qsizetype start = m_i;
        while (m_i < m_s.size() && (m_s[m_i].isLetterOrNumber() || m_s[m_i] == QLatin1Char('_')))
            ++m_i;
        return m_s.mid(start, m_i - start);
    }

    /// What Python would raise on (an index past the end, a string less than a number) or what
    /// is beyond the subset (a method or function it does not know). Only a part that is
    /// evaluated makes the expression unknown: `x[1] if len(x) > 1 else ''` has a value.
    bool unknown(Value *v)
    {
        ++m_unknown;
        *v = Value();
        v->kind = Value::None;
        return true;
    }
    /// Forgets what a part Python does not evaluate found unknown: the `m_unknown` it counted
    /// from `from` to `to`.
    void skipped(int from, int to) { m_unknown -= to - from; }

    /// Guards every rule that can recurse.
    struct Nested
    {
        explicit Nested(Parser *parser) : m_parser(parser) { ++m_parser->m_depth; }
        ~Nested() { --m_parser->m_depth; }
        bool tooDeep() const
        {
            const bool deep = m_parser->m_depth > PythonExpression::kMaxDepth;
            m_parser->m_tooDeep = m_parser->m_tooDeep || deep;
            return deep;
        }
        Parser *m_parser;
    };

    bool expression(Value *v)
    {
        const Nested nested(this);
        const int thenStart = m_unknown;
        if (nested.tooDeep() || !logical(v, true))
            return false;
        const qsizetype before = m_i;
        if (!keyword(QLatin1StringView("if"))) {
            m_i = before;
            return true;
        }
        const int thenEnd = m_unknown;
        Value condition;
        if (!logical(&condition, true) || !keyword(QLatin1StringView("else")))
            return false;
        const int conditionEnd = m_unknown;
        Value otherwise;
        if (!expression(&otherwise))
            return false;
        if (condition.truthy()) {
            skipped(conditionEnd, m_unknown);
        } else {
            const int elseUnknown = m_unknown - conditionEnd;
            m_unknown = thenStart + (conditionEnd - thenEnd) + elseUnknown;
            *v = otherwise;
        }
        return true;
    }
    /// `a or b` (`either`) and `a and b`, which give an operand as Python does, and do not
    /// evaluate the right one when the left decides.
    bool logical(Value *v, bool either)
    {
        const auto operand = [&](Value *o) { return either ? logical(o, false) : notExpr(o); };
        if (!operand(v))
            return false;
        while (keyword(either ? QLatin1StringView("or") : QLatin1StringView("and"))) {
            const int start = m_unknown;
            Value r;
            if (!operand(&r))
                return false;
            if (v->truthy() == either)
                skipped(start, m_unknown); // short-circuited
            else
                *v = r;
        }
        return true;
    }
    bool notExpr(Value *v)
    {
        const Nested nested(this);
        if (nested.tooDeep())
            return false;
        if (keyword(QLatin1StringView("not"))) {
            if (!notExpr(v))
                return false;
            *v = Value::boolean(!v->truthy());
            return true;
        }
        return comparison(v);
    }
    enum Op
    {
        Eq,
        Ne,
        Le,
        Ge,
        Lt,
        Gt,
        In,
        NotIn
    };
    /// The comparison operator at the position, consumed; none (nothing consumed) otherwise.
    std::optional<Op> comparisonOperator()
    {
        static const std::pair<QLatin1StringView, Op> symbols[] = {
            {QLatin1StringView("=="), Eq}, {QLatin1StringView("!="), Ne},
            {QLatin1StringView("<="), Le}, {QLatin1StringView(">="), Ge},
            {QLatin1StringView("<"), Lt},  {QLatin1StringView(">"), Gt}};
        for (const auto &[text, op] : symbols)
            if (symbol(text))
                return op;
        if (keyword(QLatin1StringView("in")))
            return In;
        const qsizetype at = m_i;
        if (keyword(QLatin1StringView("not")) && keyword(QLatin1StringView("in")))
            return NotIn;
        m_i = at;
        return std::nullopt;
    }
    bool comparison(Value *v)
    {
        if (!sum(v))
            return false;
        for (bool compared = false;; compared = true) {
            const std::optional<Op> op = comparisonOperator();
            if (!op)
                return true;
            Value r;
            if (compared || !sum(&r)) // a chain (a < b < c) is beyond the subset
                return false;
            bool result = false;
            switch (*op) {
            case Eq:
            case Ne:
                result = v->equals(r) == (*op == Eq);
                break;
            case In:
            case NotIn:
                if (r.kind == Value::List) {
                    for (const Value &i : std::as_const(r.items))
                        result = result || i.equals(*v);
                } else if (r.kind == Value::Str && v->kind == Value::Str) {
                    result = r.s.contains(v->s);
                } else {
                    return unknown(v);
                }
                result = result != (*op == NotIn);
                break;
            default: {
                int order = 0;
                if (v->kind == Value::Str && r.kind == Value::Str)
                    order = v->s.compare(r.s);
                else if (v->kind == Value::Num && r.kind == Value::Num)
                    order = v->n < r.n ? -1 : (v->n > r.n ? 1 : 0);
                else
                    return unknown(v); // Python refuses to order a string and a number
                result = *op == Le   ? order <= 0
                         : *op == Ge ? order >= 0
                         : *op == Lt ? order < 0
                                     : order > 0;
            }
            }
            *v = Value::boolean(result);
        }
    }
    bool sum(Value *v)
    {
        if (!postfix(v))
            return false;
        for (;;) {
            const bool plus = symbol(QLatin1StringView("+"));
            if (!plus && !symbol(QLatin1StringView("-")))
                return true;
            Value r;
            if (!postfix(&r))
                return false;
            if (v->kind == Value::Num && r.kind == Value::Num)
                *v = Value::number(plus ? v->n + r.n : v->n - r.n);
            else if (plus && v->kind == Value::Str && r.kind == Value::Str)
                v->s += r.s;
            else if (plus && v->kind == Value::List && r.kind == Value::List)
                v->items += r.items;
            else
                unknown(v);
        }
    }
    bool postfix(Value *v)
    {
        if (!atom(v))
            return false;
        for (;;) {
            if (symbol(QLatin1StringView("["))) {
                Value index;
                if (!expression(&index) || !symbol(QLatin1StringView("]")))
                    return false;
                if (!subscript(v, index))
                    unknown(v);
            } else if (symbol(QLatin1StringView("."))) {
                const QString method = name();
                QList<Value> args;
                if (method.isEmpty() || !symbol(QLatin1StringView("(")) || !arguments(&args))
                    return false;
                if (!callMethod(v, method, args))
                    unknown(v);
            } else {
                return true;
            }
        }
    }
    /// The arguments after an opening parenthesis, through the closing one.
    bool arguments(QList<Value> *args)
    {
        if (symbol(QLatin1StringView(")")))
            return true;
        for (;;) {
            Value a;
            if (!expression(&a))
                return false;
            args->append(a);
            if (symbol(QLatin1StringView(")")))
                return true;
            if (!symbol(QLatin1StringView(",")))
                return false;
        }
    }
    static bool subscript(Value *v, const Value &index)
    {
        if (index.kind != Value::Num || std::floor(index.n) != index.n)
            return false;
        const qsizetype size = v->kind == Value::Str ? v->s.size() : v->items.size();
        qsizetype i = qsizetype(index.n);
        if (i < 0)
            i += size;
        if ((v->kind != Value::Str && v->kind != Value::List) || i < 0 || i >= size)
            return false; // an IndexError is no value
        *v = v->kind == Value::Str ? Value::string(v->s.mid(i, 1)) : Value(v->items.at(i));
        return true;
    }
    static bool callMethod(Value *v, const QString &method, const QList<Value> &args)
    {
        if (v->kind != Value::Str)
            return false;
        const auto stringArg = [&](qsizetype i) { return args.at(i).kind == Value::Str; };
        if (method == QLatin1String("split") && args.size() <= 1) {
            QStringList parts;
            if (args.isEmpty())
                parts = v->s.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
            else if (stringArg(0) && !args.at(0).s.isEmpty())
                parts = v->s.split(args.at(0).s);
            else
                return false;
            Value list;
            list.kind = Value::List;
            for (const QString &p : std::as_const(parts))
                list.items.append(Value::string(p));
            *v = list;
            return true;
        }
        if (method == QLatin1String("strip") && args.isEmpty()) {
            v->s = v->s.trimmed();
            return true;
        }
        if (method == QLatin1String("lower") && args.isEmpty()) {
            v->s = v->s.toLower();
            return true;
        }
        if (method == QLatin1String("upper") && args.isEmpty()) {
            v->s = v->s.toUpper();
            return true;
        }
        if (method == QLatin1String("replace") && args.size() == 2 && stringArg(0) &&
            stringArg(1)) {
            v->s.replace(args.at(0).s, args.at(1).s);
            return true;
        }
        if ((method == QLatin1String("startswith") || method == QLatin1String("endswith")) &&
            args.size() == 1 && stringArg(0)) {
            *v =
                Value::boolean(method == QLatin1String("startswith") ? v->s.startsWith(args.at(0).s)
                                                                     : v->s.endsWith(args.at(0).s));
            return true;
        }
        return false;
    }
    static bool callBuiltin(const QString &function, const QList<Value> &args, Value *v)
    {
        if (args.size() != 1)
            return false;
        const Value &a = args.first();
        if (function == QLatin1String("len")) {
            if (a.kind != Value::Str && a.kind != Value::List)
                return false;
            *v = Value::number(double(a.kind == Value::Str ? a.s.size() : a.items.size()));
            return true;
        }
        if (function == QLatin1String("str")) {
            *v = Value::string(a.kind == Value::Bool ? a.repr() : a.text());
            return true;
        }
        if (function == QLatin1String("bool")) {
            *v = Value::boolean(a.truthy());
            return true;
        }
        if (function == QLatin1String("int") || function == QLatin1String("float")) {
            bool ok = a.kind != Value::Str;
            double n = a.kind == Value::Num ? a.n : double(a.b);
            if (a.kind == Value::Str)
                n = a.s.trimmed().toDouble(&ok);
            if (!ok || a.kind == Value::List || a.kind == Value::None)
                return false;
            *v = Value::number(function == QLatin1String("int") ? std::trunc(n) : n);
            return true;
        }
        return false;
    }
    bool atom(Value *v)
    {
        const Nested nested(this);
        skip();
        if (nested.tooDeep() || m_i >= m_s.size())
            return false;
        const QChar c = m_s[m_i];
        if (c == QLatin1Char('(')) {
            ++m_i;
            return expression(v) && symbol(QLatin1StringView(")"));
        }
        if (c == QLatin1Char('[')) {
            ++m_i;
            *v = Value();
            v->kind = Value::List;
            QList<Value> items;
            if (!symbol(QLatin1StringView("]"))) {
                for (;;) {
                    Value item;
                    if (!expression(&item))
                        return false;
                    items.append(item);
                    if (symbol(QLatin1StringView("]")))
                        break;
                    if (!symbol(QLatin1StringView(",")))
                        return false;
                    if (symbol(QLatin1StringView("]"))) // a trailing comma
                        break;
                }
            }
            v->items = items;
            return true;
        }
        if (c == QLatin1Char('\'') || c == QLatin1Char('"')) {
            const qsizetype end = m_s.indexOf(c, m_i + 1);
            if (end < 0)
                return false;
            *v = Value::string(m_s.mid(m_i + 1, end - m_i - 1));
            m_i = end + 1;
            return true;
        }
        if (c.isDigit() || c == QLatin1Char('-') || c == QLatin1Char('.')) {
            const bool negative = c == QLatin1Char('-');
            if (negative)
                ++m_i;
            if (negative && m_i < m_s.size() && !m_s[m_i].isDigit() && m_s[m_i] != '.') {
                Value operand; // -(...), -len(...)
                if (!atom(&operand))
                    return false;
                if (operand.kind != Value::Num)
                    return unknown(v);
                *v = Value::number(-operand.n);
                return true;
            }
            const qsizetype start = m_i;
            while (m_i < m_s.size() && (m_s[m_i].isDigit() || m_s[m_i] == QLatin1Char('.')))
                ++m_i;
            bool ok = false;
            const double n = m_s.mid(start, m_i - start).toDouble(&ok);
            if (!ok)
                return false;
            *v = Value::number(negative ? -n : n);
            return true;
        }
        const QString word = name();
        if (word == QLatin1String("True") || word == QLatin1String("true")) {
            *v = Value::boolean(true);
            return true;
        }
        if (word == QLatin1String("False") || word == QLatin1String("false")) {
            *v = Value::boolean(false);
            return true;
        }
        if (word == QLatin1String("None")) {
            *v = Value();
            v->kind = Value::None;
            return true;
        }
        QList<Value> args;
        if (word.isEmpty() || !symbol(QLatin1StringView("(")) || !arguments(&args))
            return false; // a bare name: nothing to evaluate it against
        return callBuiltin(word, args, v) || unknown(v);
    }

    const QString &m_s;
    qsizetype m_i = 0;
    int m_depth = 0;
    bool m_tooDeep = false;
    int m_unknown = 0; ///< evaluated parts without a value
};

} // namespace

bool PythonExpression::evaluate(const QString &expression, QString *value, bool *tooDeep)
{
    Value v;
    Parser parser(expression);
    const bool parsed = parser.parse(&v);
    if (tooDeep)
        *tooDeep = parser.wentTooDeep();
    if (!parsed)
        return false;
    *value = v.text();
    return true;
}

} // namespace rosarch
