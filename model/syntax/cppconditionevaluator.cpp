#include "syntax/cppconditionevaluator.h"

#include <QSet>

#include <climits>
#include <string_view>
#include <vector>

namespace rosarch {

namespace {

constexpr int kMaxExpansionDepth = 16;
constexpr int kMaxTokens = 4096;
constexpr int kMaxNesting = 64;

struct Token
{
    enum class Kind
    {
        Number,
        Operator,
        Unknown, ///< a function-like macro call, or anything the evaluator cannot read
    };
    Kind kind = Kind::Number;
    long long value = 0;
    std::string_view op;
};

struct Value
{
    bool known = true;
    long long v = 0;
};

bool isIdentStart(char c)
{
    return std::isalpha(uchar(c)) || c == '_';
}

bool isIdent(char c)
{
    return std::isalnum(uchar(c)) || c == '_';
}

// An integer literal with its suffixes (42, 0x2A, 052, 0b101, 1'000, 42UL); false for floats.
bool parseNumber(std::string_view text, long long *value)
{
    std::string digits;
    for (char c : text)
        if (c != '\'')
            digits += c;
    while (!digits.empty() && (digits.back() == 'u' || digits.back() == 'U' ||
                               digits.back() == 'l' || digits.back() == 'L'))
        digits.pop_back();
    int base = 10;
    size_t i = 0;
    if (digits.size() > 1 && digits[0] == '0') {
        if (digits[1] == 'x' || digits[1] == 'X') {
            base = 16;
            i = 2;
        } else if (digits[1] == 'b' || digits[1] == 'B') {
            base = 2;
            i = 2;
        } else {
            base = 8;
            i = 1;
        }
    }
    if (i >= digits.size() && base != 8)
        return false;
    unsigned long long v = 0;
    for (; i < digits.size(); ++i) {
        const char c = digits[i];
        int d = 0;
        if (std::isdigit(uchar(c)))
            d = c - '0';
        else if (std::isxdigit(uchar(c)))
            d = std::tolower(uchar(c)) - 'a' + 10;
        else
            return false;
        if (d >= base)
            return false;
        v = v * unsigned(base) + unsigned(d);
    }
    *value = (long long)v;
    return true;
}

class Tokenizer
{
public:
    explicit Tokenizer(const CppMacros &macros) : m_macros(macros) {}

    // Appends the tokens of `text`, expanding object-like macros; false when over budget.
    bool run(std::string_view text, int depth, std::vector<Token> *out)
    {
        if (depth > kMaxExpansionDepth)
            return false;
        size_t i = 0;
        const size_t n = text.size();
        while (i < n) {
            if (out->size() > size_t(kMaxTokens))
                return false;
            const char c = text[i];
            if (std::isspace(uchar(c))) {
                ++i;
            } else if (std::isdigit(uchar(c))) {
                size_t j = i;
                while (j < n && (isIdent(text[j]) || text[j] == '\'' || text[j] == '.'))
                    ++j;
                Token t;
                if (!parseNumber(text.substr(i, j - i), &t.value))
                    t.kind = Token::Kind::Unknown;
                out->push_back(t);
                i = j;
            } else if (c == '\'') { // character literal
                size_t j = i + 1;
                while (j < n && text[j] != '\'')
                    j += text[j] == '\\' ? 2 : 1;
                Token t;
                if (j == i + 2)
                    t.value = (unsigned char)text[i + 1];
                else
                    t.kind = Token::Kind::Unknown;
                out->push_back(t);
                i = j + 1;
            } else if (isIdentStart(c)) {
                size_t j = i;
                while (j < n && isIdent(text[j]))
                    ++j;
                const std::string_view word = text.substr(i, j - i);
                i = j;
                if (!identifier(text, word, &i, depth, out))
                    return false;
            } else {
                static const std::string_view ops[] = {
                    "&&", "||", "==", "!=", "<=", ">=", "<<", ">>", "(", ")", "!", "~", "*",
                    "/",  "%",  "+",  "-",  "<",  ">",  "&",  "^",  "|", "?", ":", ","};
                bool matched = false;
                for (std::string_view op : ops) {
                    if (text.substr(i, op.size()) == op) {
                        Token t;
                        t.kind = Token::Kind::Operator;
                        t.op = op;
                        out->push_back(t);
                        i += op.size();
                        matched = true;
                        break;
                    }
                }
                if (!matched) { // a string literal, `#`, ... : nothing a condition can use
                    Token t;
                    t.kind = Token::Kind::Unknown;
                    out->push_back(t);
                    ++i;
                }
            }
        }
        return true;
    }

private:
    static size_t skipSpace(std::string_view text, size_t i)
    {
        while (i < text.size() && std::isspace(uchar(text[i])))
            ++i;
        return i;
    }

