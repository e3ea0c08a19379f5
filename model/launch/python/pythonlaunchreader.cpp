#include "pythonlaunchreader.h"

#include "pythonlaunchevaluator.h"
#include "syntaxtree.h"

namespace rosarch {

bool PythonLaunchReader::isLaunchFile(const QByteArray &content)
{
    if (!content.contains("generate_launch_description"))
        return false;
    const SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Python, content, QString());
    return !ts::isNull(pylaunch::PythonLaunchEvaluator::launchFunction(tree));
}

namespace {

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

LaunchFileDescription PythonLaunchReader::read(const QByteArray &content, const QString &file)
{
    return describe(SyntaxTree::parse(SyntaxTree::Grammar::Python, content, file), file);
}

std::optional<LaunchFileDescription> PythonLaunchReader::readIfLaunchFile(const QByteArray &content,
                                                                          const QString &file)
{
    if (!content.contains("generate_launch_description"))
        return std::nullopt;
    const SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Python, content, file);
    if (ts::isNull(pylaunch::PythonLaunchEvaluator::launchFunction(tree)))
        return std::nullopt;
    return describe(tree, file);
}

} // namespace rosarch
