#include "workspace/sourcereader.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace rosarch {

SourceReader::SourceReader(QString root, qint64 maxBytes)
    : m_root(std::move(root)), m_maxBytes(maxBytes)
{
}

bool SourceReader::read(const QString &relativePath, QByteArray *content,
                        QList<Diagnostic> *diagnostics) const
{
    auto fail = [&](const QString &code, const QString &message) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.code = code;
        d.message = message;
        d.evidence.file = relativePath;
        diagnostics->append(d);
        return false;
    };
    QFile file(QDir(m_root).filePath(relativePath));
    const QFileInfo info(file);
    if (info.exists() && !info.isFile())
        return fail(QStringLiteral("unreadable-file"),
                    QStringLiteral("Skipped: %1 is not a regular file.").arg(relativePath));
    if (info.size() > m_maxBytes)
        return fail(QStringLiteral("file-too-large"),
                    QStringLiteral("Skipped: %1 is %2 MB, larger than the %3 MB analysis limit.")
                        .arg(relativePath)
                        .arg(double(info.size()) / (1024 * 1024), 0, 'f', 1)
                        .arg(double(m_maxBytes) / (1024 * 1024), 0, 'f', 1));
    if (!file.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("unreadable-file"),
                    QStringLiteral("Skipped: %1 cannot be read (%2).")
                        .arg(relativePath, file.errorString()));
    // Room for what the file holds, not for the cap: a thousand small files read ahead must not
    // hold a thousand caps. A file that grows while it is read is read on, up to the cap.
    content->resize(qMin(info.size(), m_maxBytes) + 1);
    qint64 got = 0;
    for (;;) {
        if (got == content->size()) {
            if (got > m_maxBytes)
                break;
            content->resize(qMin(got * 2 + 64 * 1024, m_maxBytes + 1));
        }
        const qint64 n = file.read(content->data() + got, content->size() - got);
        if (n <= 0)
            break;
        got += n;
    }
    content->resize(got);
    if (content->size() > m_maxBytes)
        return fail(
            QStringLiteral("file-too-large"),
            QStringLiteral("Skipped: %1 is larger than the analysis limit.").arg(relativePath));
    if (content->contains('\0'))
        return fail(QStringLiteral("binary-file"),
                    QStringLiteral("Skipped: %1 looks like a binary file (it contains NUL bytes).")
                        .arg(relativePath));
    if (!content->isValidUtf8()) {
        // Read it anyway: every byte is a Latin-1 character, so nothing is lost but the exact
        // spelling of the non-ASCII ones (ROS 2 itself expects UTF-8).
        *content = QString::fromLatin1(*content).toUtf8();
        Diagnostic d;
        d.severity = Diagnostic::Severity::Info;
        d.code = QStringLiteral("not-utf8");
        d.message = QStringLiteral("%1 is not valid UTF-8; it was read as Latin-1 (ISO 8859-1), "
                                   "so non-ASCII characters may be shown wrongly.")
                        .arg(relativePath);
        d.evidence.file = relativePath;
        diagnostics->append(d);
    }
    return true;
}

} // namespace rosarch
