#include "app/commands/evaluationreport.h"

#include <QCoreApplication>
#include <QTextStream>

#include <tuple>

namespace rosarch {

namespace {

/// Gives the command's strings a translation context lupdate can see.
struct EvalText
{
    Q_DECLARE_TR_FUNCTIONS(rosarch::EvalCommand)
};

QString ratio(double v)
{
    return QString::number(v, 'f', 3);
}

QString counts(const EvaluationScore &s)
{
    return QStringLiteral("%1 %2 %3").arg(s.tp, 5).arg(s.fp, 5).arg(s.fn, 5);
}

QString ratios(const EvaluationScore &s)
{
    return QStringLiteral("%1 %2 %3").arg(ratio(s.precision), ratio(s.recall), ratio(s.f1));
}

QString levelTitle(UmlLevel level)
{
    return level == UmlLevel::Acd ? EvalText::tr("ACD (AtomicClassifierDiagrams)")
                                  : EvalText::tr("CCD (ComposedClassifierDiagrams)");
}

} // namespace

QString EvaluationReport::levelText(const LevelEvaluation &l, int recovered)
{
    QString text;
    QTextStream out(&text);
    int missing = 0;
    for (const DiagramEvaluation &d : l.diagrams)
        missing += d.missing ? 1 : 0;
    out << "== " << levelTitle(l.level) << " ==\n";
    out << EvalText::tr("%1 reference diagrams, %2 recovered: %3 matched, %4 missing, %5 extra\n")
               .arg(l.diagrams.size())
               .arg(recovered)
               .arg(l.diagrams.size() - missing)
               .arg(missing)
               .arg(l.extra.size());
    out << QStringLiteral("%1 %2 %3 %4   %5   %6\n")
               .arg(EvalText::tr("kind"), -22)
               .arg(EvalText::tr("TP"), 5)
               .arg(EvalText::tr("FP"), 5)
               .arg(EvalText::tr("FN"), 5)
               .arg(EvalText::tr("micro P/R/F1"), -17)
               .arg(EvalText::tr("macro P/R/F1"));
    for (const KindSummary &k : l.kinds)
        out << QStringLiteral("%1 %2   %3   %4\n")
                   .arg(umlKindLabel(k.kind), -22)
                   .arg(counts(k.micro), ratios(k.micro), ratios(k.macro));
    out << QStringLiteral("%1 %2   %3   %4\n")
               .arg(EvalText::tr("all kinds"), -22)
               .arg(counts(l.micro), ratios(l.micro), ratios(l.macro));
    out << EvalText::tr("Per diagram (P R F1 over all kinds):\n");
    for (const DiagramEvaluation &d : l.diagrams)
        out << QStringLiteral("  %1 %2   %3%4\n")
                   .arg(d.name, -20)
                   .arg(counts(d.total), ratios(d.total),
                        d.missing ? EvalText::tr("   missing: no recovered diagram") : QString());
    for (const UmlDiagram &d : l.extra)
        out << EvalText::tr("  extra recovered diagram, not scored: %1 (%2)\n").arg(d.name, d.file);
    bool header = false;
    for (const DiagramEvaluation &d : l.diagrams) {
        bool named = false;
        for (const KindEvaluation &k : d.kinds) {
            for (const auto &[list, tag, file] :
                 {std::tuple{&k.falsePositives, "FP", d.recoveredFile},
                  std::tuple{&k.falseNegatives, "FN", d.referenceFile}}) {
                for (const UmlElement &e : *list) {
                    if (!header)
                        out << EvalText::tr("Differences (FP: recovered but not in the reference; "
                                            "FN: in the reference "
                                            "but not recovered):\n");
                    if (!named)
                        out << "  " << d.name << ":\n";
                    header = named = true;
                    out << QStringLiteral("    %1 %2: %3  (%4:%5)\n")
                               .arg(QLatin1String(tag), umlKindLabel(k.kind), e.value, file)
                               .arg(e.line);
                }
            }
        }
    }
    out << '\n';
    out.flush();
    return text;
}

} // namespace rosarch