    bool identifier(std::string_view text, std::string_view word, size_t *i, int depth,
                    std::vector<Token> *out)
    {
        Token t;
        if (word == "defined") {
            size_t j = skipSpace(text, *i);
            const bool paren = j < text.size() && text[j] == '(';
            if (paren)
                j = skipSpace(text, j + 1);
            size_t k = j;
            while (k < text.size() && isIdent(text[k]))
                ++k;
            const QByteArray name(text.data() + j, qsizetype(k - j));
            if (paren) {
                k = skipSpace(text, k);
                if (k < text.size() && text[k] == ')')
                    ++k;
                else
                    t.kind = Token::Kind::Unknown;
            }
            if (name.isEmpty())
                t.kind = Token::Kind::Unknown;
            t.value = m_macros.contains(name) ? 1 : 0;
            out->push_back(t);
            *i = k;
            return true;
        }
        const size_t after = skipSpace(text, *i);
        if (after < text.size() && text[after] == '(') {
            // A function-like macro call: its value depends on a definition (or a header
            // lookup, __has_include) the evaluator does not have.
            int nesting = 0;
            size_t k = after;
            for (; k < text.size(); ++k) {
                nesting += text[k] == '(' ? 1 : text[k] == ')' ? -1 : 0;
                if (nesting == 0)
                    break;
            }
            *i = k < text.size() ? k + 1 : k;
            t.kind = Token::Kind::Unknown;
            out->push_back(t);
            return true;
        }
        const QByteArray name(word.data(), qsizetype(word.size()));
        const auto it = m_macros.constFind(name);
        if (it != m_macros.constEnd() && !it->functionLike && !m_expanding.contains(name)) {
            m_expanding.insert(name);
            const bool ok = run(std::string_view(it->body.constData(), size_t(it->body.size())),
                                depth + 1, out);
            m_expanding.remove(name);
            return ok;
        }
        t.value = word == "true" ? 1 : 0; // unknown identifiers are 0, as in a compiler
        out->push_back(t);
        return true;
    }

    const CppMacros &m_macros;
    QSet<QByteArray> m_expanding;
};

class Parser
{
public:
    explicit Parser(const std::vector<Token> &tokens) : m_tokens(tokens) {}

    bool parse(Value *result)
    {
        *result = conditional(0);
        return !m_failed && m_pos == m_tokens.size();
    }

private:
    bool peek(std::string_view op) const
    {
        return m_pos < m_tokens.size() && m_tokens[m_pos].kind == Token::Kind::Operator &&
               m_tokens[m_pos].op == op;
    }

    bool accept(std::string_view op)
    {
        if (!peek(op))
            return false;
        ++m_pos;
        return true;
    }

    Value fail()
    {
        m_failed = true;
        return {false, 0};
    }

    Value conditional(int nesting)
    {
        if (nesting > kMaxNesting)
            return fail();
        const Value c = binary(0, nesting);
        if (!accept("?"))
            return c;
        const Value a = conditional(nesting + 1);
        if (!accept(":"))
            return fail();
        const Value b = conditional(nesting + 1);
        if (c.known)
            return c.v ? a : b;
        if (a.known && b.known && a.v == b.v)
            return a;
        return {false, 0};
    }

    static int precedence(std::string_view op)
    {
        static const std::pair<std::string_view, int> table[] = {
            {"||", 1}, {"&&", 2}, {"|", 3}, {"^", 4},  {"&", 5},  {"==", 6},
            {"!=", 6}, {"<", 7},  {">", 7}, {"<=", 7}, {">=", 7}, {"<<", 8},
            {">>", 8}, {"+", 9},  {"-", 9}, {"*", 10}, {"/", 10}, {"%", 10}};
        for (const auto &[o, p] : table)
            if (o == op)
                return p;
        return -1;
    }

