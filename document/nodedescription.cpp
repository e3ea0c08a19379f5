#include "nodedescription.h"
#include "document.h"

namespace rosarch {

NodeDescription NodeDescription::of(const Document &document, const QString &nodeId)
{
    const AtomicNode *node = document.atomicNodes().node(nodeId);
    if (!node)
        return {};
    NodeDescription d{node->description, node->description.isEmpty() ? Source::None : Source::Code};
    // The same order Document applies them in: the code, accepted suggestions, then a
    // person's own edits. The text is already the one in effect; only its source is asked.
    bool described = false;
    for (const Correction &c : document.corrections())
        described = described || c.kind == Correction::Kind::Describe;
    if (described) { // the keys are only made when a correction could name the class
        const QString key = document.keyOf(nodeId);
        for (const Correction &c : document.corrections())
            if (c.kind == Correction::Kind::Describe && !key.isEmpty() && c.target == key)
                d.source = Source::Correction;
    }
    if (d.source == Source::Correction)
        return d;
    for (const SuggestionDecision &s : document.decisions())
        if (s.kind == Suggestion::Kind::NodeDescription &&
            s.status == Suggestion::Status::Accepted && s.targetId == nodeId &&
            s.proposal == node->description)
            d.source = Source::Suggestion;
    return d;
}

QString NodeDescription::sourceText() const
{
    switch (source) {
    case Source::None:
        return tr("No description in the code");
    case Source::Code:
        return tr("from the code");
    case Source::Suggestion:
        return tr("from an accepted suggestion");
    case Source::Correction:
        return tr("written by a person");
    }
    return {};
}

} // namespace rosarch
