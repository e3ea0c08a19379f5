#include "suggestionrunner.h"
#include "suggestionengine.h"

#include <QMutex>
#include <QPromise>
#include <QStringList>
#include <QtConcurrent>

#include <exception>
#include <limits>

namespace rosarch {

/// State shared between one worker and the UI thread: the engine's cancel flag, the latest
/// progress and the log lines not yet delivered.
struct SuggestionRunner::Shared
{
    std::atomic_bool cancel{false};
    QMutex mutex;
    QString prompt;
    qint64 chars = 0;
    QStringList lines;
    int tick = 0;
};

SuggestionRunner::SuggestionRunner(QObject *parent) : QObject(parent) {}

SuggestionRunner::~SuggestionRunner()
{
    for (const auto &[watcher, shared] : std::as_const(m_running)) {
        watcher->disconnect(this);
        shared->cancel = true;
        QFuture<SuggestionReport> future = watcher->future();
        future.waitForFinished();
    }
}

void SuggestionRunner::run(const QString &workspaceRoot, const Recovery &recovery,
                           const Options &options)
{
    cancel();
    const int generation = ++m_generation;
    auto shared = std::make_shared<Shared>();
    auto *watcher = new Watcher(this);
    m_current = watcher;
    m_currentShared = shared;
    m_running.append({watcher, shared});
    connect(watcher, &Watcher::finished, this,
            [this, watcher, shared, generation] { onFinished(watcher, shared, generation); });
    connect(watcher, &Watcher::progressValueChanged, this,
            [this, shared, generation] { onProgress(shared, generation); });

    SuggestionEngine::Options engine;
    engine.llm = options.llm;
    if (!options.useLlm)
        engine.llm.endpoint.clear(); // SuggestionEngine asks the LLM whenever one is configured
    engine.deterministic = options.deterministic;
    engine.promptDir = options.promptDir;
    const bool llm = engine.llm.isConfigured();

    watcher->setFuture(QtConcurrent::run(
        [workspaceRoot, recovery, engine, shared](QPromise<SuggestionReport> &promise) mutable {
            // Progress and log lines go through `shared`; the future carries only a tick,
            // because QFuture progress values must grow.
            auto notify = [&promise, shared] {
                int tick = 0;
                {
                    QMutexLocker lock(&shared->mutex);
                    tick = ++shared->tick;
                }
                promise.setProgressValue(tick);
            };
            engine.cancel = &shared->cancel;
            engine.logged = [shared, notify](const QString &line) {
                {
                    QMutexLocker lock(&shared->mutex);
                    shared->lines << line;
                }
                notify();
            };
            engine.progressed = [shared, notify](const QString &prompt, qint64 chars) {
                {
                    QMutexLocker lock(&shared->mutex);
                    shared->prompt = prompt;
                    shared->chars = chars;
                }
                notify();
            };
            promise.setProgressRange(0, std::numeric_limits<int>::max());
            SuggestionReport report;
            try {
                report = SuggestionEngine(workspaceRoot, recovery, engine).run();
            } catch (const std::exception &e) {
                // A bug in the engine must not take the window down; report it in words.
                report.errors << SuggestionRunner::tr("The suggestion run stopped with an "
                                                      "internal error: %1")
                                     .arg(QString::fromLocal8Bit(e.what()));
            }
            promise.addResult(std::move(report));
        }));
    Q_EMIT suggestionsStarted(llm);
}

void SuggestionRunner::cancel()
{
    if (m_currentShared)
        m_currentShared->cancel = true;
}

void SuggestionRunner::onProgress(const std::shared_ptr<Shared> &shared, int generation)
{
    if (generation != m_generation)
        return;
    QStringList lines;
    QString prompt;
    qint64 chars = 0;
    {
        QMutexLocker lock(&shared->mutex);
        lines.swap(shared->lines);
        prompt = shared->prompt;
        chars = shared->chars;
    }
    for (const QString &line : std::as_const(lines))
        Q_EMIT stepLogged(line);
    if (!prompt.isEmpty())
        Q_EMIT suggestionsProgressed(prompt, chars);
}

void SuggestionRunner::onFinished(Watcher *watcher, const std::shared_ptr<Shared> &shared,
                                  int generation)
{
    m_running.removeIf([watcher](const auto &entry) { return entry.first == watcher; });
    watcher->deleteLater();
    if (generation != m_generation)
        return;                     // superseded by a later run
    onProgress(shared, generation); // deliver log lines that arrived after the last tick
    m_current = nullptr;
    m_currentShared.reset();
    const QFuture<SuggestionReport> future = watcher->future();
    const SuggestionReport report = future.resultCount() > 0 ? future.result() : SuggestionReport();
    if (shared->cancel)
        Q_EMIT suggestionsCanceled(report);
    else
        Q_EMIT suggestionsFinished(report);
}

} // namespace rosarch
