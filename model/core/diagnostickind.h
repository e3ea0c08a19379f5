#pragma once

#include <QList>
#include <QString>

namespace rosarch {

/// What a kind of diagnostic means and how to fix it: the rule behind a `Diagnostic::code`,
/// for a person reading a finding (the GUI, `rosarch check`, SARIF rule help).
struct DiagnosticKind
{
    QString code;  ///< "topic-unpublished"
    QString title; ///< "Subscription that nobody publishes"
    QString help;  ///< what the check means, why it matters, and how to fix it
    /// The kind's usual severity: what a code-scanning tool shows before it sees a finding.
    QString defaultLevel; ///< "error", "warning" or "note"

    /// Every kind rosarch reports, in a fixed order.
    static const QList<DiagnosticKind> &all();
    /// The kind of `code`; an unknown code gets a generic entry naming it.
    static DiagnosticKind of(const QString &code);
};

} // namespace rosarch
