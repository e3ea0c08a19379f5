#include "core/visibletext.h"

namespace rosarch {

bool isHiddenControl(char16_t c, Newlines newlines)
{
    if (newlines == Newlines::Keep && (c == u'\n' || c == u'\t'))
        return false;
    return c < 0x20 || (c >= 0x7f && c <= 0x9f) || c == 0x2028 || c == 0x2029;
}

QString visibleText(const QString &text, Newlines newlines)
{
    qsizetype first = 0;
    while (first < text.size() && !isHiddenControl(text.at(first).unicode(), newlines))
        ++first;
    if (first == text.size())
        return text; // the usual case: nothing to escape, no copy
    QString out = text.left(first);
    out.reserve(text.size() + 16);
    for (qsizetype i = first; i < text.size(); ++i) {
        const char16_t c = text.at(i).unicode();
        if (!isHiddenControl(c, newlines))
            out += QChar(c);
        else if (c <= 0xff)
            out += QStringLiteral("\\x%1").arg(uint(c), 2, 16, QLatin1Char('0'));
        else
            out += QStringLiteral("\\u%1").arg(uint(c), 4, 16, QLatin1Char('0'));
    }
    return out;
}

QByteArray visibleJson(const std::string &json)
{
    QByteArray out;
    out.reserve(qsizetype(json.size()) + 2);
    static const char digits[] = "0123456789abcdef";
    for (size_t i = 0; i < json.size(); ++i) {
        const auto b = static_cast<unsigned char>(json[i]);
        const auto next = i + 1 < json.size() ? static_cast<unsigned char>(json[i + 1]) : 0;
        if (b == 0xc2 && next >= 0x80 && next <= 0x9f) { // U+0080..U+009F
            out += "\\u00";
            out += digits[next >> 4];
            out += digits[next & 15];
            ++i;
        } else if (b == 0xe2 && next == 0x80 && i + 2 < json.size() &&
                   (static_cast<unsigned char>(json[i + 2]) == 0xa8 ||
                    static_cast<unsigned char>(json[i + 2]) == 0xa9)) {
            out += static_cast<unsigned char>(json[i + 2]) == 0xa8 ? "\\u2028" : "\\u2029";
            i += 2;
        } else if (b == 0x7f) {
            out += "\\u007f";
        } else {
            out += char(b);
        }
    }
    return out;
}

QString fileStemOf(QString name)
{
    for (QChar &c : name)
        if (c == QLatin1Char('/') || isHiddenControl(c.unicode()))
            c = QLatin1Char('_');
    return name;
}

} // namespace rosarch
