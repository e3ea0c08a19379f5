#include "widgets/llmsettingsdialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QUrl>
#include <QVBoxLayout>

namespace rosarch {

LlmSettingsDialog::LlmSettingsDialog(QWidget *parent)
    : QDialog(parent), m_use(new QCheckBox(tr("Ask a language model for suggestions"), this)),
      m_endpoint(new QLineEdit(this)), m_model(new QLineEdit(this)),
      m_temperature(new QDoubleSpinBox(this)), m_connectTimeout(new QSpinBox(this)),
      m_requestTimeout(new QSpinBox(this)), m_key(new QLabel(this)), m_problem(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setWindowTitle(tr("LLM Settings"));

    auto *intro = new QLabel(
        tr("Without a model, rosarch still proposes descriptions and groupings from the code. "
           "Any OpenAI-compatible server works: OpenAI, Ollama, llama.cpp server, vLLM."),
        this);
    intro->setWordWrap(true);

    m_endpoint->setPlaceholderText(QStringLiteral("http://localhost:11434/v1"));
    m_endpoint->setToolTip(tr("The server's base URL; /v1/chat/completions is added"));
    m_model->setPlaceholderText(QStringLiteral("gpt-4o-mini"));
    m_temperature->setRange(0.0, 2.0);
    m_temperature->setSingleStep(0.1);
    m_temperature->setDecimals(1);
    m_temperature->setToolTip(tr("0 keeps replies as repeatable as the server allows"));
    m_connectTimeout->setRange(1, 600);
    m_connectTimeout->setSuffix(tr(" s"));
    m_requestTimeout->setRange(5, 3600);
    m_requestTimeout->setSuffix(tr(" s"));
    m_requestTimeout->setToolTip(tr("How long one prompt may take, streaming included"));
    m_key->setWordWrap(true);
    m_key->setText(apiKeyStatus());
    m_key->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_problem->setWordWrap(true);
    QPalette warning = m_problem->palette();
    warning.setColor(QPalette::WindowText, QColor(0xc0, 0x39, 0x2b));
    m_problem->setPalette(warning);

    auto *form = new QFormLayout;
    form->addRow(tr("&Endpoint:"), m_endpoint);
    form->addRow(tr("&Model:"), m_model);
    form->addRow(tr("&Temperature:"), m_temperature);
    form->addRow(tr("&Connect timeout:"), m_connectTimeout);
    form->addRow(tr("&Request timeout:"), m_requestTimeout);
    form->addRow(tr("API key:"), m_key);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addSpacing(4);
    layout->addWidget(m_use);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addStretch(1);
    layout->addSpacing(6);
    layout->addWidget(m_buttons);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_use, &QCheckBox::toggled, this, &LlmSettingsDialog::validate);
    connect(m_endpoint, &QLineEdit::textChanged, this, &LlmSettingsDialog::validate);
    connect(m_model, &QLineEdit::textChanged, this, &LlmSettingsDialog::validate);
    setMinimumWidth(480);
    validate();
    // The wrapped texts make the plain size hint too tall; size for the width shown.
    layout->activate();
    const int width = 540;
    resize(width,
           layout->hasHeightForWidth() ? layout->totalHeightForWidth(width) : sizeHint().height());
}

QString LlmSettingsDialog::apiKeyStatus()
{
    // Say where the key comes from, never what it is.
    if (!qEnvironmentVariableIsEmpty("ROSARCH_LLM_API_KEY"))
        return tr("Set in ROSARCH_LLM_API_KEY (not shown, never stored).");
    if (!qEnvironmentVariableIsEmpty("OPENAI_API_KEY"))
        return tr("Set in OPENAI_API_KEY (not shown, never stored).");
    return tr("Not set. Local servers need none; for a hosted API set ROSARCH_LLM_API_KEY or "
              "OPENAI_API_KEY in the environment before starting rosarch.");
}

void LlmSettingsDialog::setSettings(const LlmSettings &settings, bool useLlm)
{
    m_settings = settings;
    m_use->setChecked(useLlm);
    m_endpoint->setText(settings.endpoint);
    m_model->setText(settings.model);
    m_temperature->setValue(settings.temperature);
    m_connectTimeout->setValue(qMax(1, settings.connectTimeoutMs / 1000));
    m_requestTimeout->setValue(qMax(5, settings.requestTimeoutMs / 1000));
    validate();
}

LlmSettings LlmSettingsDialog::settings() const
{
    LlmSettings s = m_settings;
    s.endpoint = m_endpoint->text().trimmed();
    s.model = m_model->text().trimmed();
    s.temperature = m_temperature->value();
    s.connectTimeoutMs = m_connectTimeout->value() * 1000;
    s.requestTimeoutMs = m_requestTimeout->value() * 1000;
    return s;
}

bool LlmSettingsDialog::useLlm() const
{
    return m_use->isChecked();
}

void LlmSettingsDialog::validate()
{
    const bool use = m_use->isChecked();
    for (QWidget *w : std::initializer_list<QWidget *>{m_endpoint, m_model, m_temperature,
                                                       m_connectTimeout, m_requestTimeout})
        w->setEnabled(use);
    QString problem;
    if (use) {
        const QUrl url(m_endpoint->text().trimmed(), QUrl::StrictMode);
        if (m_endpoint->text().trimmed().isEmpty())
            problem = tr("Enter the server's URL, e.g. http://localhost:11434/v1 for Ollama.");
        else if (!url.isValid() ||
                 (url.scheme() != QLatin1String("http") &&
                  url.scheme() != QLatin1String("https")) ||
                 url.host().isEmpty())
            problem = tr("The endpoint must be an http:// or https:// URL.");
        else if (m_model->text().trimmed().isEmpty())
            problem = tr("Enter the model name the server knows, e.g. llama3.1 or gpt-4o-mini.");
    }
    m_problem->setText(problem);
    m_problem->setVisible(!problem.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

} // namespace rosarch
