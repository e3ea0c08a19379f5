#pragma once

#include "syntax/syntaxtree.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace rosarch {

/// One parse of a file for two readers in the same run: stage 1 reads a Python launch file for
/// node classes and stage 2 reads it as a launch description, often at the same time on
/// different threads. Whichever parses it first hands the tree over once done with it; the
/// other takes it instead of parsing again. Only while a Run lives (one recovery); the trees
/// not taken go with it.
class ParseHandoff
{
public:
    /// Lets parses be handed over until it goes (runs do not nest: an inner one does nothing).
    class Run
    {
    public:
        Run();
        ~Run();
        Run(const Run &) = delete;
        Run &operator=(const Run &) = delete;

    private:
        bool m_owner = false;
    };

    /// Whether a tree of `file` is worth handing over: the files both readers parse.
    static bool wanted(const QByteArray &content);
    /// The tree of `file` another reader parsed from exactly `content`, taken; none otherwise.
    static std::optional<SyntaxTree> take(const QString &file, const QByteArray &content);
    /// take(), else a Python parse of `content`; `*parsedHere` says which (offer it when done).
    static SyntaxTree takeOrParse(const QString &file, const QByteArray &content, bool *parsedHere);
    /// Hands over a tree the caller is done with (dropped outside a Run, or when what waits
    /// to be taken is at its bound).
    static void offer(SyntaxTree tree);
    /// The trees waiting to be taken (for tests).
    static int waitingCount();
};

} // namespace rosarch
