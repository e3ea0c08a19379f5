#pragma once

#include "core/diagnostic.h"

#include <QByteArray>
#include <QList>
#include <QSet>
#include <QString>

namespace rosarch {

/// One finding of `rosarch check`: a diagnostic, and whether a baseline already holds it.
struct CheckFinding
{
    Diagnostic diagnostic;
    QString key;            ///< Diagnostic::key()
    bool baselined = false; ///< in the baseline: reported, but never fails the check
    bool failing = false;   ///< new, and at or above the --fail-on severity
};

/// The findings of one check run, and their formats: text for a terminal, JSON (which is
/// also a baseline), SARIF 2.1.0 for code scanning, JUnit XML for CI test reports.
class CheckReport
{
public:
    /// `failOn` is the lowest severity that fails; `failNever` reports without failing.
    CheckReport(const QList<Diagnostic> &diagnostics, const QSet<QString> &baseline,
                Diagnostic::Severity failOn, bool failNever = false);

    const QList<CheckFinding> &findings() const { return m_findings; }
    int failing() const;
    int baselined() const;
    int count(Diagnostic::Severity severity) const;

    /// `file:line:column: severity: message [code]`, related places indented below, and a
    /// summary line.
    QString text() const;
    /// {"version", "tool", "summary", "findings": [{key, code, severity, message, evidence,
    /// related, baselined}]}; `--baseline` reads it back.
    QByteArray json(const QString &toolVersion) const;
    /// SARIF 2.1.0: one run, one rule per diagnostic kind (with help text), results with
    /// locations relative to %SRCROOT% (the workspace), related locations, the stable key as
    /// a partial fingerprint, and baselined findings as externally suppressed.
    QByteArray sarif(const QString &workspace, const QString &toolVersion) const;
    /// JUnit XML: one test case per finding, failed when it fails the check, skipped when
    /// baselined.
    QByteArray junit() const;

    /// The keys in a baseline: the JSON this class writes, or one key per line ('#' starts a
    /// comment). False, with `error`, when the file is neither.
    static bool readBaseline(const QByteArray &data, QSet<QString> *keys, QString *error);

private:
    QList<CheckFinding> m_findings;
};

} // namespace rosarch
