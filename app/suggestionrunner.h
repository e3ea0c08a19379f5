#pragma once

#include "jobs/jobrunner.h"
#include "pipeline/recovery.h"
#include "suggestions/llm/llmsettings.h"
#include "suggestions/suggestionreport.h"

#include <QObject>

namespace rosarch {

/// Runs SuggestionEngine off the UI thread on a JobRunner and reports back on the UI thread.
/// A new run cancels the previous one, whose late result is dropped by generation number. LLM
/// failures come back in the report's errors, with the deterministic suggestions.
class SuggestionRunner : public QObject
{
    Q_OBJECT
public:
    /// What one run uses.
    struct Options
    {
        LlmSettings llm; ///< used when `useLlm` and an endpoint is set
        bool useLlm = false;
        bool deterministic = true;
        QString promptDir; ///< "" = $ROSARCH_PROMPT_DIR, else the embedded prompts
    };

    explicit SuggestionRunner(QObject *parent = nullptr);

    /// Starts the suggestion tasks on `recovery` (copied), superseding any run in progress.
    void run(const QString &workspaceRoot, const Recovery &recovery, const Options &options);
    /// Asks the current run to stop after the prompt in flight; suggestionsCanceled follows.
    void cancel();
    bool isRunning() const { return m_jobs.isRunning(); }
    /// Incremented by every run; results of older generations are dropped.
    int generation() const { return m_jobs.generation(); }

Q_SIGNALS:
    /// A run started; `llm` says whether prompts will be sent.
    void suggestionsStarted(bool llm);
    /// Streaming progress of the prompt in flight: characters received so far.
    void suggestionsProgressed(const QString &prompt, qint64 chars);
    /// One step of the run, for the log ("describe_nodes [arc_1,…]: 1234 characters, …").
    void stepLogged(const QString &line);
    /// The run finished; failures of the LLM are in `report.errors`.
    void suggestionsFinished(const rosarch::SuggestionReport &report);
    /// The run was canceled; `partial` holds what was checked before it stopped.
    void suggestionsCanceled(const rosarch::SuggestionReport &partial);

private:
    JobRunner m_jobs; ///< its destructor cancels and waits for the worker
};

} // namespace rosarch
