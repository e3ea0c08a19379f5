#include "pythonnodeanalyzer.h"

#include "pythonerrorrecovery.h"
#include "pythonmodulereader.h"
#include "pythonnodelinker.h"
#include "sourcereader.h"
#include "syntaxtree.h"

#include <QSet>

namespace rosarch {

namespace {
/// The dotted module path of a file: its stem, prefixed by the enclosing folders that are
/// Python packages (hold an __init__.py). A loose script is named by its path inside its ROS
/// package, so that same-named scripts in different folders stay apart.
QString modulePath(const QString &file, const QString &packagePath,
                   const QSet<QString> &pythonFiles)
{
    QStringList parts;
    QString dir = file.section(QLatin1Char('/'), 0, -2);
    QString stem = file.section(QLatin1Char('/'), -1);
    stem.chop(3); // ".py"
    if (stem != QLatin1String("__init__"))
        parts.append(stem);
    if (!dir.isEmpty() && !pythonFiles.contains(dir + QStringLiteral("/__init__.py"))) {
        QString inPackage = file;
        if (!packagePath.isEmpty() && file.startsWith(packagePath + QLatin1Char('/')))
            inPackage = file.mid(packagePath.size() + 1);
        inPackage.chop(3);
        return inPackage.replace(QLatin1Char('/'), QLatin1Char('.'));
    }
    while (!dir.isEmpty() && pythonFiles.contains(dir + QStringLiteral("/__init__.py"))) {
        parts.prepend(dir.section(QLatin1Char('/'), -1));
        dir = dir.section(QLatin1Char('/'), 0, -2);
    }
    return parts.isEmpty() ? stem : parts.join(QLatin1Char('.'));
}
} // namespace

PythonNodeAnalyzer::PythonNodeAnalyzer(const Workspace &workspace) : m_workspace(workspace) {}

LanguageAnalysis PythonNodeAnalyzer::analyze(const StageControl &control) const
{
    LanguageAnalysis result;
    QList<const SourceFile *> files;
    QSet<QString> pythonFiles;
    for (const SourceFile &f : m_workspace.files) {
        if (f.language != SourceFile::Language::Python)
            continue;
        files.append(&f);
        pythonFiles.insert(f.path);
    }

    const SourceReader reader(m_workspace.root);
    QList<PythonModuleFacts> modules;
    modules.reserve(files.size());
    for (int i = 0; i < files.size(); ++i) {
        if (control.isCanceled())
            return result;
        const SourceFile &file = *files.at(i);
        control.report(i, int(files.size()), file.path);
        const FileWork work(control, file.path);
        QByteArray content;
        if (work.skip(&result.diagnostics) ||
            !reader.read(file.path, &content, &result.diagnostics))
            continue;
        SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Python, content, file.path);
        if (!ts::isNull(tree.root()) && ts_node_has_error(tree.root())) {
            QList<Diagnostic> isolated;
            const QByteArray repaired = PythonErrorRecovery::isolate(content, file.path, &isolated);
            if (!isolated.isEmpty()) {
                result.diagnostics.append(isolated);
                tree = SyntaxTree::parse(SyntaxTree::Grammar::Python, repaired, file.path);
            }
        }
        result.diagnostics.append(tree.syntaxErrors());
        if (ts::isNull(tree.root()))
            continue;
        const RosPackage *package = m_workspace.package(file.package);
        const QString module =
            modulePath(file.path, package ? package->path : QString(), pythonFiles);
        modules.append(PythonModuleReader(tree, module).read(file.package));
    }
    control.report(int(files.size()), int(files.size()), QString());
    PythonNodeLinker(modules).link(&result);
    return result;
}

} // namespace rosarch
