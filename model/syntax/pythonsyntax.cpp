#include "syntax/pythonsyntax.h"

namespace rosarch::py {

namespace {
bool isPositional(TSNode n)
{
    const std::string_view t = ts::type(n);
    return t != "keyword_argument" && t != "comment" && t != "dictionary_splat";
}
} // namespace

TSNode positional(TSNode call, int index)
{
    TSNode args = ts::field(call, "arguments");
    if (!ts::is(args, "argument_list"))
        return TSNode{};
    int i = 0;
    const uint32_t count = ts_node_named_child_count(args);
    for (uint32_t c = 0; c < count; ++c) {
        TSNode n = ts_node_named_child(args, c);
        if (!isPositional(n))
            continue;
        if (ts::is(n, "list_splat"))
            return TSNode{};
        if (i == index)
            return n;
        ++i;
    }
    return TSNode{};
}

TSNode keyword(const SyntaxTree &tree, TSNode call, std::string_view name)
{
    TSNode args = ts::field(call, "arguments");
    if (!ts::is(args, "argument_list"))
        return TSNode{};
    const uint32_t count = ts_node_named_child_count(args);
    for (uint32_t c = 0; c < count; ++c) {
        TSNode n = ts_node_named_child(args, c);
        if (ts::is(n, "keyword_argument") && tree.view(ts::field(n, "name")) == name)
            return ts::field(n, "value");
    }
    return TSNode{};
}

TSNode argument(const SyntaxTree &tree, TSNode call, int index, std::string_view name)
{
    TSNode n = index >= 0 ? positional(call, index) : TSNode{};
    if (ts::isNull(n) && !name.empty())
        n = keyword(tree, call, name);
    return n;
}

std::string_view calleeName(const SyntaxTree &tree, TSNode call)
{
    TSNode f = ts::field(call, "function");
    if (ts::is(f, "identifier"))
        return tree.view(f);
    if (ts::is(f, "attribute"))
        return tree.view(ts::field(f, "attribute"));
    return {};
}

TSNode calleeObject(TSNode call)
{
    TSNode f = ts::field(call, "function");
    return ts::is(f, "attribute") ? ts::field(f, "object") : TSNode{};
}

bool isDottedName(TSNode node)
{
    while (ts::is(node, "attribute"))
        node = ts::field(node, "object");
    return ts::is(node, "identifier");
}

std::vector<Parameter> parameters(const SyntaxTree &tree, TSNode functionDefinition)
{
    std::vector<Parameter> out;
    for (TSNode p : ts::namedChildren(ts::field(functionDefinition, "parameters"))) {
        Parameter param;
        const std::string_view t = ts::type(p);
        if (t == "identifier") {
            param.name = tree.text(p);
        } else if (t == "typed_parameter") {
            TSNode id = ts_node_named_child(p, 0);
            if (!ts::is(id, "identifier"))
                continue; // *args: T, **kwargs: T
            param.name = tree.text(id);
        } else if (t == "default_parameter" || t == "typed_default_parameter") {
            TSNode id = ts::field(p, "name");
            if (!ts::is(id, "identifier"))
                continue;
            param.name = tree.text(id);
            param.defaultValue = ts::field(p, "value");
        } else {
            continue; // *args, **kwargs, separators, comments
        }
        out.push_back(param);
    }
    return out;
}

TSNode undecorated(TSNode node)
{
    if (ts::is(node, "decorated_definition"))
        return ts::field(node, "definition");
    return node;
}

} // namespace rosarch::py
