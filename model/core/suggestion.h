#pragma once

#include "core/evidence.h"

#include <QDateTime>
#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// A proposed change to the recovered architecture, from an LLM or the deterministic
/// provider, that an engineer accepts or rejects. Only checked suggestions reach the user.
struct Suggestion
{
    enum class Kind
    {
        NodeDescription,
        SubsystemGrouping,
        NameResolution
    };
    enum class Status
    {
        Pending,
        Accepted,
        Rejected
    };

    /// A cited source range and the text it is cited for (it must appear on those lines).
    struct Citation
    {
        Evidence evidence; ///< file relative to the workspace, line .. endLine
        QString quote;
        bool operator==(const Citation &) const = default;
    };

    /// Who proposed it and from which prompt, when.
    struct Origin
    {
        QString provider;    ///< "llm:<model>" or "deterministic"
        QString prompt;      ///< prompt name ("" for deterministic rules)
        QDateTime timestamp; ///< UTC
        bool operator==(const Origin &) const = default;
    };

    QString id; ///< "s1", ... in deterministic order
    Kind kind = Kind::NodeDescription;
    /// node-description: the ARC id; subsystem-grouping: the root launch-file instance id;
    /// name-resolution: the unresolved item id ("arc_2/p1" for a port, "n3#u1" for a launch item).
    QString targetId;
    QStringList memberIds; ///< subsystem-grouping: the node instance ids of the group, sorted
    QString value;         ///< the description, the group name, or the candidate value
    QString rationale;
    /// The value is text quoted from the repository (a docstring, a comment), not written by
    /// rosarch or a model: it is data, and is shown as a quotation wherever it is proposed.
    bool quoted = false;
    QList<Citation> evidence;
    Origin origin;
    Status status = Status::Pending;

    bool operator==(const Suggestion &) const = default;

    /// "node-description", "subsystem-grouping", "name-resolution".
    static QString kindName(Kind kind);
    static bool kindFromName(const QString &name, Kind *kind);
    /// "pending", "accepted", "rejected".
    static QString statusName(Status status);
    static bool statusFromName(const QString &name, Status *status);
    /// Identifies what the suggestion is about, independent of wording: kind, target, members.
    QString subjectKey() const;
};

} // namespace rosarch
