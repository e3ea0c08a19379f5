#include "app/suggestioncontroller.h"
#include "app/appsettings.h"
#include "document/document.h"
#include "widgets/llmsettingsdialog.h"
#include "widgets/suggestionmodel.h"
#include "widgets/suggestionpanel.h"

#include <QUrl>

namespace rosarch {

SuggestionController::SuggestionController(Document *document, SuggestionPanel *panel,
                                           QObject *parent)
    : QObject(parent), m_document(document), m_panel(panel), m_runner(new SuggestionRunner(this))
{
    m_editor = [this](LlmSettings *settings, bool *useLlm) {
        LlmSettingsDialog dialog(m_panel->window());
        dialog.setSettings(*settings, *useLlm);
        if (dialog.exec() != QDialog::Accepted)
            return false;
        *settings = dialog.settings();
        *useLlm = dialog.useLlm();
        return true;
    };

    connect(m_panel, &SuggestionPanel::runRequested, this, &SuggestionController::run);
    connect(m_panel, &SuggestionPanel::cancelRequested, this, &SuggestionController::cancel);
    connect(m_panel, &SuggestionPanel::settingsRequested, this,
            &SuggestionController::editSettings);
    connect(m_panel, &SuggestionPanel::acceptRequested, m_document->session(),
            &ProjectSession::acceptSuggestion);
    connect(m_panel, &SuggestionPanel::rejectRequested, m_document->session(),
            &ProjectSession::rejectSuggestion);
    connect(m_panel, &SuggestionPanel::acceptAllRequested, this, [this](Suggestion::Kind kind) {
        const int n = m_document->session()->acceptAllSuggestions(kind);
        if (n > 0)
            Q_EMIT logged(tr("Suggestions: accepted %1 (%2) as one step (Undo takes it back)")
                              .arg(n)
                              .arg(SuggestionModel::kindPlural(kind)));
    });
    connect(m_panel, &SuggestionPanel::evidenceActivated, this, [this](const Evidence &e) {
        if (m_previews.showEvidence)
            m_previews.showEvidence(e);
    });
    connect(m_panel, &SuggestionPanel::nodeClassPreviewRequested, this, [this](const QString &id) {
        if (m_previews.showNodeClass)
            m_previews.showNodeClass(id);
    });
    connect(m_panel, &SuggestionPanel::instancesPreviewRequested, this,
            [this](const QStringList &ids) {
                if (m_previews.showInstances)
                    m_previews.showInstances(ids);
            });

    connect(m_runner, &SuggestionRunner::suggestionsStarted, this,
            &SuggestionController::onStarted);
    connect(m_runner, &SuggestionRunner::suggestionsProgressed, this,
            &SuggestionController::onProgressed);
    connect(m_runner, &SuggestionRunner::stepLogged, this,
            [this](const QString &line) { Q_EMIT logged(tr("Suggestions: %1").arg(line)); });
    connect(m_runner, &SuggestionRunner::suggestionsFinished, this,
            &SuggestionController::onFinished);
    connect(m_runner, &SuggestionRunner::suggestionsCanceled, this,
            &SuggestionController::onCanceled);
    connect(m_document->session(), &ProjectSession::saveFailed, this,
            [this](const QString &message) {
                Q_EMIT logged(tr("Suggestions: the decisions could not be saved: %1").arg(message));
            });
    updateLlmDescription();
}

void SuggestionController::setPreviews(Previews previews)
{
    m_previews = std::move(previews);
}

void SuggestionController::setSettingsEditor(SettingsEditor editor)
{
    m_editor = std::move(editor);
}

SuggestionRunner::Options SuggestionController::runOptions() const
{
    const AppSettings settings;
    SuggestionRunner::Options options;
    options.llm = settings.llmSettings();
    options.useLlm = settings.useLlm() && options.llm.isConfigured();
    return options;
}

void SuggestionController::run()
{
    if (m_document->workspaceRoot().isEmpty() || m_document->atomicNodes().nodes.isEmpty()) {
        Q_EMIT logged(tr("Suggestions need a recovered model: open a workspace and run the "
                         "stages first."));
        Q_EMIT statusMessage(tr("Nothing to suggest on yet"), 5000);
        return;
    }
    const Recovery recovery{m_document->atomicNodes(), m_document->launchDependencies(),
                            m_document->architecture()};
    const SuggestionRunner::Options options = runOptions();
    if (AppSettings().useLlm() && !options.useLlm)
        Q_EMIT logged(tr("Suggestions: the LLM is turned on but has no endpoint; only the "
                         "deterministic suggestions are made (LLM Settings…)."));
    m_runner->run(m_document->workspaceRoot(), recovery, options);
}

void SuggestionController::cancel()
{
    m_runner->cancel();
}

void SuggestionController::editSettings()
{
    AppSettings settings;
    LlmSettings llm = settings.llmSettings();
    bool use = settings.useLlm();
    if (!m_editor || !m_editor(&llm, &use))
        return;
    settings.setLlmSettings(llm);
    settings.setUseLlm(use);
    updateLlmDescription();
    // describe() shows the key only as set / not set.
    Q_EMIT logged(use ? tr("LLM settings: %1").arg(llm.describe())
                      : tr("LLM settings: the LLM is off; suggestions come from the code only"));
}

void SuggestionController::updateLlmDescription()
{
    const SuggestionRunner::Options options = runOptions();
    if (!options.useLlm) {
        m_panel->setLlmDescription(tr("LLM off"));
        return;
    }
    const QString host = QUrl(options.llm.completionsUrl()).host();
    m_panel->setLlmDescription(tr("LLM: %1 at %2").arg(options.llm.model, host));
}

void SuggestionController::onStarted(bool llm)
{
    m_panel->setRunning(true);
    m_panel->setProgressText(llm ? tr("Asking the LLM…") : tr("Reading the code…"));
    Q_EMIT logged(llm ? tr("Suggestions started (deterministic, then the LLM)")
                      : tr("Suggestions started (deterministic; the LLM is off)"));
    Q_EMIT statusMessage(tr("Looking for suggestions…"), 0);
    Q_EMIT runningChanged(true);
}

void SuggestionController::onProgressed(const QString &prompt, qint64 chars)
{
    m_panel->setProgressText(tr("%1: %L2 characters received").arg(prompt).arg(chars));
}

QString SuggestionController::summary(const SuggestionReport &report, int alreadyDecided)
{
    QMap<Suggestion::Kind, int> byKind;
    int fresh = 0;
    for (const Suggestion &s : report.suggestions)
        if (s.status == Suggestion::Status::Pending) {
            ++byKind[s.kind];
            ++fresh;
        }
    QStringList kinds;
    // Spelled out rather than %n: without a loaded translation %n leaves "(s)" in the text.
    if (int n = byKind.value(Suggestion::Kind::NodeDescription))
        kinds << (n == 1 ? tr("1 description") : tr("%1 descriptions").arg(n));
    if (int n = byKind.value(Suggestion::Kind::SubsystemGrouping))
        kinds << (n == 1 ? tr("1 grouping") : tr("%1 groupings").arg(n));
    if (int n = byKind.value(Suggestion::Kind::NameResolution))
        kinds << (n == 1 ? tr("1 name") : tr("%1 names").arg(n));
    QString line = tr("Suggestions: %1 new").arg(fresh);
    if (!kinds.isEmpty())
        line += QStringLiteral(" (%1)").arg(kinds.join(QStringLiteral(", ")));
    if (alreadyDecided > 0)
        line += tr(", %1 already decided").arg(alreadyDecided);
    if (report.discardedTotal() > 0) {
        QStringList reasons;
        for (auto it = report.discarded.cbegin(); it != report.discarded.cend(); ++it)
            reasons << QStringLiteral("%1 %2").arg(it.key()).arg(it.value());
        line += tr(", %1 discarded: %2")
                    .arg(report.discardedTotal())
                    .arg(reasons.join(QStringLiteral(", ")));
    }
    return line;
}

void SuggestionController::onFinished(const SuggestionReport &report)
{
    const int decided = m_document->session()->setSuggestions(report);
    m_panel->setRunning(false);
    const QString line = summary(m_document->session()->suggestionReport(), decided);
    Q_EMIT logged(line);
    for (const QString &error : report.errors)
        Q_EMIT logged(tr("Suggestions: the LLM failed: %1 The suggestions from the code are "
                         "shown; check LLM Settings… and run again.")
                          .arg(LlmSettings::masked(error)));
    if (report.errors.isEmpty()) {
        m_panel->setProgressText(report.llmUsed ? tr("Done: code and %1").arg(report.llmModel)
                                                : tr("Done: from the code"));
        Q_EMIT statusMessage(line, 8000);
    } else {
        m_panel->setProgressText(tr("The LLM failed; see the log"));
        Q_EMIT statusMessage(tr("Suggestions: the LLM failed (see the log); the suggestions from "
                                "the code are shown"),
                             8000);
    }
    Q_EMIT runningChanged(false);
}

void SuggestionController::onCanceled(const SuggestionReport &partial)
{
    const int decided = m_document->session()->setSuggestions(partial);
    m_panel->setRunning(false);
    m_panel->setProgressText(tr("Canceled"));
    Q_EMIT logged(tr("Suggestions canceled; %1")
                      .arg(summary(m_document->session()->suggestionReport(), decided)));
    Q_EMIT statusMessage(tr("Suggestions canceled"), 5000);
    Q_EMIT runningChanged(false);
}

} // namespace rosarch
