#pragma once

#include "evidence.h"

#include <QString>

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

    Severity severity = Severity::Warning;
    QString code;    ///< stable machine-readable kind, e.g. "syntax-error", "binary-file"
    QString message; ///< one sentence for a person
    Evidence evidence;

    static QString severityName(Severity s);
    bool operator==(const Diagnostic &) const = default;
};

} // namespace rosarch
