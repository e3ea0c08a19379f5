#pragma once

#include "suggestions/llm/llmrequest.h"

#include <QJsonObject>
#include <QMap>
#include <QString>
#include <QStringList>

namespace rosarch {

/// A prompt contract read from a Markdown file in prompts/: sections "## Role", "## Goal",
/// "## Backstory", "## Examples", "## Input", "## Task", "## Expected output" (whose ```json
/// block is the schema the reply must fit), with {{placeholders}} filled by code.
class PromptTemplate
{
public:
    /// The sections a task prompt must have, lower-case.
    static QStringList requiredSections();
    /// Loads `name`.md from `overrideDir`, else $ROSARCH_PROMPT_DIR, else the embedded
    /// resources (:/prompts); a file in the user folder wins over the embedded one.
    static PromptTemplate load(const QString &name, const QString &overrideDir = {});

    bool isValid() const { return m_error.isEmpty(); }
    QString error() const { return m_error; }
    QString name() const { return m_name; }
    /// The file it was read from (":/prompts/x.md" for the embedded copy).
    QString path() const { return m_path; }
    /// A section's text by lower-case title ("" when absent).
    QString section(const QString &title) const { return m_sections.value(title); }
    /// Required sections that are missing (empty for a complete task prompt).
    QStringList missingSections() const;
    /// The JSON Schema in the expected-output section (empty when there is none).
    QJsonObject schema() const { return m_schema; }
    /// Every {{placeholder}} the template uses, sorted.
    QStringList placeholders() const;

    /// `text` with {{key}} replaced by values[key] in one pass, so values are never expanded
    /// again; values cannot close a data block. Unknown keys are listed in `missing`.
    static QString fill(const QString &text, const QMap<QString, QString> &values,
                        QStringList *missing = nullptr);
    /// The conversation for this prompt: role, goal and backstory as the system message;
    /// examples, input, task and expected output as the user message.
    LlmRequest request(const QMap<QString, QString> &values, QStringList *missing = nullptr) const;

private:
    QString m_name;
    QString m_path;
    QString m_error;
    QMap<QString, QString> m_sections;
    QStringList m_order; ///< section titles as written
    QJsonObject m_schema;
};

} // namespace rosarch
