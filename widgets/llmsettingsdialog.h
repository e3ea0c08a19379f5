#pragma once

#include "suggestions/llm/llmsettings.h"

#include <QDialog>

class QCheckBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace rosarch {

/// LLM Settings…: whether to ask a language model, its OpenAI-compatible endpoint, model,
/// temperature and timeouts. Shows whether an API key is in the environment, never the key;
/// the key cannot be entered here, so it is never stored.
class LlmSettingsDialog : public QDialog
{
    Q_OBJECT
public:
    explicit LlmSettingsDialog(QWidget *parent = nullptr);

    void setSettings(const LlmSettings &settings, bool useLlm);
    /// The values as edited (the fields the dialog does not show keep setSettings' values).
    LlmSettings settings() const;
    bool useLlm() const;

    /// The line about the API key, for the environment of this process.
    static QString apiKeyStatus();

    QCheckBox *useCheck() const { return m_use; }
    QLineEdit *endpointEdit() const { return m_endpoint; }
    QLineEdit *modelEdit() const { return m_model; }
    QLabel *keyLabel() const { return m_key; }
    QDialogButtonBox *buttons() const { return m_buttons; }

private:
    void validate();

    LlmSettings m_settings;
    QCheckBox *m_use;
    QLineEdit *m_endpoint;
    QLineEdit *m_model;
    QDoubleSpinBox *m_temperature;
    QSpinBox *m_connectTimeout;
    QSpinBox *m_requestTimeout;
    QLabel *m_key;
    QLabel *m_problem;
    QDialogButtonBox *m_buttons;
};

} // namespace rosarch
