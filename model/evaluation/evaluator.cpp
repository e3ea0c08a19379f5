#include "evaluation/evaluator.h"

#include <QFileInfo>
#include <QMap>

namespace rosarch {

namespace {

QList<UmlElement> ofKind(const QList<UmlElement> &elements, const QString &kind)
{
    QList<UmlElement> out;
    for (const UmlElement &e : elements)
        if (e.kind == kind)
            out << e;
    return out;
}

QString stem(const QString &file)
{
    return QFileInfo(file).completeBaseName();
}

} // namespace

KindEvaluation Evaluator::compare(const QString &kind, const QList<UmlElement> &reference,
                                  const QList<UmlElement> &recovered)
{
    // QMap keeps the differences sorted by value: stable reports.
    QMap<QString, QList<UmlElement>> ref, rec;
    for (const UmlElement &e : reference)
        ref[e.value] << e;
    for (const UmlElement &e : recovered)
        rec[e.value] << e;
    KindEvaluation k;
    k.kind = kind;
    int tp = 0;
    for (auto it = ref.cbegin(); it != ref.cend(); ++it) {
        const QList<UmlElement> matches = rec.value(it.key());
        const qsizetype shared = std::min(it.value().size(), matches.size());
        tp += int(shared);
        k.falseNegatives.append(it.value().mid(shared));
    }
    for (auto it = rec.cbegin(); it != rec.cend(); ++it) {
        const qsizetype shared = std::min(it.value().size(), ref.value(it.key()).size());
        k.falsePositives.append(it.value().mid(shared));
    }
    k.score =
        EvaluationScore::fromCounts(tp, int(k.falsePositives.size()), int(k.falseNegatives.size()));
    return k;
}

DiagramEvaluation Evaluator::evaluateDiagram(const UmlDiagram &reference,
                                             const UmlDiagram *recovered)
{
    DiagramEvaluation d;
    d.name = reference.name;
    d.referenceFile = reference.file;
    d.missing = recovered == nullptr;
    if (recovered)
        d.recoveredFile = recovered->file;
    int tp = 0, fp = 0, fn = 0;
    for (const QString &kind : umlKinds(reference.level)) {
        KindEvaluation k =
            compare(kind, ofKind(reference.elements, kind),
                    recovered ? ofKind(recovered->elements, kind) : QList<UmlElement>{});
        if (d.missing) // §4: a reference diagram with no recovered counterpart scores 0/0/0
            k.score.precision = k.score.recall = k.score.f1 = 0;
        tp += k.score.tp;
        fp += k.score.fp;
        fn += k.score.fn;
        d.kinds << k;
    }
    d.total = EvaluationScore::fromCounts(tp, fp, fn);
    if (d.missing)
        d.total.precision = d.total.recall = d.total.f1 = 0;
    return d;
}

LevelEvaluation Evaluator::evaluateLevel(const QList<UmlDiagram> &reference,
                                         const QList<UmlDiagram> &recovered, UmlLevel level)
{
    LevelEvaluation result;
    result.level = level;
    QList<const UmlDiagram *> unmatched;
    for (const UmlDiagram &d : recovered)
        if (d.level == level)
            unmatched << &d;
    for (const UmlDiagram &ref : reference) {
        if (ref.level != level)
            continue;
        qsizetype pick = -1;
        for (qsizetype i = 0; i < unmatched.size(); ++i) {
            if (unmatched.at(i)->name != ref.name)
                continue;
            if (pick < 0)
                pick = i;
            if (stem(unmatched.at(i)->file) ==
                stem(ref.file)) { // two classes of one name: the file decides
                pick = i;
                break;
            }
        }
        const UmlDiagram *match = pick >= 0 ? unmatched.takeAt(pick) : nullptr;
        result.diagrams << evaluateDiagram(ref, match);
    }
    for (const UmlDiagram *d : std::as_const(unmatched))
        result.extra << *d;

    QList<EvaluationScore> totals;
    int tp = 0, fp = 0, fn = 0;
    for (const DiagramEvaluation &d : std::as_const(result.diagrams)) {
        totals << d.total;
        tp += d.total.tp;
        fp += d.total.fp;
        fn += d.total.fn;
    }
    for (const QString &kind : umlKinds(level)) {
        QList<EvaluationScore> scores;
        int ktp = 0, kfp = 0, kfn = 0;
        for (const DiagramEvaluation &d : std::as_const(result.diagrams)) {
            const EvaluationScore &s = d.kind(kind)->score;
            scores << s;
            ktp += s.tp;
            kfp += s.fp;
            kfn += s.fn;
        }
        KindSummary summary;
        summary.kind = kind;
        summary.macro = EvaluationScore::mean(scores);
        summary.micro = result.diagrams.isEmpty() ? EvaluationScore{}
                                                  : EvaluationScore::fromCounts(ktp, kfp, kfn);
        result.kinds << summary;
    }
    result.macro = EvaluationScore::mean(totals);
    // With no reference diagram there is nothing to score: 0, like a missing diagram.
    result.micro =
        result.diagrams.isEmpty() ? EvaluationScore{} : EvaluationScore::fromCounts(tp, fp, fn);
    return result;
}

Evaluation Evaluator::evaluate(const QList<UmlDiagram> &reference,
                               const QList<UmlDiagram> &recovered, const QList<UmlLevel> &levels)
{
    Evaluation e;
    for (UmlLevel level : levels)
        e.levels << evaluateLevel(reference, recovered, level);
    return e;
}

} // namespace rosarch