    Value binary(int minPrecedence, int nesting)
    {
        Value left = unary(nesting);
        while (!m_failed && m_pos < m_tokens.size() &&
               m_tokens[m_pos].kind == Token::Kind::Operator) {
            const std::string_view op = m_tokens[m_pos].op;
            const int p = precedence(op);
            if (p < 0 || p < minPrecedence)
                break;
            ++m_pos;
            const Value right = binary(p + 1, nesting);
            left = apply(op, left, right);
        }
        return left;
    }

    static Value apply(std::string_view op, Value a, Value b)
    {
        if (op == "&&") {
            if ((a.known && !a.v) || (b.known && !b.v))
                return {true, 0};
            return {a.known && b.known, 1};
        }
        if (op == "||") {
            if ((a.known && a.v) || (b.known && b.v))
                return {true, 1};
            return {a.known && b.known, 0};
        }
        if (!a.known || !b.known)
            return {false, 0};
        const auto ua = (unsigned long long)a.v;
        const auto ub = (unsigned long long)b.v;
        if (op == "|")
            return {true, (long long)(ua | ub)};
        if (op == "^")
            return {true, (long long)(ua ^ ub)};
        if (op == "&")
            return {true, (long long)(ua & ub)};
        if (op == "==")
            return {true, a.v == b.v};
        if (op == "!=")
            return {true, a.v != b.v};
        if (op == "<")
            return {true, a.v < b.v};
        if (op == ">")
            return {true, a.v > b.v};
        if (op == "<=")
            return {true, a.v <= b.v};
        if (op == ">=")
            return {true, a.v >= b.v};
        if (op == "<<" || op == ">>") {
            if (b.v < 0 || b.v > 63)
                return {false, 0};
            return {true, (long long)(op == "<<" ? ua << b.v : ua >> b.v)};
        }
        if (op == "+")
            return {true, (long long)(ua + ub)};
        if (op == "-")
            return {true, (long long)(ua - ub)};
        if (op == "*")
            return {true, (long long)(ua * ub)};
        if (b.v == 0 || (a.v == LLONG_MIN && b.v == -1))
            return {false, 0};
        return {true, op == "/" ? a.v / b.v : a.v % b.v};
    }

    Value unary(int nesting)
    {
        if (nesting > kMaxNesting)
            return fail();
        if (accept("!")) {
            const Value v = unary(nesting + 1);
            return {v.known, !v.v};
        }
        if (accept("~")) {
            const Value v = unary(nesting + 1);
            return {v.known, (long long)~(unsigned long long)v.v};
        }
        if (accept("-")) {
            const Value v = unary(nesting + 1);
            return {v.known, (long long)(0ULL - (unsigned long long)v.v)};
        }
        if (accept("+"))
            return unary(nesting + 1);
        if (accept("(")) {
            const Value v = conditional(nesting + 1);
            if (!accept(")"))
                return fail();
            return v;
        }
        if (m_pos >= m_tokens.size() || m_tokens[m_pos].kind == Token::Kind::Operator)
            return fail();
        const Token &t = m_tokens[m_pos++];
        if (t.kind == Token::Kind::Unknown)
            return {false, 0};
        return {true, t.value};
    }

    const std::vector<Token> &m_tokens;
    size_t m_pos = 0;
    bool m_failed = false;
};

} // namespace

CppConditionEvaluator::CppConditionEvaluator(const CppMacros &macros) : m_macros(macros) {}

CppConditionEvaluator::Result CppConditionEvaluator::evaluate(const QByteArray &condition) const
{
    std::vector<Token> tokens;
    Tokenizer tokenizer(m_macros);
    if (!tokenizer.run(std::string_view(condition.constData(), size_t(condition.size())), 0,
                       &tokens) ||
        tokens.empty())
        return {};
    Value v;
    if (!Parser(tokens).parse(&v) || !v.known)
        return {};
    return {true, v.v};
}

} // namespace rosarch
