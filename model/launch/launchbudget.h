#pragma once

#include "core/evidence.h"
#include "core/launchdependencies.h"

#include <QSet>
#include <QString>

namespace rosarch {

/// The budgets of one launch execution that are not counts of steps: how many node and launch
/// file instances an output may hold, and the size of a value (kMaxValueChars, enforced by
/// SubstitutionEvaluator). Each limit hit is said once, where it was hit.
class LaunchBudget
{
public:
    /// Node and launch file instances one output holds at most: includes that multiply
    /// includes reach millions from a few kilobytes (the whole Autoware system holds 3,424).
    /// Past it, a launch-evaluation-limit warning.
    static constexpr qsizetype kMaxInstances = 20000;

    /// True, and said once per output, when `out` holds kMaxInstances instances already.
    bool overBudget(LaunchDependencies *out, const Evidence &evidence);
    /// An evaluation-limit warning in `out` at `evidence`, once per place.
    void sayValueLimit(LaunchDependencies *out, const Evidence &evidence);

private:
    const LaunchDependencies *m_instancesSaidFor = nullptr;
    QSet<QString> m_valueLimitSaid; ///< file:line of each evaluation-limit said
};

} // namespace rosarch
