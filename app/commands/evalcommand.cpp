#include "app/commands/evalcommand.h"
#include "app/commands/commandline.h"
#include "app/commands/evaluationreport.h"
#include "app/commands/terminalstream.h"
#include "evaluation/evaluationjson.h"
#include "evaluation/evaluator.h"
#include "plantuml/umlmodel.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

namespace rosarch {

namespace {

/// Gives the command's strings a translation context lupdate can see.
struct EvalText
{
    Q_DECLARE_TR_FUNCTIONS(rosarch::EvalCommand)
};

void printLevel(QTextStream &out, const LevelEvaluation &l, int recovered)
{
    out << EvaluationReport::levelText(l, recovered);
}

void printMessages(QTextStream &err, const UmlModel &model)
{
    for (const QString &e : model.errors)
        err << EvalText::tr("error: %1\n").arg(e);
    for (const UmlDiagram &d : model.diagrams) {
        for (const QString &n : d.notes)
            err << d.file << ": " << EvalText::tr("note: ") << n << '\n';
        for (const QString &w : d.warnings)
            err << d.file << ": " << EvalText::tr("warning: ") << w << '\n';
    }
}

} // namespace

int runEval(const QStringList &arguments)
{
    TerminalStream out(stdout);
    TerminalStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        EvalText::tr("Score a recovered PlantUML model against a reference model."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("eval"), QString());
    const QCommandLineOption referenceOption(
        QStringLiteral("reference"),
        EvalText::tr(
            "The reference model: a .puml file or a folder of them (searched recursively)."),
        QStringLiteral("dir|file"));
    const QCommandLineOption recoveredOption(
        QStringLiteral("recovered"),
        EvalText::tr("The recovered model: a .puml file or a folder of them."),
        QStringLiteral("dir|file"));
    const QCommandLineOption levelOption(
        QStringLiteral("level"),
        EvalText::tr("Evaluate only ACDs or only CCDs (default: every level present)."),
        QStringLiteral("acd|ccd"));
    const QCommandLineOption jsonOption(QStringLiteral("json"),
                                        EvalText::tr("Print the result as JSON."));
    parser.addOption(referenceOption);
    parser.addOption(recoveredOption);
    parser.addOption(levelOption);
    parser.addOption(jsonOption);
    const QString usage =
        EvalText::tr("Usage: rosarch eval --reference <dir|file> --recovered <dir|file> "
                     "[--level acd|ccd] [--json]\n");
    if (const int done = CommandLine::parseOrFinish(parser, arguments, usage); done >= 0)
        return done;
    if (!parser.isSet(referenceOption) || !parser.isSet(recoveredOption) ||
        parser.positionalArguments().size() != 1) {
        err << EvalText::tr("eval needs --reference and --recovered, and no other arguments.\n\n")
            << usage;
        return CommandLine::UsageError;
    }
    QList<UmlLevel> levels;
    if (parser.isSet(levelOption)) {
        const QString l = parser.value(levelOption).toLower();
        if (l != QLatin1String("acd") && l != QLatin1String("ccd")) {
            err << EvalText::tr("--level expects acd or ccd, got '%1'.\n")
                       .arg(parser.value(levelOption));
            return CommandLine::UsageError;
        }
        levels << (l == QLatin1String("acd") ? UmlLevel::Acd : UmlLevel::Ccd);
    }
    UmlModel reference, recovered;
    QString error;
    if (!UmlModel::load(parser.value(referenceOption), &reference, &error) ||
        !UmlModel::load(parser.value(recoveredOption), &recovered, &error)) {
        err << EvalText::tr("eval: %1\n").arg(error);
        return CommandLine::UsageError;
    }
    if (levels.isEmpty())
        for (UmlLevel l : {UmlLevel::Acd, UmlLevel::Ccd})
            if (reference.hasLevel(l) || recovered.hasLevel(l))
                levels << l;
    const Evaluation evaluation =
        Evaluator::evaluate(reference.diagrams, recovered.diagrams, levels);
    const bool json = parser.isSet(jsonOption);
    if (json) {
        out << QString::fromUtf8(EvaluationJson::write(evaluation, reference, recovered));
    } else {
        printMessages(err, reference);
        printMessages(err, recovered);
        if (levels.isEmpty())
            out << EvalText::tr("Nothing to evaluate: no ACD or CCD found in either input.\n");
        for (const LevelEvaluation &l : evaluation.levels)
            printLevel(out, l, int(recovered.ofLevel(l.level).size()));
    }
    const QList<UmlDiagram> bad = reference.unparseable() + recovered.unparseable();
    if (!bad.isEmpty() || !reference.errors.isEmpty() || !recovered.errors.isEmpty()) {
        for (const UmlDiagram &d : bad)
            err << EvalText::tr("eval: %1 is neither an ACD nor a CCD\n").arg(d.file);
        return CommandLine::AnalysisErrors;
    }
    return CommandLine::Ok;
}

} // namespace rosarch
