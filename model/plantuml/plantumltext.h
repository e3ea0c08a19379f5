#pragma once

#include <QString>

namespace rosarch::PlantUmlText {

/// Text that is safe inside a PlantUML label: no double quotes, no line breaks.
inline QString label(QString text)
{
    text.replace(QLatin1Char('"'), QLatin1Char('\''));
    text.replace(QLatin1Char('\n'), QLatin1Char(' '));
    return text;
}

/// An identifier made of ASCII letters, digits and '_' (every other character becomes '_'):
/// a PlantUML alias or a Mermaid node id.
inline QString safeId(const QString &text)
{
    QString s;
    for (const QChar c : text)
        s += c.isLetterOrNumber() && c.unicode() < 128 ? c : QLatin1Char('_');
    return s;
}

/// "pkg/msg/T" -> "pkg::msg::T", the blueprint's notation ("?" when unknown).
inline QString type(const QString &canonical)
{
    return canonical.isEmpty() ? QStringLiteral("?")
                               : QString(canonical).replace(QLatin1Char('/'), QLatin1String("::"));
}

} // namespace rosarch::PlantUmlText
