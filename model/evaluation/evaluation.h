#pragma once

#include "plantuml/umldiagram.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// Counts and the ratios computed from them (blueprint §4). Both sides empty scores 1/1/1;
/// otherwise an undefined ratio (nothing recovered, or nothing expected) is 0, so that
/// F1 = 2TP / (2TP + FP + FN) always holds.
struct EvaluationScore
{
    int tp = 0;
    int fp = 0;
    int fn = 0;
    double precision = 0;
    double recall = 0;
    double f1 = 0;

    /// The ratios of the counts, with the conventions above.
    static EvaluationScore fromCounts(int tp, int fp, int fn);
    /// The mean of the ratios of `scores` (0/0/0 when empty); the counts are summed.
    static EvaluationScore mean(const QList<EvaluationScore> &scores);
};

/// One element kind in one diagram: its score and the elements that differ.
struct KindEvaluation
{
    QString kind;
    EvaluationScore score;
    QList<UmlElement>
        falsePositives; ///< recovered, not in the reference (line in the recovered file)
    QList<UmlElement>
        falseNegatives; ///< in the reference, not recovered (line in the reference file)
};

/// One reference diagram against its recovered counterpart (matched by name).
struct DiagramEvaluation
{
    QString name;
    QString referenceFile;
    QString recoveredFile; ///< "" when missing
    bool missing = false;  ///< no recovered counterpart: scores 0/0/0
    QList<KindEvaluation> kinds;
    EvaluationScore total; ///< all kinds' counts together

    const KindEvaluation *kind(const QString &kind) const;
};

/// One element kind over all diagrams of a level.
struct KindSummary
{
    QString kind;
    EvaluationScore micro; ///< from the summed counts
    EvaluationScore macro; ///< mean of the per-diagram ratios (counts summed)
};

/// The evaluation of one level (ACD or CCD).
struct LevelEvaluation
{
    UmlLevel level = UmlLevel::Unknown;
    QList<DiagramEvaluation> diagrams; ///< one per reference diagram, in reference order
    QList<KindSummary> kinds;          ///< in umlKinds() order
    EvaluationScore micro;             ///< all kinds, summed counts over all diagrams
    EvaluationScore macro;             ///< mean of the diagrams' totals
    /// Recovered diagrams with no reference counterpart: listed, not scored (neither macro nor
    /// micro), since the reference defines what is evaluated.
    QList<UmlDiagram> extra;

    const DiagramEvaluation *diagram(const QString &name) const;
    const KindSummary *kind(const QString &kind) const;
};

/// What Evaluator computes: one entry per evaluated level.
struct Evaluation
{
    QList<LevelEvaluation> levels;

    const LevelEvaluation *level(UmlLevel level) const;
};

} // namespace rosarch
