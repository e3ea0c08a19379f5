#include "compose/checkscope.h"

namespace rosarch {

CheckScope::CheckScope(const LaunchDependencies &launch) : m_externals(launch.externals)
{
    for (const LaunchArgument &a : launch.arguments)
        if (a.hasDefault && a.defaultValue.startsWith(QLatin1Char('/')) &&
            a.defaultValue.size() > 1)
            m_argumentDefaults[a.launchFile].insert(a.defaultValue);
    // `**` any segments, `*` within one, as parameter files match node names
    for (const ExpectedExternal &e : m_externals) {
        QString rx = QRegularExpression::escape(e.name);
        rx.replace(QLatin1String("\\*\\*"), QLatin1String(".*"))
            .replace(QLatin1String("\\*"), QLatin1String("[^/]*"));
        m_externalPatterns.append(QRegularExpression(QRegularExpression::anchoredPattern(rx)));
    }
    for (const Port &p : launch.viewedTopics) // relative: in whichever namespace
        m_viewed.insert(p.name.startsWith(u'/') ? p.name : QLatin1Char('/') + p.name);
}

void CheckScope::enterSystem(const QString &rootFile)
{
    m_rootArguments = m_argumentDefaults.value(rootFile);
}

bool CheckScope::isViewed(const QString &name) const
{
    for (qsizetype at = 0; at >= 0 && at < name.size(); at = name.indexOf(u'/', at + 1))
        if (m_viewed.contains(name.mid(at)))
            return true;
    return false;
}

bool CheckScope::isInterface(const QString &name, bool output) const
{
    return isExpectedExternal(name, output) || m_rootArguments.contains(name);
}

bool CheckScope::isExpectedExternal(const QString &name, bool output) const
{
    for (qsizetype i = 0; i < m_externals.size(); ++i)
        if (m_externals.at(i).output == output && m_externalPatterns.at(i).match(name).hasMatch())
            return true;
    return false;
}

QString CheckScope::externalOf(const QString &name, bool output)
{
    if (!name.startsWith(QLatin1Char('/')) || name.contains(QLatin1Char(' ')) ||
        name.contains(QLatin1Char('{')))
        return {};
    return (output ? QLatin1String("output ") : QLatin1String("input ")) + name;
}

bool CheckScope::isJudged(const LaunchDependencies &launch, const QString &rootFile)
{
    return launch.entryPoints.isEmpty() || launch.entryPoints.contains(rootFile);
}

QSet<QString> CheckScope::judgedInstances(const LaunchDependencies &launch)
{
    QSet<QString> in;
    for (const LaunchFileInstance &i : launch.instances) // roots first, then their includes
        if (i.parentId.isEmpty() ? isJudged(launch, i.file) : in.contains(i.parentId))
            in.insert(i.id);
    return in;
}

} // namespace rosarch
