#include "launch/launchbudget.h"
#include "core/valuebudget.h"

namespace rosarch {

bool LaunchBudget::overBudget(LaunchDependencies *out, const Evidence &evidence)
{
    if (!out || out->nodes.size() + out->instances.size() < kMaxInstances)
        return false;
    if (m_instancesSaidFor != out) { // once per output: the rest of the fan-out is cut silently
        m_instancesSaidFor = out;
        Diagnostic diag;
        diag.severity = Diagnostic::Severity::Warning;
        diag.code = QStringLiteral("launch-evaluation-limit");
        diag.message = QStringLiteral("The launch files start more than %1 nodes and launch file "
                                      "instances (includes multiplying includes?); the nodes "
                                      "and includes from here on were not followed.")
                           .arg(kMaxInstances);
        diag.evidence = evidence;
        out->diagnostics.append(diag);
    }
    return true;
}

void LaunchBudget::sayValueLimit(LaunchDependencies *out, const Evidence &evidence)
{
    const QString where = evidence.file + QLatin1Char(':') + QString::number(evidence.line);
    if (!out || m_valueLimitSaid.contains(where))
        return;
    m_valueLimitSaid.insert(where);
    Diagnostic diag;
    diag.severity = Diagnostic::Severity::Warning;
    diag.code = QStringLiteral("evaluation-limit");
    diag.message = QStringLiteral("A value here grows past %1 characters (an argument built "
                                  "from itself, doubled?); it is left unresolved.")
                       .arg(kMaxValueChars);
    diag.evidence = evidence;
    out->diagnostics.append(diag);
}

} // namespace rosarch
