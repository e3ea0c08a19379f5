#pragma once

#include <QDateTime>
#include <QJsonObject>
#include <QString>

namespace rosarch {

/// A person's decision about one finding (a diagnostic), kept in the project by the finding's
/// stable key (Diagnostic::key): hidden (not worth looking at here) or accepted (seen, and
/// fine as it is: `rosarch check` no longer counts it as new). Like a correction, it says who
/// decided, when and, optionally, why.
struct FindingMark
{
    enum class Status
    {
        Hidden,
        Accepted
    };

    QString key; ///< Diagnostic::key(), e.g. "topic-unpublished:3f2a9c0e51b7d4a8"
    Status status = Status::Hidden;
    QString reason;
    QString author;
    QDateTime time; ///< UTC

    static QString statusName(Status status);
    QJsonObject toJson() const;
    /// False with `error` when `o` is not a finding mark.
    static bool fromJson(const QJsonObject &o, FindingMark *mark, QString *error);
    bool operator==(const FindingMark &) const = default;
};

} // namespace rosarch
