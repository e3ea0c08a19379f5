#include "evaluation/evaluation.h"

namespace rosarch {

EvaluationScore EvaluationScore::fromCounts(int tp, int fp, int fn)
{
    EvaluationScore s;
    s.tp = tp;
    s.fp = fp;
    s.fn = fn;
    if (tp + fp + fn == 0) {
        s.precision = s.recall = s.f1 = 1;
        return s;
    }
    s.precision = tp + fp > 0 ? double(tp) / (tp + fp) : 0;
    s.recall = tp + fn > 0 ? double(tp) / (tp + fn) : 0;
    s.f1 = s.precision + s.recall > 0 ? 2 * s.precision * s.recall / (s.precision + s.recall) : 0;
    return s;
}

EvaluationScore EvaluationScore::mean(const QList<EvaluationScore> &scores)
{
    EvaluationScore m;
    for (const EvaluationScore &s : scores) {
        m.tp += s.tp;
        m.fp += s.fp;
        m.fn += s.fn;
        m.precision += s.precision;
        m.recall += s.recall;
        m.f1 += s.f1;
    }
    if (!scores.isEmpty()) {
        m.precision /= scores.size();
        m.recall /= scores.size();
        m.f1 /= scores.size();
    }
    return m;
}

const KindEvaluation *DiagramEvaluation::kind(const QString &k) const
{
    for (const KindEvaluation &e : kinds)
        if (e.kind == k)
            return &e;
    return nullptr;
}

const DiagramEvaluation *LevelEvaluation::diagram(const QString &name) const
{
    for (const DiagramEvaluation &d : diagrams)
        if (d.name == name)
            return &d;
    return nullptr;
}

const KindSummary *LevelEvaluation::kind(const QString &k) const
{
    for (const KindSummary &s : kinds)
        if (s.kind == k)
            return &s;
    return nullptr;
}

const LevelEvaluation *Evaluation::level(UmlLevel l) const
{
    for (const LevelEvaluation &e : levels)
        if (e.level == l)
            return &e;
    return nullptr;
}

} // namespace rosarch
