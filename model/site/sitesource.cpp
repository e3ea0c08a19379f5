#include "site/sitesource.h"

#include "diff/gitrevision.h"

#include <QDir>
#include <QUrl>

namespace rosarch {

namespace {

/// A path as a URL path: each segment percent-encoded, slashes kept.
QString encodedPath(const QString &path)
{
    QStringList parts = path.split(u'/');
    for (QString &part : parts)
        part = QString::fromLatin1(QUrl::toPercentEncoding(part));
    return parts.join(u'/');
}

QString git(const QString &folder, const QStringList &arguments, bool *ok)
{
    QByteArray output;
    *ok = GitRevision::run(folder, arguments, &output, nullptr, 10000);
    return *ok ? QString::fromUtf8(output).trimmed() : QString();
}

} // namespace

SiteSource SiteSource::relative(const QString &siteFolder, const QString &workspace)
{
    SiteSource s;
    QString prefix =
        QDir(QDir(siteFolder).absolutePath()).relativeFilePath(QDir(workspace).absolutePath());
    if (prefix == QLatin1String("."))
        prefix.clear();
    if (!prefix.isEmpty() && !prefix.endsWith(u'/'))
        prefix += u'/';
    s.m_prefix = prefix;
    return s;
}

SiteSource SiteSource::pattern(const QString &pattern, const QString &commit,
                               const QString &repositoryPrefix)
{
    SiteSource s;
    s.m_pattern = pattern;
    s.m_commit = commit;
    s.m_prefix = repositoryPrefix;
    return s;
}

bool SiteSource::needsCommit(const QString &pattern)
{
    return pattern.contains(QLatin1String("{commit}"));
}

QString SiteSource::url(const Evidence &evidence, int depth) const
{
    if (evidence.file.isEmpty())
        return {};
    const QString path = encodedPath(m_prefix + evidence.file);
    const int line = std::max(1, evidence.line);
    if (m_pattern.isEmpty())
        return QStringLiteral("../").repeated(depth) + path + QStringLiteral("#L%1").arg(line);
    QString url = m_pattern;
    url.replace(QLatin1String("{commit}"), m_commit);
    url.replace(QLatin1String("{path}"), path);
    url.replace(QLatin1String("{line}"), QString::number(line));
    return url;
}

bool SiteSource::gitInfo(const QString &workspace, QString *commit, QString *prefix)
{
    bool ok = false;
    const QString head = git(workspace, {QStringLiteral("rev-parse"), QStringLiteral("HEAD")}, &ok);
    if (!ok || head.isEmpty())
        return false;
    const QString inside =
        git(workspace, {QStringLiteral("rev-parse"), QStringLiteral("--show-prefix")}, &ok);
    if (!ok)
        return false;
    *commit = head;
    *prefix = inside;
    return true;
}

} // namespace rosarch
