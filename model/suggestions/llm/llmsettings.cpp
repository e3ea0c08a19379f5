#include "suggestions/llm/llmsettings.h"

#include <QtGlobal>

namespace rosarch {

QString LlmSettings::completionsUrl() const
{
    QString url = endpoint.trimmed();
    while (url.endsWith(QLatin1Char('/')))
        url.chop(1);
    if (url.isEmpty())
        return {};
    if (url.endsWith(QLatin1String("/chat/completions")))
        return url;
    if (url.endsWith(QLatin1String("/v1")))
        return url + QStringLiteral("/chat/completions");
    return url + QStringLiteral("/v1/chat/completions");
}

LlmSettings LlmSettings::fromEnvironment()
{
    LlmSettings s;
    s.endpoint = qEnvironmentVariable("ROSARCH_LLM_ENDPOINT");
    const QString model = qEnvironmentVariable("ROSARCH_LLM_MODEL");
    if (!model.isEmpty())
        s.model = model;
    return s;
}

QString LlmSettings::apiKey()
{
    const QString key = qEnvironmentVariable("ROSARCH_LLM_API_KEY");
    return key.isEmpty() ? qEnvironmentVariable("OPENAI_API_KEY") : key;
}

QString LlmSettings::masked(const QString &text)
{
    const QString key = apiKey();
    // Very short keys would mask ordinary words; they are not real keys anyway.
    if (key.size() < 4)
        return text;
    QString out = text;
    out.replace(key, QStringLiteral("***"));
    return out;
}

QString LlmSettings::describe() const
{
    return QStringLiteral("endpoint=%1 model=%2 temperature=%3 timeout=%4s key=%5")
        .arg(completionsUrl().isEmpty() ? QStringLiteral("(none)") : completionsUrl(), model)
        .arg(temperature)
        .arg(requestTimeoutMs / 1000.0)
        .arg(apiKey().isEmpty() ? QStringLiteral("not set") : QStringLiteral("set (hidden)"));
}

} // namespace rosarch
