#pragma once

#include "accepted/suggestiondecision.h"
#include "core/subsystemgroup.h"
#include "pipeline/recovery.h"

#include <QList>
#include <QMap>
#include <QString>

namespace rosarch {

/// What a person accepted that changes the model, limited to what exists in one recovery.
struct AcceptedDecisions
{
    /// Accepted subsystem groupings whose root launch file and member instances exist.
    QList<SubsystemGroup> groupings;
    /// Accepted values of unresolved items that exist: item id ("arc_2/p1", "n3#u1") → value.
    QMap<QString, QString> names;
    /// Accepted node descriptions of node classes that exist: node id → text.
    QMap<QString, QString> descriptions;

    bool isEmpty() const
    {
        return groupings.isEmpty() && names.isEmpty() && descriptions.isEmpty();
    }
};

/// The model as a person accepted it: one pure function from a recovery and the decisions on
/// it, used by the diagram, the exports and the headless commands alike, so that the same
/// workspace and decisions give the same artifacts everywhere.
class AcceptedModel
{
public:
    /// The accepted decisions among `decisions` whose targets exist in `recovery`.
    static AcceptedDecisions select(const QMap<QString, SuggestionDecision> &decisions,
                                    const Recovery &recovery);
    /// `recovery` with `accepted` applied: node descriptions set; ports the code names by an
    /// expression given their accepted names and stage 3 composed again, so they resolve, wire
    /// and promote like literal names; accepted groupings nested as subsystems. Launch items
    /// keep their values (a new value needs a stage 2 run).
    static Recovery apply(const Recovery &recovery, const AcceptedDecisions &accepted);
};

} // namespace rosarch
