// LaunchExecutor's includes: where an include's evaluated path points (a workspace launch file,
// a package outside the workspace, or nothing).
#include "launchexecutor.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

namespace rosarch {

IncludeTarget LaunchExecutor::resolveInclude(const QString &rawPath, const QString &fromFile) const
{
    const QString key = rawPath + QChar(0) + fromFile;
    const auto known = m_includeTargets.constFind(key);
    if (known != m_includeTargets.cend())
        return *known;
    const IncludeTarget t = findInclude(rawPath, fromFile);
    m_includeTargets.insert(key, t);
    return t;
}

IncludeTarget LaunchExecutor::findInclude(const QString &rawPath, const QString &fromFile) const
{
    IncludeTarget t;
    QString path = rawPath.trimmed();
    static const QRegularExpression share(
        QStringLiteral("^\\$\\(find-pkg-(?:share|prefix) ([^)\\s]+)\\)/*(.*)$"));
    const auto m = share.match(path);
    auto existing = [&](const QString &rel) {
        const auto it = m_isFile.constFind(rel);
        if (it != m_isFile.cend())
            return *it;
        const QString absolute = m_workspace.absolutePath(rel);
        const bool file = !absolute.isEmpty() && QFileInfo(absolute).isFile();
        m_isFile.insert(rel, file);
        return file;
    };
    if (m.hasMatch()) {
        t.package = m.captured(1);
        QString rest = m.captured(2);
        if (rest.startsWith(QLatin1String("share/") + t.package + QLatin1Char('/')))
            rest = rest.mid(7 + t.package.size()); // find-pkg-prefix + share/<pkg>/...
        t.shareRelative = rest;
        if (!m_packagePaths.contains(t.package)) {
            t.external = true;
            return t;
        }
        const QString pkgPath = m_packagePaths.value(t.package);
        const QString direct = pkgPath.isEmpty() ? rest : pkgPath + QLatin1Char('/') + rest;
        if (existing(direct)) {
            t.file = direct;
            return t;
        }
        // Installed share layouts rarely mirror the source tree: match on the longest suffix.
        const QString name = QFileInfo(rest).fileName();
        int best = -1;
        for (const SourceFile &f : m_workspace.files) {
            if (f.package != t.package || QFileInfo(f.path).fileName() != name)
                continue;
            int score = 0;
            const QStringList a = f.path.split(QLatin1Char('/'));
            const QStringList b = rest.split(QLatin1Char('/'));
            while (score < a.size() && score < b.size() &&
                   a[a.size() - 1 - score] == b[b.size() - 1 - score])
                ++score;
            if (score > best) {
                best = score;
                t.file = f.path;
            }
        }
        return t;
    }
    // Relative to the including file (ThisLaunchFileDir, or a bare relative path).
    if (!path.startsWith(QLatin1Char('/'))) {
        const QString rel = QFileInfo(path).isRelative() && !existing(path)
                                ? launchFileDir(fromFile) + QLatin1Char('/') + path
                                : path;
        const QString clean = QDir::cleanPath(rel);
        if (existing(clean)) {
            t.file = clean;
            t.package = m_filePackages.value(clean);
            return t;
        }
    }
    return t;
}

} // namespace rosarch
