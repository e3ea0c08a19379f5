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

LaunchFileDescription PythonLaunchReader::read(const QByteArray &content, const QString &file)
{
    LaunchFileDescription d;
    d.file = file;
    d.format = LaunchFileDescription::Format::Python;
    const SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Python, content, file);
    d.diagnostics = tree.syntaxErrors();
    if (ts::isNull(tree.root()))
        return d;
    pylaunch::PythonLaunchEvaluator evaluator(tree);
    d.actions = evaluator.run();
    d.diagnostics += evaluator.diagnostics();
    return d;
}

} // namespace rosarch
