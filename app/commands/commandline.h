#pragma once

#include <QStringList>

class QCommandLineParser;

namespace rosarch {

/// The headless side of the one executable: `rosarch recover <workspace> --out <dir>`,
/// `--help`, `--version`. Exit codes: 0 ok, 1 analysis finished with errors reported (or the
/// artifacts could not be written), 2 usage.
class CommandLine
{
public:
    enum ExitCode
    {
        Ok = 0,
        AnalysisErrors = 1,
        UsageError = 2
    };

    /// True when the arguments ask for a headless command rather than the GUI: a command, an
    /// option of ours, or anything that is neither a folder nor a Qt option (a mistyped
    /// command, a wrong path), which gets a message instead of a window.
    static bool isHeadless(int argc, char **argv);
    /// The command `written` probably means ("" when none is close).
    static QString nearestCommand(const QString &written);
    /// Runs the headless command; `arguments` includes the program name.
    static int run(const QStringList &arguments);
    /// Parses a command's arguments. Returns the exit code when the command ends here (a
    /// parse error, printed with `usage`, or --help, printed to stdout), else -1.
    static int parseOrFinish(QCommandLineParser &parser, const QStringList &arguments,
                             const QString &usage = {});
};

} // namespace rosarch
