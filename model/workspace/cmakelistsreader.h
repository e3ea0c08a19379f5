#pragma once

#include "core/diagnostic.h"
#include "core/rospackage.h"

#include <QHash>
#include <QList>
#include <QSet>
#include <QString>
#include <QStringList>
#include <functional>

namespace rosarch {

/// Reads the executables and component plugins a package's CMakeLists.txt declares:
/// add_executable, ament_auto_add_executable, add_library (for plugin sources),
/// rclcpp_components_register_node(s), set() variables, foreach loops and add_subdirectory.
/// Not a CMake interpreter: conditions are ignored (every branch counts).
class CMakeListsReader
{
public:
    /// `load` returns a file's content by workspace-relative path (false if missing).
    using Loader = std::function<bool(const QString &relativePath, QByteArray *content)>;

    explicit CMakeListsReader(Loader load);

    /// A foreach loop runs its body for at most this many items; the rest is said and skipped.
    static constexpr int kMaxForeachItems = 256;
    /// Function calls and loop iterations per read, together: nested loops and recursive
    /// functions multiply, and a file must not make that a hang. Past it, they are skipped.
    static constexpr int kMaxBodyRuns = 10000;

    /// Reads `file` (workspace-relative CMakeLists.txt) and the subdirectories it adds.
    QList<Executable> read(const QString &file, QList<Diagnostic> *diagnostics);

    struct Command
    {
        QString name; ///< lower-cased
        QStringList args;
        int line = 0;
        int endLine = 0;
    };
    /// Splits CMake source into commands (exposed for tests).
    static QList<Command> tokenize(const QByteArray &content);

private:
    struct Function
    {
        QStringList params;
        QList<Command> body;
    };
    void readFile(const QString &file, int depth, QList<Diagnostic> *diagnostics);
    void execute(const QList<Command> &commands, int depth, QList<Diagnostic> *diagnostics);
    void parseArguments(const QStringList &rawArgs);
    /// The items a foreach(...) header loops over (its arguments after the loop variable).
    QStringList foreachItems(const QStringList &rawArgs) const;
    /// `text` with its variables expanded; empty, and m_valueTooLarge set, past the size budget.
    QString expand(const QString &text) const;
    /// Says (an evaluation-limit warning at `where`) and clears a value past the size budget.
    bool valueTooLarge(const Evidence &where, QList<Diagnostic> *diagnostics);
    mutable bool m_valueTooLarge = false;
    QSet<QString> m_valueLimitSaid; ///< file:line of each evaluation-limit said
    QStringList expandArgs(const QStringList &args) const;

    Loader m_load;
    QString m_file;       ///< the CMakeLists.txt being executed
    QSet<QString> m_read; ///< every CMakeLists.txt read in this run (no file is read twice)
    QString m_dir;        ///< its folder, relative to the workspace root
    QHash<QString, Function> m_functions;
    int m_bodyRuns = 0; ///< function bodies and loop bodies run in this read
    /// Takes one run from the budget; false (and said once) when it is spent.
    bool takeBodyRun(const Evidence &where, QList<Diagnostic> *diagnostics);
    QHash<QString, QString> m_vars;
    QHash<QString, QStringList> m_targetSources; ///< target -> workspace-relative sources
    QList<Executable> m_executables;
    QList<Executable> m_plugins; ///< registrations, linked to target sources at the end
};

} // namespace rosarch
