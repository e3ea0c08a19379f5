#pragma once

#include "evaluation/evaluation.h"
#include "plantuml/umldiagram.h"

#include <QList>

namespace rosarch {

/// Compares a reference model with a recovered one as canonical multisets of elements
/// (blueprint §4): per element kind and per diagram, then macro and micro averages per level.
class Evaluator
{
public:
    /// Evaluates each of `levels`; diagrams of other levels are not looked at.
    static Evaluation evaluate(const QList<UmlDiagram> &reference,
                               const QList<UmlDiagram> &recovered, const QList<UmlLevel> &levels);
    /// One level: reference diagrams are matched to recovered ones by name (then file stem).
    static LevelEvaluation evaluateLevel(const QList<UmlDiagram> &reference,
                                         const QList<UmlDiagram> &recovered, UmlLevel level);
    /// One diagram pair; `recovered` null means missing (every kind 0/0/0).
    static DiagramEvaluation evaluateDiagram(const UmlDiagram &reference,
                                             const UmlDiagram *recovered);
    /// One kind: shared elements (as a multiset, by value) are TP, the rest FP or FN.
    static KindEvaluation compare(const QString &kind, const QList<UmlElement> &reference,
                                  const QList<UmlElement> &recovered);
};

} // namespace rosarch
