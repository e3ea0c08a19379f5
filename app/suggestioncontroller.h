#pragma once

#include "app/suggestionrunner.h"
#include "core/evidence.h"
#include "suggestions/suggestionreport.h"

#include <QObject>

#include <functional>

namespace rosarch {

class Document;
class SuggestionPanel;

/// Wires the Suggestions panel: runs the suggestion tasks on the Document's model (off the UI
/// thread), puts the result into the Document, turns accept / reject into undoable commands,
/// forwards previews to the other views and writes what happened to the log.
class SuggestionController : public QObject
{
    Q_OBJECT
public:
    /// How the other views show what a suggestion is about; any of them may be empty.
    struct Previews
    {
        std::function<void(const Evidence &)> showEvidence;
        std::function<void(const QString &arcId)> showNodeClass;
        std::function<void(const QStringList &instanceIds)> showInstances;
    };
    /// Edits the LLM settings; returns false when the person canceled. The default opens
    /// LlmSettingsDialog; tests replace it.
    using SettingsEditor = std::function<bool(LlmSettings *settings, bool *useLlm)>;

    SuggestionController(Document *document, SuggestionPanel *panel, QObject *parent = nullptr);

    void setPreviews(Previews previews);
    void setSettingsEditor(SettingsEditor editor);
    SuggestionRunner *runner() const { return m_runner; }

    /// Runs the suggestion tasks on the current model with the stored LLM settings.
    void run();
    void cancel();
    /// Opens the LLM settings and stores what the person chose (never an API key).
    void editSettings();
    /// The options the next run uses (AppSettings' LLM settings).
    SuggestionRunner::Options runOptions() const;
    /// One line for the log about a finished run ("Suggestions: 9 new (8 descriptions, …").
    static QString summary(const SuggestionReport &report, int alreadyDecided);

Q_SIGNALS:
    /// A line for the log.
    void logged(const QString &line);
    /// A line for the status bar (0: until replaced).
    void statusMessage(const QString &text, int timeout);
    /// A run started or ended.
    void runningChanged(bool running);

private:
    void onStarted(bool llm);
    void onProgressed(const QString &prompt, qint64 chars);
    void onFinished(const SuggestionReport &report);
    void onCanceled(const SuggestionReport &partial);
    void updateLlmDescription();

    Document *m_document;
    SuggestionPanel *m_panel;
    SuggestionRunner *m_runner;
    Previews m_previews;
    SettingsEditor m_editor;
};

} // namespace rosarch
