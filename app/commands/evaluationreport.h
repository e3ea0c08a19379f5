#pragma once

#include "evaluation/evaluation.h"

#include <QString>

namespace rosarch {

/// The evaluation as a person reads it: per-kind table with micro and macro scores, the
/// per-diagram lines and the false positives and negatives with their file and line.
/// Shared by `rosarch eval` and the GUI's comparison with a reference model.
namespace EvaluationReport {
QString levelText(const LevelEvaluation &level, int recoveredDiagrams);
}

} // namespace rosarch
