#pragma once

#include <QFlags>
#include <QMetaType>
#include <QString>

namespace rosarch {

/// What changed in a Document: which parts, and for a single node or suggestion, its id.
struct DocumentChange
{
    enum Part : unsigned
    {
        Model = 1u << 0,         ///< everything was replaced (a stage 1-3 run, another workspace)
        Launch = 1u << 1,        ///< stages 2 and 3 were replaced (a stage 2 re-run)
        LaunchOptions = 1u << 2, ///< the root launch file or argument values
        Node = 1u << 3,          ///< one node class (`id`): its description
        Suggestions = 1u << 4,   ///< the suggestion list was replaced
        Suggestion = 1u << 5,    ///< one suggestion's status (`id`)
        Decisions = 1u << 6,     ///< accepted decisions: groupings, names, descriptions
        Corrections = 1u << 7,   ///< the corrections (`id`: the one added or removed)
        Findings = 1u << 8,      ///< the hidden and accepted findings
        Accepted = 1u << 9,      ///< the model as accepted was made again (a background job)
    };
    Q_DECLARE_FLAGS(Parts, Part)

    Parts parts;
    QString id; ///< the node, suggestion or correction, for Node, Suggestion and Corrections

    bool has(Part part) const { return parts.testFlag(part); }
    /// True when a list the views show from scratch is replaced (model, launch, suggestions).
    bool isReset() const { return parts & (Model | Launch | Suggestions); }
};

Q_DECLARE_OPERATORS_FOR_FLAGS(DocumentChange::Parts)

} // namespace rosarch

Q_DECLARE_METATYPE(rosarch::DocumentChange)
