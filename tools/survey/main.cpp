// rosarch-survey: what the analyzers find in real code, for reading next to that code. Not a
// check: it prints what stage 1 or the launch readers recover from a workspace, with counts
// and timing, so a reading of public repositories can be compared with the analysis.
//
//   rosarch-survey nodes <workspace> [--dump]    node classes and ports per language
//   rosarch-survey launch <folder> [--dump]      launch files of every format, action kinds,
//                                                what stayed unresolved, diagnostics
#include "analysistext.h"
#include "launch/launchanalyzer.h"
#include "nodes/cpp/cppnodeanalyzer.h"
#include "nodes/python/pythonnodeanalyzer.h"
#include "workspace/sourcereader.h"
#include "workspace/workspacescanner.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTextStream>

using namespace rosarch;

namespace {

int surveyNodes(const Workspace &ws, bool dump, QTextStream &out)
{
    QElapsedTimer timer;
    const auto report = [&](const char *language, const LanguageAnalysis &a, qint64 ms) {
        qsizetype ports = 0;
        qsizetype unresolved = 0;
        for (const AtomicNode &n : a.nodes)
            for (const Port &p : n.ports) {
                ++ports;
                unresolved += p.isResolved() ? 0 : 1;
            }
        if (dump)
            out << AnalysisText::analysis(a);
        out << language << ": " << a.nodes.size() << " node classes, " << ports << " ports ("
            << unresolved << " with unresolved names), " << a.entryPoints.size()
            << " entry points, " << a.registrations.size() << " component registrations, "
            << a.diagnostics.size() << " diagnostics in " << ms << " ms\n";
    };
    timer.start();
    const LanguageAnalysis python = PythonNodeAnalyzer(ws).analyze();
    report("python", python, timer.restart());
    const LanguageAnalysis cpp = CppNodeAnalyzer(ws).analyze();
    report("c++", cpp, timer.elapsed());
    return 0;
}

int surveyLaunch(const Workspace &ws, bool dump, QTextStream &out)
{
    const SourceReader reader(ws.root);
    QMap<QString, int> files;
    QMap<QString, int> kinds;
    QMap<QString, int> unresolved;
    QMap<QString, int> diagnostics;
    QElapsedTimer timer;
    timer.start();
    for (const SourceFile &f : ws.files) {
        const char *format = f.language == SourceFile::Language::Python ? "python"
                             : f.language == SourceFile::Language::Xml  ? "xml"
                             : f.language == SourceFile::Language::Yaml ? "yaml"
                                                                        : nullptr;
        if (!format)
            continue;
        QByteArray content;
        QList<Diagnostic> skipped;
        if (!reader.read(f.path, &content, &skipped))
            continue;
        const std::optional<LaunchFileDescription> read = LaunchAnalyzer::read(f, content);
        if (!read)
            continue;
        const LaunchFileDescription &d = *read;
        ++files[QString::fromLatin1(format)];
        AnalysisText::tally(d.actions, &kinds, &unresolved);
        for (const Diagnostic &diag : std::as_const(d.diagnostics))
            ++diagnostics[diag.code];
        if (dump) {
            out << "== " << f.path << '\n';
            for (const QString &line : AnalysisText::actions(d.actions))
                out << "  " << line << '\n';
            for (const Diagnostic &diag : std::as_const(d.diagnostics))
                out << "  diagnostic " << diag.code << ' ' << diag.message << '\n';
        }
    }
    const auto print = [&](const char *what, const QMap<QString, int> &counts) {
        for (auto it = counts.cbegin(); it != counts.cend(); ++it)
            out << what << ' ' << it.key() << ' ' << it.value() << '\n';
    };
    print("files", files);
    print("kind", kinds);
    print("unresolved", unresolved);
    print("diagnostic", diagnostics);
    out << "read in " << timer.elapsed() << " ms\n";
    return 0;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("rosarch-survey"));
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "What rosarch's analyzers find in real code, with counts and timing.\n"
        "  nodes <workspace>   node classes and ports per language (stage 1 before linking)\n"
        "  launch <folder>     launch files of every format: action kinds, unresolved, "
        "diagnostics"));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("what"), QStringLiteral("nodes or launch"));
    parser.addPositionalArgument(QStringLiteral("folder"), QStringLiteral("the folder to read"));
    const QCommandLineOption dumpOption(QStringLiteral("dump"),
                                        QStringLiteral("Print everything found, not only counts."));
    parser.addOption(dumpOption);
    parser.process(app);
    QTextStream out(stdout);
    QTextStream err(stderr);
    const QStringList args = parser.positionalArguments();
    if (args.size() != 2 ||
        (args.first() != QLatin1String("nodes") && args.first() != QLatin1String("launch"))) {
        err << parser.helpText();
        return 2;
    }
    if (!QFileInfo(args.at(1)).isDir()) {
        err << "Not a folder: " << args.at(1) << '\n';
        return 2;
    }
    const Workspace ws = WorkspaceScanner::scan(args.at(1));
    out << ws.files.size() << " files in " << ws.packages.size() << " packages under " << ws.root
        << '\n';
    return args.first() == QLatin1String("nodes") ? surveyNodes(ws, parser.isSet(dumpOption), out)
                                                  : surveyLaunch(ws, parser.isSet(dumpOption), out);
}
