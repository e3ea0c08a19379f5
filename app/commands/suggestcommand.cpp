#include "app/commands/suggestcommand.h"
#include "app/commands/commandline.h"
#include "app/commands/terminalstream.h"
#include "pipeline/recovery.h"
#include "suggestions/suggestionengine.h"
#include "suggestions/suggestionsjson.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTextStream>

namespace rosarch {

int runSuggest(const QStringList &arguments)
{
    TerminalStream out(stdout);
    TerminalStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "rosarch::SuggestCommand", "Recover a ROS 2 workspace and propose checked suggestions "
                                   "(node descriptions, subsystem groupings, unresolved names)."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("suggest"), QString());
    parser.addPositionalArgument(
        QStringLiteral("workspace"),
        QCoreApplication::translate("rosarch::SuggestCommand", "The workspace folder to analyse."));
    const QCommandLineOption outOption(
        QStringList{QStringLiteral("o"), QStringLiteral("out")},
        QCoreApplication::translate("rosarch::SuggestCommand", "Folder for suggestions.json."),
        QStringLiteral("dir"));
    const QCommandLineOption endpointOption(
        QStringLiteral("llm-endpoint"),
        QCoreApplication::translate(
            "rosarch::SuggestCommand",
            "OpenAI-compatible endpoint (with or without /v1); default $ROSARCH_LLM_ENDPOINT. "
            "The API key is read from $ROSARCH_LLM_API_KEY or $OPENAI_API_KEY."),
        QStringLiteral("url"));
    const QCommandLineOption modelOption(
        QStringLiteral("llm-model"),
        QCoreApplication::translate("rosarch::SuggestCommand",
                                    "Model name; default $ROSARCH_LLM_MODEL."),
        QStringLiteral("name"));
    const QCommandLineOption timeoutOption(
        QStringLiteral("llm-timeout"),
        QCoreApplication::translate("rosarch::SuggestCommand",
                                    "Request timeout in seconds (default 120)."),
        QStringLiteral("s"));
    const QCommandLineOption promptOption(
        QStringLiteral("prompt-dir"),
        QCoreApplication::translate(
            "rosarch::SuggestCommand",
            "Folder whose prompt files override the built-in ones; default $ROSARCH_PROMPT_DIR."),
        QStringLiteral("dir"));
    const QCommandLineOption quietOption(
        QStringList{QStringLiteral("q"), QStringLiteral("quiet")},
        QCoreApplication::translate("rosarch::SuggestCommand", "Print only errors."));
    for (const QCommandLineOption &o :
         {outOption, endpointOption, modelOption, timeoutOption, promptOption, quietOption})
        parser.addOption(o);
    if (const int done = CommandLine::parseOrFinish(parser, arguments); done >= 0)
        return done;
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 2 || !parser.isSet(outOption)) {
        err << QCoreApplication::translate("rosarch::SuggestCommand",
                                           "suggest needs a workspace folder and --out <dir>.\n");
        return CommandLine::UsageError;
    }
    const QString &workspace = positional.at(1);
    if (!QFileInfo(workspace).isDir()) {
        err << QCoreApplication::translate("rosarch::SuggestCommand", "Not a folder: %1\n")
                   .arg(workspace);
        return CommandLine::UsageError;
    }

    SuggestionEngine::Options options;
    options.llm = LlmSettings::fromEnvironment();
    if (parser.isSet(endpointOption))
        options.llm.endpoint = parser.value(endpointOption);
    if (parser.isSet(modelOption))
        options.llm.model = parser.value(modelOption);
    if (parser.isSet(timeoutOption)) {
        bool ok = false;
        const double seconds = parser.value(timeoutOption).toDouble(&ok);
        if (!ok || seconds <= 0) {
            err << QCoreApplication::translate(
                       "rosarch::SuggestCommand",
                       "--llm-timeout expects a positive number of seconds, got '%1'.\n")
                       .arg(parser.value(timeoutOption));
            return CommandLine::UsageError;
        }
        options.llm.requestTimeoutMs = int(seconds * 1000);
        options.llm.connectTimeoutMs =
            qMin(options.llm.connectTimeoutMs, options.llm.requestTimeoutMs);
    }
    options.promptDir = parser.value(promptOption);
    const bool quiet = parser.isSet(quietOption);
    if (!quiet)
        options.logged = [&out](const QString &line) {
            out << line << '\n';
            out.flush();
        };

    const Recovery recovery = recoverWorkspace(workspace);
    if (!quiet && options.llm.isConfigured())
        out << QCoreApplication::translate("rosarch::SuggestCommand", "LLM: %1\n")
                   .arg(options.llm.describe());
    const SuggestionReport report = SuggestionEngine(workspace, recovery, options).run();

    int exitCode = CommandLine::Ok;
    for (const QString &e : report.errors) {
        err << QCoreApplication::translate("rosarch::SuggestCommand", "LLM error: %1\n").arg(e);
        exitCode = CommandLine::AnalysisErrors;
    }
    const QString outDir = parser.value(outOption);
    const QString path = QDir(outDir).filePath(QStringLiteral("suggestions.json"));
    QFile file(path);
    if (!QDir().mkpath(outDir) || !file.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
        file.write(SuggestionsJson::write(report)) < 0) {
        err << QCoreApplication::translate("rosarch::SuggestCommand", "Cannot create %1\n")
                   .arg(path);
        return CommandLine::AnalysisErrors;
    }
    file.close();
    if (!quiet) {
        QMap<QString, int> kinds;
        for (const Suggestion &s : report.suggestions)
            ++kinds[Suggestion::kindName(s.kind)];
        QStringList kindText;
        for (auto it = kinds.cbegin(); it != kinds.cend(); ++it)
            kindText << QStringLiteral("%1 %2").arg(it.value()).arg(it.key());
        QStringList reasons;
        for (auto it = report.discarded.cbegin(); it != report.discarded.cend(); ++it)
            reasons << QStringLiteral("%1 %2").arg(it.value()).arg(it.key());
        qint64 tokens = 0;
        for (const SuggestionReport::PromptUsage &p : report.prompts)
            tokens += p.estimatedTokens;
        out << QCoreApplication::translate("rosarch::SuggestCommand",
                                           "%1 suggestions (%2); %3 discarded (%4); %5 prompts, "
                                           "~%6 tokens (characters / 4).\n"
                                           "Wrote %7\n")
                   .arg(report.suggestions.size())
                   .arg(kindText.join(QStringLiteral(", ")))
                   .arg(report.discardedTotal())
                   .arg(reasons.join(QStringLiteral(", ")))
                   .arg(report.prompts.size())
                   .arg(tokens)
                   .arg(QDir(path).absolutePath());
    }
    out.flush();
    return exitCode;
}

} // namespace rosarch
