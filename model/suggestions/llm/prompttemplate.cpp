#include "suggestions/llm/prompttemplate.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QRegularExpression>

#include <mutex>

// Resources of a static library must be registered explicitly; outside any namespace.
static void initPromptResources()
{
    static std::once_flag once;
    std::call_once(once, [] { Q_INIT_RESOURCE(prompts); });
}

namespace rosarch {

namespace {

const QRegularExpression &placeholderPattern()
{
    static const QRegularExpression re(QStringLiteral("\\{\\{([A-Za-z0-9_]+)\\}\\}"));
    return re;
}

QString titleCase(const QString &title)
{
    return title.isEmpty() ? title : title.at(0).toUpper() + title.mid(1);
}

} // namespace

QStringList PromptTemplate::requiredSections()
{
    return {QStringLiteral("role"),           QStringLiteral("goal"),  QStringLiteral("backstory"),
            QStringLiteral("examples"),       QStringLiteral("input"), QStringLiteral("task"),
            QStringLiteral("expected output")};
}

PromptTemplate PromptTemplate::load(const QString &name, const QString &overrideDir)
{
    initPromptResources();
    PromptTemplate t;
    t.m_name = name;
    const QString fileName = name + QStringLiteral(".md");
    QStringList candidates;
    for (const QString &dir : {overrideDir, qEnvironmentVariable("ROSARCH_PROMPT_DIR")})
        if (!dir.isEmpty())
            candidates << QDir(dir).filePath(fileName);
    candidates << QStringLiteral(":/prompts/") + fileName;
    for (const QString &path : std::as_const(candidates)) {
        QFile f(path);
        if (!f.exists() || !f.open(QIODevice::ReadOnly))
            continue;
        t.m_path = path;
        const QString text = QString::fromUtf8(f.readAll());
        QString current;
        QStringList lines;
        auto flush = [&] {
            if (!current.isEmpty()) {
                t.m_sections.insert(current, lines.join(QLatin1Char('\n')).trimmed());
                t.m_order << current;
            }
            lines.clear();
        };
        for (const QString &line : text.split(QLatin1Char('\n'))) {
            if (line.startsWith(QLatin1String("## "))) {
                flush();
                current = line.mid(3).trimmed().toLower();
            } else if (!current.isEmpty()) {
                lines << line;
            }
        }
        flush();
        const QString expected = t.section(QStringLiteral("expected output"));
        static const QRegularExpression block(QStringLiteral("```json\\s*\\n([\\s\\S]*?)```"));
        const QRegularExpressionMatch m = block.match(expected);
        if (m.hasMatch()) {
            QJsonParseError error;
            const QJsonDocument doc = QJsonDocument::fromJson(m.captured(1).toUtf8(), &error);
            if (!doc.isObject())
                t.m_error =
                    QStringLiteral(
                        "%1: the schema under \"Expected output\" is not a JSON object (%2)")
                        .arg(path, error.errorString());
            t.m_schema = doc.object();
        }
        return t;
    }
    t.m_error = QStringLiteral("No prompt template named %1").arg(fileName);
    return t;
}

QStringList PromptTemplate::missingSections() const
{
    QStringList missing;
    for (const QString &s : requiredSections())
        if (!m_sections.contains(s))
            missing << s;
    return missing;
}

QStringList PromptTemplate::placeholders() const
{
    QStringList out;
    for (const QString &text : m_sections) {
        auto it = placeholderPattern().globalMatch(text);
        while (it.hasNext())
            out << it.next().captured(1);
    }
    out.removeDuplicates();
    out.sort();
    return out;
}

QString PromptTemplate::fill(const QString &text, const QMap<QString, QString> &values,
                             QStringList *missing)
{
    QString out;
    qsizetype last = 0;
    auto it = placeholderPattern().globalMatch(text);
    while (it.hasNext()) {
        const QRegularExpressionMatch m = it.next();
        out += QStringView(text).mid(last, m.capturedStart() - last);
        const QString key = m.captured(1);
        if (values.contains(key)) {
            QString value = values.value(key);
            // Repository text must not be able to end its data block early.
            value.replace(QLatin1String("<<<DATA"), QLatin1String("<<< DATA"));
            value.replace(QLatin1String("DATA>>>"), QLatin1String("DATA >>>"));
            out += value;
        } else {
            out += m.captured(0);
            if (missing && !missing->contains(key))
                missing->append(key);
        }
        last = m.capturedEnd();
    }
    out += QStringView(text).mid(last);
    return out;
}

LlmRequest PromptTemplate::request(const QMap<QString, QString> &values, QStringList *missing) const
{
    auto part = [&](const QStringList &titles) {
        QStringList blocks;
        for (const QString &title : titles)
            if (m_sections.contains(title))
                blocks << QStringLiteral("## %1\n%2")
                              .arg(titleCase(title),
                                   fill(m_sections.value(title), values, missing));
        return blocks.join(QStringLiteral("\n\n"));
    };
    LlmRequest r;
    r.name = m_name;
    r.schema = m_schema;
    r.messages.append(
        {QStringLiteral("system"),
         part({QStringLiteral("role"), QStringLiteral("goal"), QStringLiteral("backstory")})});
    r.messages.append({QStringLiteral("user"),
                       part({QStringLiteral("examples"), QStringLiteral("input"),
                             QStringLiteral("task"), QStringLiteral("expected output")})});
    return r;
}

} // namespace rosarch
