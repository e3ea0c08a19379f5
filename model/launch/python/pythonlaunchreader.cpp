#include "launch/python/pythonlaunchreader.h"

#include "launch/python/pythonlaunchevaluator.h"
#include "syntax/parsehandoff.h"
#include "syntax/pythonsyntax.h"
#include "syntax/syntaxtree.h"

namespace rosarch {

namespace {

/// The module-level generate_launch_description definition, or a null node.
TSNode launchFunction(const SyntaxTree &tree)
{
    for (TSNode n : ts::namedChildren(tree.root())) {
        TSNode def = py::undecorated(n);
        if (ts::is(def, "function_definition") &&
            tree.view(ts::field(def, "name")) == "generate_launch_description")
            return def;
    }
    return TSNode{};
}

LaunchFileDescription describe(const SyntaxTree &tree, const QString &file)
{
    LaunchFileDescription d;
    d.file = file;
    d.format = LaunchFileDescription::Format::Python;
    d.diagnostics = tree.syntaxErrors();
    if (ts::isNull(tree.root()))
        return d;
    pylaunch::PythonLaunchEvaluator evaluator(tree);
    d.actions = evaluator.run();
    d.diagnostics += evaluator.diagnostics();
    return d;
}

} // namespace

bool PythonLaunchReader::isLaunchFile(const QByteArray &content)
{
    if (!py::namesLaunchFunction(content))
        return false;
    const SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Python, content, QString());
    return !ts::isNull(launchFunction(tree));
}

LaunchFileDescription PythonLaunchReader::read(const QByteArray &content, const QString &file)
{
    return describe(SyntaxTree::parse(SyntaxTree::Grammar::Python, content, file), file);
}

std::optional<LaunchFileDescription> PythonLaunchReader::readIfLaunchFile(const QByteArray &content,
                                                                          const QString &file)
{
    if (!py::namesLaunchFunction(content))
        return std::nullopt;
    // Stage 1 reads the same file for node classes: one parse for both (ParseHandoff).
    bool parsedHere = true;
    SyntaxTree tree = ParseHandoff::takeOrParse(file, content, &parsedHere);
    std::optional<LaunchFileDescription> d;
    if (!ts::isNull(launchFunction(tree)))
        d = describe(tree, file);
    if (parsedHere)
        ParseHandoff::offer(std::move(tree));
    return d;
}

} // namespace rosarch
