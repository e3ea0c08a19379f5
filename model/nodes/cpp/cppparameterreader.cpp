#include "nodes/cpp/cppparameterreader.h"

#include <QRegularExpression>

#include "core/declaringcall.h"
#include "core/parameter.h"

namespace rosarch {

using namespace cppsyntax;

namespace {

/// Declaring helpers of nav2_util and autoware_utils: on a node, or free with the node first.
bool isNav2Helper(const QString &name)
{
    return name == QLatin1String("declare_parameter_if_not_declared") ||
           name == QLatin1String("declare_or_get_parameter") ||
           name == QLatin1String("get_or_declare_parameter") ||
           name == QLatin1String("getOrDeclareParameter");
}

QString escaped(const QString &s)
{
    return QRegularExpression::escape(s);
}

/// The last match of `pattern` in `text`, capture 1 ("" when none).
QString lastCapture(const QString &text, const QString &pattern)
{
    const QRegularExpression re(pattern);
    QString out;
    for (auto it = re.globalMatch(text); it.hasNext();)
        out = it.next().captured(1).trimmed();
    return out;
}

} // namespace

CppParameterReader::CppParameterReader(const SyntaxTree &tree, const CppValueEvaluator &values)
    : m_tree(tree), m_values(values)
{
}

CppParameterDeclaration CppParameterReader::read(TSNode call, const CallShape &shape,
                                                 const std::vector<TSNode> &args,
                                                 TSNode definition) const
{
    CppParameterDeclaration decl;
    const QString &name = shape.name;
    const QString lower = name.toLower();
    const bool standard = isStandardDeclaringCall(name);
    // node options (`automatically_declare_parameters_from_overrides(true)`) declare nothing
    const bool custom = !standard && !lower.startsWith(QLatin1String("automatically")) &&
                        !lower.startsWith(QLatin1String("allow_undeclared")) &&
                        lower.contains(QLatin1String("declare")) &&
                        lower.contains(QLatin1String("parameter")) &&
                        !lower.endsWith(QLatin1String("parameters")) &&
                        !lower.startsWith(QLatin1String("undeclare"));
    const bool orDefault = name == QLatin1String("get_parameter_or");
    const bool undeclare = name == QLatin1String("undeclare_parameter");
    if ((!standard && !custom && !orDefault && !undeclare) || args.empty())
        return decl;
    // nav2_util's free helpers take the node first: `declare_parameter_if_not_declared(node,
    // "name", value)`; as methods of a node they take the name first.
    size_t at = 0;
    CppValue named = m_values.evaluate(args[0]);
    const auto isName = [](const CppValue &v) {
        return v.kind == CppValue::Kind::Literal || v.kind == CppValue::Kind::Local ||
               v.kind == CppValue::Kind::Concatenation;
    };
    if ((isNav2Helper(name) || custom) && args.size() >= 2 && !isName(named)) {
        at = 1;
        named = m_values.evaluate(args[1]);
    }
    if (named.kind == CppValue::Kind::Literal || named.kind == CppValue::Kind::Local) {
        if (named.literal.isEmpty() || named.literal.at(0).isDigit() ||
            named.literal == QLatin1String("true") || named.literal == QLatin1String("false"))
            return decl;
        decl.parameter = named.literal;
    } else if (named.kind == CppValue::Kind::Concatenation ||
               named.kind == CppValue::Kind::Member ||
               named.kind == CppValue::Kind::FunctionParameter ||
               named.kind == CppValue::Kind::Constant) {
        decl.name = named;
    } else {
        return decl;
    }
    decl.via = undeclare ? QStringLiteral("undeclare") : name;
    decl.evidence = m_tree.evidence(call);
    // declared where a failure is caught: the parameter is optional
    for (TSNode up = ts_node_parent(call); !ts::isNull(up) && !ts_node_eq(up, definition);
         up = ts_node_parent(up))
        if (ts::is(up, "try_statement")) {
            decl.guard = QStringLiteral("try");
            break;
        }
    if (undeclare)
        return decl;
    if (!ts::isNull(shape.templateArguments))
        decl.type = parameterTypeOfWritten(firstTemplateArgument(m_tree, shape.templateArguments));
    // get_parameter_or("p", variable, default)
    const size_t value = at + (orDefault ? 2 : 1);
    if (value < args.size()) {
        bool typeOnly = false;
        const QString type = typeOfValue(args[value], &typeOnly);
        if (decl.type.isEmpty())
            decl.type = type;
        if (!typeOnly) {
            decl.defaultValue = m_values.evaluate(args[value]);
            decl.hasDefault = true;
            decl.defaultText = simplified(m_tree, args[value]);
        }
    }
    const size_t descriptor = at + (orDefault ? 3 : 2);
    if (!orDefault && descriptor < args.size() && ts::is(args[descriptor], "identifier"))
        readDescriptor(m_tree.text(args[descriptor]), call, definition, &decl);
    return decl;
}

CppParameterDeclaration CppParameterReader::readGetterCall(TSNode call,
                                                           const std::vector<TSNode> &args,
                                                           TSNode getter) const
{
    CppParameterDeclaration decl;
    if (args.size() < 3 || ts::isNull(getter) || !ts::is(getter, "call_expression"))
        return decl;
    const CallShape made = callShape(m_tree, ts::field(getter, fields().function));
    if (!isParameterGetterFactory(made.name))
        return decl;
    const std::vector<TSNode> madeArgs = arguments(ts::field(getter, fields().arguments));
    QString name;
    if (madeArgs.size() != 1 || !stringLiteral(m_tree, args[1], &name) || name.isEmpty())
        return decl;
    // the handler joins the namespace and the name with a dot, and takes the name alone for
    // an empty namespace
    const CppValue ns = m_values.evaluate(madeArgs.front());
    if (ns.kind == CppValue::Kind::Literal || ns.kind == CppValue::Kind::Local) {
        decl.parameter = ns.literal.isEmpty() ? name : ns.literal + QLatin1Char('.') + name;
    } else if (ns.kind == CppValue::Kind::Member || ns.kind == CppValue::Kind::FunctionParameter ||
               ns.kind == CppValue::Kind::Concatenation || ns.kind == CppValue::Kind::Constant) {
        CppValue rest;
        rest.kind = CppValue::Kind::Literal;
        rest.literal = QLatin1Char('.') + name;
        rest.text = QStringLiteral("\".%1\"").arg(name);
        decl.name.kind = CppValue::Kind::Concatenation;
        decl.name.text = ns.text + QStringLiteral(" + ") + rest.text;
        decl.name.parts = {ns, rest};
    } else {
        return decl;
    }
    decl.via = made.name;
    decl.evidence = m_tree.evidence(call);
    bool typeOnly = false;
    decl.type = typeOfValue(args[2], &typeOnly);
    if (!typeOnly) {
        decl.defaultValue = m_values.evaluate(args[2]);
        decl.hasDefault = true;
        decl.defaultText = simplified(m_tree, args[2]);
    }
    return decl;
}

QList<CppParameterDeclaration> CppParameterReader::readMany(TSNode call, const CallShape &shape,
                                                            const std::vector<TSNode> &args) const
{
    QList<CppParameterDeclaration> out;
    if (shape.name != QLatin1String("declare_parameters") || args.size() < 2)
        return out;
    QString prefix;
    const CppValue ns = m_values.evaluate(args[0]);
    if (ns.kind == CppValue::Kind::Literal || ns.kind == CppValue::Kind::Local)
        prefix = ns.literal;
    else
        return out; // a prefix decided at run time: nothing certain to add
    const QString type =
        ts::isNull(shape.templateArguments)
            ? QString()
            : parameterTypeOfWritten(firstTemplateArgument(m_tree, shape.templateArguments));
    const auto named = [&](const QString &name) {
        CppParameterDeclaration d;
        d.parameter = prefix.isEmpty() ? name : prefix + QLatin1Char('.') + name;
        d.via = QStringLiteral("declare_parameter");
        d.type = type;
        d.evidence = m_tree.evidence(call);
        return d;
    };
    // the map: `std::map<std::string, T>{{"a", 1}, ...}` or a braced list `{{"a", 1}, ...}`
    TSNode map = args[1];
    if (ts::is(map, "compound_literal_expression"))
        map = ts::field(map, fields().value);
    if (!ts::is(map, "initializer_list")) {
        CppParameterDeclaration d = named(QString());
        d.parameter.clear();
        d.name.kind = CppValue::Kind::Concatenation;
        const QString lead = prefix.isEmpty() ? QString() : prefix + QLatin1Char('.');
        d.name.text = QStringLiteral("%1{%2}").arg(lead, simplified(m_tree, args[1]));
        CppValue head;
        head.kind = CppValue::Kind::Literal;
        head.literal = head.text = lead;
        CppValue rest;
        rest.kind = CppValue::Kind::Expression;
        rest.text = simplified(m_tree, args[1]);
        d.name.parts = {head, rest};
        out.append(d);
        return out;
    }
    for (TSNode pair : arguments(map)) {
        const std::vector<TSNode> kv = arguments(pair);
        QString name;
        if (kv.size() != 2 || !stringLiteral(m_tree, kv[0], &name) || name.isEmpty())
            continue;
        CppParameterDeclaration d = named(name);
        if (d.type.isEmpty())
            d.type = typeOfValue(kv[1]);
        d.defaultValue = m_values.evaluate(kv[1]);
        d.hasDefault = true;
        d.defaultText = simplified(m_tree, kv[1]);
        out.append(d);
    }
    return out;
}

QString CppParameterReader::typeOfValue(TSNode value, bool *isTypeOnly, int depth) const
{
    if (ts::isNull(value) || depth > 8)
        return {};
    if (ts::is(value, "parenthesized_expression") && ts_node_named_child_count(value) == 1)
        return typeOfValue(ts_node_named_child(value, 0), isTypeOnly, depth + 1);
    if (ts::is(value, "string_literal") || ts::is(value, "raw_string_literal") ||
        ts::is(value, "concatenated_string"))
        return QStringLiteral("string");
    if (ts::is(value, "true") || ts::is(value, "false"))
        return QStringLiteral("bool");
    if (ts::is(value, "unary_expression"))
        return typeOfValue(ts::field(value, fields().argument), isTypeOnly, depth + 1);
    if (ts::is(value, "number_literal")) {
        const QString t = m_tree.text(value).toLower();
        if (t.startsWith(QLatin1String("0x")))
            return QStringLiteral("integer");
        return t.contains(u'.') || t.contains(u'e') || t.endsWith(u'f') ? QStringLiteral("double")
                                                                        : QStringLiteral("integer");
    }
    const QString text = simplified(m_tree, value);
    if (ts::is(value, "identifier") || ts::is(value, "qualified_identifier")) {
        if (text.contains(QLatin1String("PARAMETER_"))) {
            if (isTypeOnly)
                *isTypeOnly = true;
            return parameterTypeOfWritten(text);
        }
        return {};
    }
    if (ts::is(value, "compound_literal_expression"))
        return parameterTypeOfWritten(simplified(m_tree, ts::field(value, fields().type)));
    if (ts::is(value, "call_expression")) {
        const CallShape shape = callShape(m_tree, ts::field(value, fields().function));
        const std::vector<TSNode> inner = arguments(ts::field(value, fields().arguments));
        if (shape.name == QLatin1String("ParameterValue"))
            return inner.empty() ? QString() : typeOfValue(inner.front(), isTypeOnly, depth + 1);
        if (shape.name == QLatin1String("string"))
            return QStringLiteral("string");
        QString written =
            shape.scope.isEmpty() ? shape.name : shape.scope + QStringLiteral("::") + shape.name;
        if (!ts::isNull(shape.templateArguments))
            written += m_tree.text(shape.templateArguments);
        return parameterTypeOfWritten(written);
    }
    return {};
}

void CppParameterReader::readDescriptor(const QString &variable, TSNode call, TSNode definition,
                                        CppParameterDeclaration *decl) const
{
    if (ts::isNull(definition))
        return;
    // what the function says before the call (a descriptor reused keeps what was set)
    const uint32_t start = ts_node_start_byte(definition);
    const uint32_t end = ts_node_start_byte(call);
    if (end <= start)
        return;
    const std::string_view whole = m_tree.view(definition);
    const QString text = QString::fromUtf8(whole.data(), qsizetype(end - start));
    const QString v = escaped(variable);
    const QString description =
        lastCapture(text, v + QStringLiteral("\\s*\\.\\s*description\\s*=\\s*\"((?:[^\"\\\\]|"
                                             "\\\\.)*)\""));
    if (!description.isEmpty())
        decl->description = description;
    const QString readOnly =
        lastCapture(text, v + QStringLiteral("\\s*\\.\\s*read_only\\s*=\\s*(\\w+)"));
    decl->readOnly = readOnly == QLatin1String("true");
    const QString dynamic =
        lastCapture(text, v + QStringLiteral("\\s*\\.\\s*dynamic_typing\\s*=\\s*(\\w+)"));
    decl->dynamicTyping = dynamic == QLatin1String("true");
    // a range: `d.floating_point_range[0].from_value = 0.0;`, or a range object `r` with
    // `r.from_value = 0.0;` that is pushed into `d.integer_range`
    QStringList objects;
    for (const char *kind : {"floating_point", "integer"}) {
        const QString list = v + QStringLiteral("\\s*\\.\\s*") + kind + QStringLiteral("_range");
        if (!QRegularExpression(list).match(text).hasMatch())
            continue;
        objects << list + QStringLiteral("\\s*\\[\\s*0\\s*\\]");
        const QString pushed = lastCapture(
            text, list + QStringLiteral("\\s*\\.\\s*(?:push_back|emplace_back)\\s*\\(\\s*(\\w+)"));
        if (!pushed.isEmpty())
            objects << escaped(pushed);
    }
    for (const QString &o : std::as_const(objects)) {
        auto bound = [&](const QString &field) {
            QString x = lastCapture(text, o + QStringLiteral("\\s*\\.\\s*") + field +
                                              QStringLiteral("\\s*=\\s*([^;]+);"));
            if (x.isEmpty())
                x = lastCapture(text, o + QStringLiteral("[^;]*\\.\\s*set__") + field +
                                          QStringLiteral("\\s*\\(([^()]*)\\)"));
            return x;
        };
        const QString from = bound(QStringLiteral("from_value"));
        const QString to = bound(QStringLiteral("to_value"));
        if (from.isEmpty() || to.isEmpty())
            continue;
        decl->range = QStringLiteral("[%1, %2]").arg(from, to);
        const QString step = bound(QStringLiteral("step"));
        if (!step.isEmpty() && step != QLatin1String("0") && step != QLatin1String("0.0"))
            decl->range += QStringLiteral(" step ") + step;
        break;
    }
}

} // namespace rosarch
