#include "syntax/cppsyntax.h"
#include "syntax/cppcodescan.h"

#include <QRegularExpression>

#include <cstring>

#include <algorithm>

namespace rosarch::cppsyntax {

const Fields &fields()
{
    static const Fields f = [] {
        const auto id = [](std::string_view name) {
            return ts::fieldId(SyntaxTree::Grammar::Cpp, name);
        };
        Fields f{};
        f.alternative = id("alternative");
        f.argument = id("argument");
        f.arguments = id("arguments");
        f.body = id("body");
        f.condition = id("condition");
        f.consequence = id("consequence");
        f.declarator = id("declarator");
        f.defaultValue = id("default_value");
        f.field = id("field");
        f.function = id("function");
        f.left = id("left");
        f.name = id("name");
        f.op = id("operator");
        f.parameters = id("parameters");
        f.right = id("right");
        f.scope = id("scope");
        f.type = id("type");
        f.value = id("value");
        return f;
    }();
    return f;
}

namespace {

constexpr auto Cpp = SyntaxTree::Grammar::Cpp;

QString nodeText(const SyntaxTree &tree, TSNode n)
{
    return tree.text(n);
}

// Descends the `scope::scope::name` chain of a qualified_identifier.
void splitQualifiedIdentifier(const SyntaxTree &tree, TSNode n, QStringList *scope, TSNode *last)
{
    static const ts::TypeSet qualified(Cpp, {"qualified_identifier"});
    const Fields &f = fields();
    while (qualified.contains(n)) {
        const TSNode s = ts::field(n, f.scope);
        if (!ts::isNull(s))
            scope->append(simplified(tree, s));
        n = ts::field(n, f.name);
    }
    *last = n;
}

} // namespace

CallShape callShape(const SyntaxTree &tree, TSNode function)
{
    enum
    {
        Qualified,
        Field,
        TemplateFunction,
        TemplateMethod,
        Identifier,
        FieldIdentifier
    };
    static const ts::TypeSet kinds(Cpp,
                                   {"qualified_identifier", "field_expression", "template_function",
                                    "template_method", "identifier", "field_identifier"});
    const Fields &f = fields();
    CallShape shape;
    TSNode n = function;
    const int kind = kinds.index(n);
    if (kind == Qualified) {
        QStringList scope;
        splitQualifiedIdentifier(tree, n, &scope, &n);
        shape.scope = scope.join(QStringLiteral("::"));
    } else if (kind == Field) {
        shape.receiver = ts::field(n, f.argument);
        const TSNode op = ts::field(n, f.op);
        shape.arrow = ts::isNull(op) ? tree.view(n).find("->") != std::string_view::npos
                                     : tree.view(op) == "->";
        n = ts::field(n, f.field);
        if (kinds.index(n) == Qualified) {
            QStringList scope;
            splitQualifiedIdentifier(tree, n, &scope, &n);
            shape.scope = scope.join(QStringLiteral("::"));
        }
    }
    const int last = kinds.index(n);
    if (last == TemplateFunction || last == TemplateMethod) {
        shape.name = nodeText(tree, ts::field(n, f.name));
        shape.templateArguments = ts::field(n, f.arguments);
    } else if (last == Identifier || last == FieldIdentifier) {
        shape.name = nodeText(tree, n);
    }
    return shape;
}

QString firstTemplateArgument(const SyntaxTree &tree, TSNode templateArguments)
{
    for (TSNode a : ts::namedChildren(templateArguments)) {
        if (ts::is(a, "comment"))
            continue;
        return simplified(tree, a);
    }
    return {};
}

std::vector<TSNode> arguments(TSNode list)
{
    static const ts::TypeSet comment(Cpp, {"comment"});
    // One pass with a cursor into one list: this runs for every call the analysis reads.
    std::vector<TSNode> out;
    if (ts::isNull(list))
        return out;
    out.reserve(ts_node_named_child_count(list));
    TSTreeCursor cursor = ts_tree_cursor_new(list);
    if (ts_tree_cursor_goto_first_child(&cursor)) {
        do {
            const TSNode a = ts_tree_cursor_current_node(&cursor);
            if (ts_node_is_named(a) && !comment.contains(a))
                out.push_back(a);
        } while (ts_tree_cursor_goto_next_sibling(&cursor));
    }
    ts_tree_cursor_delete(&cursor);
    return out;
}

bool stringLiteral(const SyntaxTree &tree, TSNode n, QString *content)
{
    enum
    {
        String,
        Raw,
        Concatenated
    };
    static const ts::TypeSet kinds(Cpp,
                                   {"string_literal", "raw_string_literal", "concatenated_string"});
    const int kind = kinds.index(n);
    if (kind == String) {
        const std::string_view v = tree.view(n);
        const size_t open = v.find('"');
        if (open == std::string_view::npos || v.size() < open + 2 || v.back() != '"')
            return false;
        *content = QString::fromUtf8(v.data() + open + 1, qsizetype(v.size() - open - 2));
        return true;
    }
    if (kind == Raw) {
        static const QRegularExpression raw(QStringLiteral("^[uUL8]*R\"([^(]*)\\((.*)\\)\\1\"$"),
                                            QRegularExpression::DotMatchesEverythingOption);
        const auto m = raw.match(tree.text(n));
        if (!m.hasMatch())
            return false;
        *content = m.captured(2);
        return true;
    }
    if (kind == Concatenated) {
        QString all;
        for (TSNode part : arguments(n)) {
            QString piece;
            if (!stringLiteral(tree, part, &piece))
                return false;
            all += piece;
        }
        *content = all;
        return true;
    }
    return false;
}

TSNode unwrap(const SyntaxTree &tree, TSNode n)
{
    enum
    {
        Parenthesized,
        Cast,
        Call,
        CompoundLiteral
    };
    static const ts::TypeSet kinds(Cpp, {"parenthesized_expression", "cast_expression",
                                         "call_expression", "compound_literal_expression"});
    const Fields &f = fields();
    for (int guard = 0; guard < 16 && !ts::isNull(n); ++guard) {
        const int kind = kinds.index(n);
        if (kind == Parenthesized) {
            const auto inner = arguments(n);
            if (inner.size() != 1)
                return n;
            n = inner.front();
            continue;
        }
        if (kind == Cast) {
            n = ts::field(n, f.value);
            continue;
        }
        if (kind == Call || kind == CompoundLiteral) {
            QString name;
            QString scope;
            if (kind == Call) {
                const CallShape shape = callShape(tree, ts::field(n, f.function));
                name = shape.name;
                scope = shape.scope;
            } else {
                const QStringList parts = splitScope(simplified(tree, ts::field(n, f.type)));
                name = parts.isEmpty() ? QString() : parts.last();
                scope = parts.mid(0, parts.size() - 1).join(QStringLiteral("::"));
            }
            const bool transparent =
                name == QLatin1String("static_cast") || name == QLatin1String("const_cast") ||
                name == QLatin1String("reinterpret_cast") ||
                ((name == QLatin1String("move") || name == QLatin1String("forward")) &&
                 (scope.isEmpty() || scope == QLatin1String("std"))) ||
                (name == QLatin1String("string") && scope == QLatin1String("std")) ||
                name == QLatin1String("ParameterValue");
            if (!transparent)
                return n;
            const TSNode list = kind == Call ? ts::field(n, f.arguments) : ts::field(n, f.value);
            const auto args = arguments(list);
            if (args.empty())
                return n;
            n = args.front();
            continue;
        }
        return n;
    }
    return n;
}

TSNode declaredName(TSNode declarator)
{
    static const ts::TypeSet names(Cpp, {"identifier", "field_identifier"});
    const TSFieldId inner = fields().declarator;
    TSNode n = declarator;
    for (int guard = 0; guard < 16 && !ts::isNull(n); ++guard) {
        if (names.contains(n))
            return n;
        TSNode next = ts::field(n, inner);
        if (ts::isNull(next)) {
            // reference_declarator keeps its identifier as an unnamed-field child.
            const auto kids = ts::namedChildren(n);
            if (kids.empty())
                break;
            next = kids.back();
        }
        n = next;
    }
    TSNode null{};
    return null;
}

QString simplified(const SyntaxTree &tree, TSNode n)
{
    return tree.text(n).simplified();
}

QStringList splitScope(const QString &qualified)
{
    QStringList out;
    QString current;
    int depth = 0;
    const QString s = qualified.trimmed();
    for (qsizetype i = 0; i < s.size(); ++i) {
        const QChar c = s.at(i);
        if (c == u'<' || c == u'(')
            ++depth;
        else if ((c == u'>' || c == u')') && depth > 0)
            --depth;
        if (depth == 0 && c == u':' && i + 1 < s.size() && s.at(i + 1) == u':') {
            if (!current.trimmed().isEmpty())
                out.append(current.trimmed());
            current.clear();
            ++i;
            continue;
        }
        current += c;
    }
    if (!current.trimmed().isEmpty())
        out.append(current.trimmed());
    return out;
}

QStringList templateArgumentsOf(const QString &type)
{
    const qsizetype open = type.indexOf(u'<');
    if (open < 0 || !type.endsWith(u'>'))
        return {};
    QStringList out;
    QString current;
    int depth = 0;
    for (qsizetype i = open + 1; i < type.size() - 1; ++i) {
        const QChar c = type.at(i);
        depth += c == u'<' ? 1 : c == u'>' ? -1 : 0;
        if (c == u',' && depth == 0) {
            out.append(current.trimmed());
            current.clear();
            continue;
        }
        current += c;
    }
    if (!current.trimmed().isEmpty())
        out.append(current.trimmed());
    return out;
}

QString withoutTemplateArguments(const QString &name)
{
    QString out;
    int depth = 0;
    for (QChar c : name) {
        if (c == u'<') {
            ++depth;
            continue;
        }
        if (c == u'>') {
            if (depth > 0)
                --depth;
            continue;
        }
        if (depth == 0)
            out += c;
    }
    return out.trimmed();
}

QString lastSegment(const QString &qualified)
{
    const QStringList parts = splitScope(withoutTemplateArguments(qualified));
    return parts.isEmpty() ? QString() : parts.last();
}

QString canonicalInterfaceType(const QString &written)
{
    QString s = written.simplified();
    for (const char *prefix : {"typename ", "const ", "struct ", "class "})
        if (s.startsWith(QLatin1String(prefix)))
            s = s.mid(int(strlen(prefix)));
    s.remove(u' ');
    while (s.endsWith(u'&') || s.endsWith(u'*'))
        s.chop(1);
    for (const char *wrapper : {"std::shared_ptr<", "std::unique_ptr<", "shared_ptr<"}) {
        if (s.startsWith(QLatin1String(wrapper)) && s.endsWith(u'>')) {
            s = s.mid(int(strlen(wrapper)));
            s.chop(1);
            if (s.startsWith(QLatin1String("const")))
                s = s.mid(5);
        }
    }
    // rclcpp::TypeAdapter<CustomType, ros_message_type>: the ROS type goes over the wire.
    if (s.startsWith(QLatin1String("rclcpp::TypeAdapter<")) && s.endsWith(u'>')) {
        const QString inner = s.mid(20, s.size() - 21);
        int depth = 0;
        for (qsizetype i = 0; i < inner.size(); ++i) {
            const QChar c = inner.at(i);
            depth += c == u'<' ? 1 : c == u'>' ? -1 : 0;
            if (c == u',' && depth == 0)
                return canonicalInterfaceType(inner.mid(i + 1));
        }
    }
    QStringList parts = splitScope(s);
    static const QStringList pointers = {
        QStringLiteral("SharedPtr"), QStringLiteral("ConstSharedPtr"), QStringLiteral("UniquePtr"),
        QStringLiteral("Ptr"),       QStringLiteral("ConstPtr"),       QStringLiteral("WeakPtr")};
    while (parts.size() > 1 && pointers.contains(parts.last()))
        parts.removeLast();
    for (qsizetype i = parts.size() - 2; i >= 1; --i) {
        const QString &kind = parts.at(i);
        if (kind == QLatin1String("msg") || kind == QLatin1String("srv") ||
            kind == QLatin1String("action")) {
            QString type = parts.at(i + 1);
            // Message templates with an allocator: String_<std::allocator<void>>.
            if (type.contains(u'<')) {
                type = withoutTemplateArguments(type);
                if (type.endsWith(u'_'))
                    type.chop(1);
            }
            // Nested types keep their ROS name: Fibonacci::Impl::FeedbackMessage ->
            // Fibonacci_FeedbackMessage.
            for (qsizetype j = i + 2; j < parts.size(); ++j)
                if (parts.at(j) != QLatin1String("Impl"))
                    type += u'_' + withoutTemplateArguments(parts.at(j));
            return parts.at(i - 1) + u'/' + kind + u'/' + type;
        }
    }
    return parts.join(QStringLiteral("::"));
}

void blankExportMacros(QByteArray *source)
{
    static const char *suffixes[] = {"_PUBLIC", "_LOCAL",       "_EXPORT",
                                     "_IMPORT", "_PUBLIC_TYPE", "_API",
                                     "_HIDDEN", "_DLLEXPORT",   "_DLLIMPORT"};
    // Attribute macros without a visibility suffix: PCL's, and CUDA's function qualifiers.
    static const char *names[] = {"PCL_EXPORTS", "__device__", "__host__", "__global__"};
    char *data = source->data();
    const qsizetype size = source->size();
    bool lineStart = true;
    bool preprocessor = false;
    for (qsizetype i = 0; i < size;) {
        const char c = data[i];
        if (c == '\n') {
            // A continued preprocessor line stays a preprocessor line.
            if (!(i > 0 && data[i - 1] == '\\'))
                preprocessor = false;
            lineStart = true;
            ++i;
            continue;
        }
        if (lineStart && (c == ' ' || c == '\t')) {
            ++i;
            continue;
        }
        if (lineStart && c == '#')
            preprocessor = true;
        lineStart = false;
        if (c == '"') { // topic names in string literals stay as written
            ++i;
            while (i < size && data[i] != '"' && data[i] != '\n')
                i += data[i] == '\\' ? 2 : 1;
            ++i;
            continue;
        }
        // ASCII tests, not the locale's: this loop runs on every byte of every file.
        if (!scan::isIdentifierChar(c) || (c >= '0' && c <= '9')) {
            ++i;
            continue;
        }
        qsizetype end = i;
        bool upper = true;
        while (end < size && scan::isIdentifierChar(data[end])) {
            upper = upper && !(data[end] >= 'a' && data[end] <= 'z');
            ++end;
        }
        // A value (`durability = RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL`, an argument) is an
        // enumerator or a constant, not a visibility macro.
        qsizetype before = i - 1;
        while (before >= 0 && (data[before] == ' ' || data[before] == '\t'))
            --before;
        qsizetype after = end;
        while (after < size && (data[after] == ' ' || data[after] == '\t'))
            ++after;
        // ... or one after `case` or `return`, or one a `,`, `:`, `;`, closing bracket or
        // argument list follows (`case RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL:`,
        // `{X_LOCAL, "Local"}`, `BOOST_CLASS_EXPORT(T)`): a macro of visibility stands before a
        // declaration.
        const auto wordBefore = [&](std::string_view w) {
            const qsizetype from = before - qsizetype(w.size()) + 1;
            return from >= 0 && std::string_view(data + from, w.size()) == w &&
                   (from == 0 || !scan::isIdentifierChar(data[from - 1]));
        };
        const bool value =
            (before >= 0 && (data[before] == '=' || data[before] == '(' || data[before] == ',' ||
                             data[before] == '?')) ||
            wordBefore("case") || wordBefore("return") ||
            (after < size && std::strchr(",;)]}(", data[after]) && data[after] != '\0') ||
            (after + 1 < size && data[after] == ':' && data[after + 1] != ':');
        const std::string_view word(data + i, size_t(end - i));
        if (!preprocessor && !value &&
            std::find(std::begin(names), std::end(names), word) != std::end(names)) {
            std::fill(data + i, data + end, ' ');
        } else if (!preprocessor && upper && !value && end - i > 7) {
            for (const char *suffix : suffixes) {
                const std::string_view sv(suffix);
                if (word.size() > sv.size() && word.substr(word.size() - sv.size()) == sv) {
                    std::fill(data + i, data + end, ' ');
                    break;
                }
            }
        }
        i = end;
    }
}

void blankQtKeywords(QByteArray *source)
{
    if (!scan::contains(*source, "Q_OBJECT") && !scan::contains(*source, "Q_GADGET") &&
        !scan::contains(*source, "slots") && !scan::contains(*source, "signals") &&
        !scan::contains(*source, "Q_S"))
        return;
    char *data = source->data();
    const qsizetype size = source->size();
    auto word = [&](qsizetype i, qsizetype *end) {
        qsizetype j = i;
        while (j < size && (std::isalnum(uchar(data[j])) || data[j] == '_'))
            ++j;
        *end = j;
        return std::string_view(data + i, size_t(j - i));
    };
    auto skipBlanks = [&](qsizetype i) {
        while (i < size && (data[i] == ' ' || data[i] == '\t'))
            ++i;
        return i;
    };
    for (qsizetype line = 0; line < size;) {
        qsizetype next = source->indexOf('\n', line);
        next = next < 0 ? size : next + 1;
        const qsizetype i = skipBlanks(line);
        qsizetype end = 0;
        const std::string_view first = word(i, &end);
        const qsizetype after = skipBlanks(end);
        const bool alone = after >= next - 1 || data[after] == '\n' || data[after] == '\r' ||
                           (data[after] == '/' && after + 1 < size && data[after + 1] == '/');
        if ((first == "Q_OBJECT" || first == "Q_GADGET") && alone) {
            std::fill(data + i, data + end, ' ');
        } else if ((first == "signals" || first == "Q_SIGNALS") && after < size &&
                   data[after] == ':') {
            std::fill(data + i, data + end, ' ');
            std::copy_n("public", 6, data + i);
        } else if (first == "public" || first == "protected" || first == "private") {
            qsizetype end2 = 0;
            const std::string_view second = word(after, &end2);
            const qsizetype colon = skipBlanks(end2);
            if ((second == "slots" || second == "Q_SLOTS") && colon < size && data[colon] == ':')
                std::fill(data + after, data + end2, ' ');
        }
        line = next;
    }
}

bool isHeaderPath(const QString &path)
{
    const QString lower = path.toLower();
    for (const char *ext : {".h", ".hh", ".hpp", ".hxx", ".inl", ".ipp"})
        if (lower.endsWith(QLatin1String(ext)))
            return true;
    return false;
}

} // namespace rosarch::cppsyntax
