// What Python's literals and operators mean on symbolic values.
#include "launch/python/pythonlaunchoperators.h"

namespace rosarch::pylaunch {

QString decodeEscapes(const QString &s)
{
    if (!s.contains(QLatin1Char('\\')))
        return s;
    QString out;
    out.reserve(s.size());
    for (qsizetype i = 0; i < s.size(); ++i) {
        const QChar c = s.at(i);
        if (c != QLatin1Char('\\') || i + 1 >= s.size()) {
            out += c;
            continue;
        }
        const QChar n = s.at(++i);
        switch (n.unicode()) {
        case 'n':
            out += QLatin1Char('\n');
            break;
        case 't':
            out += QLatin1Char('\t');
            break;
        case 'r':
            out += QLatin1Char('\r');
            break;
        case '\\':
            out += QLatin1Char('\\');
            break;
        case '\'':
            out += QLatin1Char('\'');
            break;
        case '"':
            out += QLatin1Char('"');
            break;
        case '\n':
            break; // line continuation
        default:
            out += QLatin1Char('\\');
            out += n;
        }
    }
    return out;
}

/// The text a value contributes to a string (f-string, str(), format): literals as Python prints
/// them.
Substitution asText(const Value &v)
{
    if (const auto literal = v.literalText())
        return Substitution::literal(*literal);
    return v.toSubstitution();
}

std::optional<bool> compare(std::string_view op, const Value &a, const Value &b)
{
    using T = Value::Type;
    if (op == "==" || op == "!=") {
        std::optional<bool> eq;
        if (a.isLiteral() && b.isLiteral())
            eq = a.sameLiteral(b);
        else if (a.type == T::Subst && b.type == T::Subst && a.subst == b.subst)
            eq = true;
        else if ((a.type == T::None) != (b.type == T::None) &&
                 (a.type == T::List || b.type == T::List || a.type == T::Dict ||
                  b.type == T::Dict || a.type == T::Action || b.type == T::Action))
            eq = false;
        if (!eq)
            return std::nullopt;
        return op == "==" ? *eq : !*eq;
    }
    if (op == "is" || op == "is not") {
        std::optional<bool> same;
        if (a.type == T::None || b.type == T::None) {
            const Value &other = a.type == T::None ? b : a;
            if (other.type == T::None)
                same = true;
            else if (other.type != T::Unknown && other.type != T::Module &&
                     other.type != T::Context)
                same = false;
        } else if (a.type == T::Bool && b.type == T::Bool) {
            same = a.boolean == b.boolean;
        }
        if (!same)
            return std::nullopt;
        return op == "is" ? *same : !*same;
    }
    if (op == "in" || op == "not in") {
        std::optional<bool> found;
        if (b.type == T::List && (a.isLiteral() || a.type == T::Subst)) {
            bool decided = true;
            found = false;
            for (const Value &item : b.items()) {
                if (a.sameLiteral(item)) {
                    found = true;
                    break;
                }
                if (!item.isLiteral())
                    decided = false;
            }
            if (!*found && !decided)
                found.reset();
        } else if (b.type == T::Dict && a.isLiteral()) {
            found = b.dict->find(a) != nullptr;
        } else if (b.type == T::String && a.type == T::String) {
            found = b.text.contains(a.text);
        }
        if (!found)
            return std::nullopt;
        return op == "in" ? *found : !*found;
    }
    if ((a.type == T::Number || a.type == T::Bool) && (b.type == T::Number || b.type == T::Bool)) {
        const double x = a.type == T::Bool ? a.boolean : a.number;
        const double y = b.type == T::Bool ? b.boolean : b.number;
        if (op == "<")
            return x < y;
        if (op == "<=")
            return x <= y;
        if (op == ">")
            return x > y;
        if (op == ">=")
            return x >= y;
    }
    if (a.type == T::String && b.type == T::String) {
        const int c = a.text.compare(b.text);
        if (op == "<")
            return c < 0;
        if (op == "<=")
            return c <= 0;
        if (op == ">")
            return c > 0;
        if (op == ">=")
            return c >= 0;
    }
    return std::nullopt;
}

} // namespace rosarch::pylaunch
