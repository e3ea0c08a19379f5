#pragma once

#include <QString>
#include <QStringList>

namespace rosarch::perfbench {

/// The single-core baseline: every file the stages parse, parsed once with tree-sitter.
struct ParseBaseline
{
    qint64 ms = 0;
    int pythonFiles = 0;
    int cppFiles = 0;
    qint64 bytes = 0;
};

/// Parses, on this thread, every Python and C++ file of the workspace at `root` (the Python
/// launch files among them) with the grammars the analyzers use. Parse only, no analysis.
ParseBaseline parseBaseline(const QString &root);

/// How a recovery was run.
enum class Path
{
    Worker,    ///< through rosarch-stages, as the GUI runs it
    InProcess, ///< recoverWorkspace() in the measuring process
    Session,   ///< one StageSession kept across the runs, as the GUI's StageRunner keeps it
    Command,   ///< the `rosarch recover` command, end to end: artifacts written included
};

/// One recovery, measured in a child process of its own.
struct RunResult
{
    bool ok = false;
    QString error;
    qint64 ms = 0;        ///< wall time of stages 1 to 3 (the worker's start included)
    qint64 peakRssKb = 0; ///< of the process that did the analysis
};

/// Runs stages 1-3 on `root` once in a child process (`program --child <path> <root>`) with
/// the analysis cache in `cacheDir` ("" = no cache).
RunResult runChild(const QString &program, Path path, const QString &root, const QString &cacheDir);

/// The child's side: runs the recovery and prints "ms peakRssKb" on stdout.
int childMain(const QString &path, const QString &root);

/// Runs `runs` recoveries of `root` in one child process on one StageSession (the GUI's
/// path), after one unmeasured run that starts the worker and fills the cache; before each
/// measured run, `editedFile` (if any) is edited with the numbers from `firstEdit` on.
/// `result.ms` is unused; the runs' times go to `ms`.
RunResult runSessionChild(const QString &program, const QString &root, const QString &cacheDir,
                          int runs, const QString &editedFile, int firstEdit, QList<qint64> *ms);

/// The child's side of runSessionChild: prints "peakRssKb ms..." on stdout.
int sessionChildMain(const QStringList &args);

/// Copies the files of the workspace at `from` that the scanner reads into `to`.
bool copyWorkspace(const QString &from, const QString &to, QString *error);

/// The C++ source file to edit: `wanted` if given, else the largest .cpp file creating a port.
QString pickEditTarget(const QString &root, const QString &wanted);

/// Changes `file`'s content (a comment line with `n` in front), as a person saving an edit.
bool editFile(const QString &file, int n);

} // namespace rosarch::perfbench
