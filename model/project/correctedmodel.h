#pragma once

#include "pipeline/recovery.h"
#include "project/project.h"
#include "project/stablekeys.h"

#include <QList>
#include <QMap>
#include <QString>

namespace rosarch {

/// A decision or correction of the project that matches nothing in a recovery (blueprint §5):
/// it is listed with what it said and applied to nothing.
struct Orphan
{
    enum class Source
    {
        Decision,
        Correction
    };
    Source source = Source::Correction;
    QString id;     ///< the correction id, or the decision's key
    QString kind;   ///< the correction's or the decision's kind name
    QString target; ///< the stable key it names
    QString said;   ///< what it said: the correction's summary or the decision's proposal
    QString reason; ///< why it no longer matches
    bool operator==(const Orphan &) const = default;
};

/// The recovered model with a project applied.
struct CorrectedRecovery
{
    Recovery recovery;
    QList<Orphan> orphans;
    /// The decisions of the project bound to this recovery: id-based (targetId and memberIds are
    /// the ids of the recovery), by SuggestionDecision::key. Orphaned ones are left out.
    QMap<QString, SuggestionDecision> decisions;
};

/// The model as a person corrected it: one pure function from a recovery and a project, used
/// by the GUI, `recover --project` and every export, so that the same project gives
/// byte-identical artifacts everywhere.
class CorrectedModel
{
public:
    /// `recovered` with the project applied: accepted suggestions first (provenance
    /// `suggested`), then the corrections in the order they were made (`corrected`), then
    /// review marks. Stage 3 is composed again when anything it reads changed. What names
    /// nothing in `recovered` is listed in `orphans` and changes nothing.
    static CorrectedRecovery apply(const Recovery &recovered, const Project &project);

    /// `decision` (ids of the recovery `keys` was built from) with its target and members as
    /// stable keys; false when one of them has no key.
    static bool keyed(const SuggestionDecision &decision, const StableKeys &keys,
                      SuggestionDecision *out);
    /// The reverse: a decision stored with keys, bound to the ids of `keys`' recovery; false
    /// (with `reason`) when its target or a member is not there.
    static bool bound(const SuggestionDecision &decision, const StableKeys &keys,
                      SuggestionDecision *out, QString *reason);
};

} // namespace rosarch
