#pragma once

#include <QByteArray>
#include <QString>

#include <string>

namespace rosarch {

/// Text from a workspace (file names, names, values, messages) made safe for a terminal, a log
/// line or an XML report: every control character (C0 and C1, DEL, and the Unicode line and
/// paragraph separators) becomes a visible escape, "\x1b" or "\u2028". A crafted file name then
/// can neither move the cursor, clear the screen or set a terminal's title, nor split one
/// `file:line: severity: message` line into two.
enum class Newlines
{
    Escape, ///< one line: "\n" and "\t" are escaped too
    Keep,   ///< a text of several lines: "\n" and "\t" stay
};
QString visibleText(const QString &text, Newlines newlines = Newlines::Escape);

/// True when `c` (a UTF-16 code unit) is one visibleText() escapes with `newlines`.
bool isHiddenControl(char16_t c, Newlines newlines = Newlines::Escape);

/// JSON text (UTF-8, as a JSON library writes it) with the control characters that JSON lets
/// stand raw in strings, the C1 controls and U+2028/U+2029, written as \u escapes: the same
/// value for a JSON reader, and no terminal sequence for whoever prints the file. (C0 controls
/// are escaped by every JSON writer already; DEL is escaped here too.)
QByteArray visibleJson(const std::string &json);

/// `name` as a file name's stem: "/" and every control character become "_", so that a
/// crafted launch file or class name makes neither a folder nor a terminal sequence of an
/// artifact's name.
QString fileStemOf(QString name);

} // namespace rosarch
