#include "launch/xmlyaml/xmllaunchreader.h"
#include "launch/xmlyaml/frontendactionmapper.h"

#include <QHash>
#include <QXmlStreamReader>

#include <algorithm>

namespace rosarch {

namespace {

// Launch files nest a handful of levels; deeper elements are skipped so that mapping them can
// never exhaust the stack.
constexpr int kMaxDepth = 200;

/// Maps character offsets of the decoded text to 1-based lines and UTF-8 byte columns.
class Positions
{
public:
    explicit Positions(const QString &text) : m_bytes(text.size() + 1, 0)
    {
        m_lineStarts << 0;
        for (qsizetype i = 0; i < text.size(); ++i) {
            const char16_t c = text[i].unicode();
            m_bytes[i + 1] = m_bytes[i] + (c < 0x80                ? 1
                                           : c < 0x800             ? 2
                                           : QChar::isSurrogate(c) ? 2
                                                                   : 3);
            if (c == u'\n')
                m_lineStarts << i + 1;
        }
    }

    void at(qsizetype offset, int *line, int *column) const
    {
        offset = std::clamp<qsizetype>(offset, 0, m_bytes.size() - 1);
        const auto it = std::upper_bound(m_lineStarts.cbegin(), m_lineStarts.cend(), offset);
        const auto index = (it - m_lineStarts.cbegin()) - 1;
        *line = int(index) + 1;
        *column = int(m_bytes[offset] - m_bytes[m_lineStarts[index]]) + 1;
    }

    Evidence range(const QString &file, qsizetype begin, qsizetype end) const
    {
        Evidence e;
        e.file = file;
        at(begin, &e.line, &e.column);
        at(end, &e.endLine, &e.endColumn);
        return e;
    }

private:
    QList<int> m_bytes; // UTF-8 bytes before each character
    QList<qsizetype> m_lineStarts;
};

/// Where each attribute of a start tag is written, from its name to its closing quote
/// (QXmlStreamReader reports positions only per token).
QHash<QString, QPair<qsizetype, qsizetype>> attributeRanges(const QString &text, qsizetype begin,
                                                            qsizetype end)
{
    QHash<QString, QPair<qsizetype, qsizetype>> out;
    qsizetype i = begin + 1;
    auto isNameChar = [&](qsizetype k) {
        const QChar c = text[k];
        return !c.isSpace() && c != u'=' && c != u'/' && c != u'>';
    };
    while (i < end && isNameChar(i)) // the element name
        ++i;
    while (i < end) {
        while (i < end && text[i].isSpace())
            ++i;
        const qsizetype nameBegin = i;
        while (i < end && isNameChar(i))
            ++i;
        if (i == nameBegin)
            break;
        const QString name = text.mid(nameBegin, i - nameBegin);
        while (i < end && (text[i].isSpace() || text[i] == u'='))
            ++i;
        if (i >= end || (text[i] != u'"' && text[i] != u'\''))
            break;
        const qsizetype close = text.indexOf(text[i], i + 1);
        if (close < 0 || close >= end)
            break;
        i = close + 1;
        out.insert(name, {nameBegin, i});
    }
    return out;
}

} // namespace

bool XmlLaunchReader::isLaunchFile(const QByteArray &content)
{
    // Only the prolog and the root's start tag are read.
    QXmlStreamReader xml(content);
    while (!xml.atEnd()) {
        if (xml.readNext() == QXmlStreamReader::StartElement)
            return xml.name() == u"launch";
    }
    return false;
}

LaunchFileDescription XmlLaunchReader::read(const QByteArray &content, const QString &file)
{
    LaunchFileDescription d;
    d.file = file;
    d.format = LaunchFileDescription::Format::Xml;

    const QString text = QString::fromUtf8(content);
    const Positions positions(text);
    QXmlStreamReader xml(text);
    QList<FrontendEntity> open; // the elements being read, innermost last
    QList<FrontendEntity> entities;
    bool sawRoot = false;
    int skipped = 0; // depth inside an element that is nested too deeply
    auto close = [&](qsizetype endOffset) {
        FrontendEntity e = open.takeLast();
        positions.at(endOffset, &e.evidence.endLine, &e.evidence.endColumn);
        (open.isEmpty() ? entities : open.last().children) << std::move(e);
    };

    while (!xml.atEnd()) {
        const auto token = xml.readNext();
        if (token == QXmlStreamReader::StartElement) {
            const qsizetype tagEnd = xml.characterOffset();
            const qsizetype tagBegin = std::max<qsizetype>(0, text.lastIndexOf(u'<', tagEnd - 1));
            if (!sawRoot) {
                sawRoot = true;
                if (xml.name() != u"launch") {
                    Diagnostic diag;
                    diag.severity = Diagnostic::Severity::Warning;
                    diag.code = QStringLiteral("not-a-launch-file");
                    diag.message = QStringLiteral("The root element is <%1>, not <launch>.")
                                       .arg(xml.name().toString());
                    diag.evidence = positions.range(file, tagBegin, tagEnd);
                    d.diagnostics << diag;
                    return d;
                }
                continue;
            }
            if (skipped > 0 || open.size() >= kMaxDepth) {
                if (skipped++ == 0) {
                    Diagnostic diag;
                    diag.code = QStringLiteral("nesting-too-deep");
                    diag.message = QStringLiteral("Elements nested deeper than %1 levels are "
                                                  "skipped.")
                                       .arg(kMaxDepth);
                    diag.evidence = positions.range(file, tagBegin, tagEnd);
                    d.diagnostics << diag;
                }
                continue;
            }
            FrontendEntity e;
            e.type = xml.name().toString();
            e.evidence = positions.range(file, tagBegin, tagEnd);
            const auto ranges = attributeRanges(text, tagBegin, tagEnd);
            for (const QXmlStreamAttribute &a : xml.attributes()) {
                FrontendAttribute attribute;
                attribute.name = a.qualifiedName().toString();
                attribute.value = a.value().toString();
                const auto range = ranges.value(attribute.name, {tagBegin, tagEnd});
                attribute.evidence = positions.range(file, range.first, range.second);
                e.attributes << attribute;
            }
            open << e;
        } else if (token == QXmlStreamReader::EndElement) {
            if (skipped > 0)
                --skipped;
            else if (!open.isEmpty())
                close(xml.characterOffset());
        }
    }

    Diagnostic error;
    if (xml.hasError()) {
        // Keep what was read: the elements still open end where the error is.
        const qsizetype errorOffset = xml.characterOffset();
        while (!open.isEmpty())
            close(errorOffset);
        error.severity = Diagnostic::Severity::Error;
        error.code = QStringLiteral("malformed-xml");
        error.evidence.file = file;
        error.evidence.line = error.evidence.endLine = int(xml.lineNumber());
        error.evidence.column = error.evidence.endColumn = int(xml.columnNumber()) + 1;
        error.message = QStringLiteral("Malformed XML at line %1, column %2: %3.")
                            .arg(error.evidence.line)
                            .arg(error.evidence.column)
                            .arg(xml.errorString());
    }
    FrontendActionMapper mapper(&d.diagnostics);
    d.actions = mapper.map(entities);
    if (!error.code.isEmpty())
        d.diagnostics << error;
    return d;
}

} // namespace rosarch
