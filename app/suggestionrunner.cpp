#include "app/suggestionrunner.h"
#include "suggestions/suggestionengine.h"

namespace rosarch {

SuggestionRunner::SuggestionRunner(QObject *parent) : QObject(parent)
{
    connect(&m_jobs, &JobRunner::logged, this, &SuggestionRunner::stepLogged);
    connect(&m_jobs, &JobRunner::progressed, this,
            [this](qint64 chars, qint64, const QString &prompt) {
                Q_EMIT suggestionsProgressed(prompt, chars);
            });
    connect(&m_jobs, &JobRunner::failed, this, [this](const QString &message) {
        SuggestionReport report;
        report.errors << tr("The suggestion run stopped with an internal error: %1").arg(message);
        Q_EMIT suggestionsFinished(report);
    });
}

void SuggestionRunner::run(const QString &workspaceRoot, const Recovery &recovery,
                           const Options &options)
{
    SuggestionEngine::Options engine;
    engine.llm = options.llm;
    if (!options.useLlm)
        engine.llm.endpoint.clear(); // SuggestionEngine asks the LLM whenever one is configured
    engine.deterministic = options.deterministic;
    engine.promptDir = options.promptDir;
    const bool llm = engine.llm.isConfigured();

    m_jobs.start<SuggestionReport>(
        [workspaceRoot, recovery, engine](const JobControl &control) mutable {
            engine.cancel = control.cancelFlag();
            engine.logged = [&control](const QString &line) { control.log(line); };
            engine.progressed = [&control](const QString &prompt, qint64 chars) {
                control.progress(chars, 0, prompt);
            };
            return SuggestionEngine(workspaceRoot, recovery, engine).run();
        },
        [this](SuggestionReport report, bool canceled) {
            if (canceled)
                Q_EMIT suggestionsCanceled(report);
            else
                Q_EMIT suggestionsFinished(report);
        });
    Q_EMIT suggestionsStarted(llm);
}

void SuggestionRunner::cancel()
{
    m_jobs.cancel();
}

} // namespace rosarch
