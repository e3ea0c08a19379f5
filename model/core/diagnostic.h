#pragma once

#include "core/evidence.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// A message from a stage about the input: a broken file, something skipped, something unsure.
struct Diagnostic
{
    enum class Severity
    {
        Info,
        Warning,
        Error
    };

    /// Another place that takes part in the finding: the publisher of a type mismatch seen
    /// from its subscriber, the other node of a duplicate name, the nearest existing name.
    struct Related
    {
        QString message; ///< what this place is, for a person ("the publisher, with type T")
        Evidence evidence;
        bool operator==(const Related &) const = default;
    };

    Severity severity = Severity::Warning;
    QString code;    ///< stable machine-readable kind, e.g. "syntax-error", "binary-file"
    QString message; ///< one sentence for a person
    Evidence evidence;
    QList<Related> related;
    /// The systems (root launch files) the finding was seen in, in the order they were checked;
    /// empty for a finding that belongs to no one system (a file, a launch line).
    QStringList contexts = {};
    /// Other keys the finding answers to: those the per-system findings merged into it had
    /// (their messages named the system), so baselines and project files written before the
    /// merge still recognise it.
    QStringList aliases = {};
    /// A finding about a port whose counterpart may be outside the system: the expected
    /// external that would accept it, "input /scan" or "output /cmd_vel" ("" otherwise).
    QString external = {};

    static QString severityName(Severity s);
    /// The finding's stable key (blueprint §5): its code, file and message, with no line or
    /// column, so that it survives edits elsewhere in the file. Baselines remember findings by
    /// it: "topic-unpublished:3f2a9c0e51b7d4a8".
    QString key() const;
    /// True when `keys` holds the key() or one of the aliases.
    template <typename Set> bool isIn(const Set &keys) const
    {
        if (keys.contains(key()))
            return true;
        for (const QString &alias : aliases)
            if (keys.contains(alias))
                return true;
        return false;
    }
    bool operator==(const Diagnostic &) const = default;

    /// Drops every diagnostic equal to an earlier one, keeping the order: in linear time (by a
    /// hash of code, place and message), where a list's contains() made it quadratic.
    static void removeDuplicates(QList<Diagnostic> *list);
};

} // namespace rosarch
