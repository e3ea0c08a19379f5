#pragma once

#include "evaluation/evaluation.h"
#include "plantuml/umlmodel.h"

#include <QByteArray>

namespace rosarch {

/// The evaluation as JSON, with the reader's notes and warnings of both inputs, for
/// `rosarch eval --json`. Deterministic: the same inputs give the same bytes.
class EvaluationJson
{
public:
    static QByteArray write(const Evaluation &evaluation, const UmlModel &reference,
                            const UmlModel &recovered);
};

} // namespace rosarch
