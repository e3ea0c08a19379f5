#include "suggestions/suggestionchecker.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

namespace rosarch {

namespace {

QString normalized(const QString &text)
{
    return text.simplified();
}

} // namespace

SuggestionChecker::SuggestionChecker(const QString &workspaceRoot, const Recovery &recovery)
    : m_root(QFileInfo(workspaceRoot).canonicalFilePath()), m_recovery(recovery)
{
    for (const SuggestionItem &item : SuggestionItem::collect(recovery))
        m_items.insert(item.id, item);
}

bool SuggestionChecker::fileLines(const QString &relative, QStringList *lines) const
{
    if (relative.isEmpty() || QDir::isAbsolutePath(relative) || m_root.isEmpty())
        return false;
    const QString canonical = QFileInfo(QDir(m_root).filePath(relative)).canonicalFilePath();
    // Cited files must lie inside the workspace: no "..", no symlinks out of it.
    if (canonical.isEmpty() || !canonical.startsWith(m_root + QLatin1Char('/')) ||
        !QFileInfo(canonical).isFile())
        return false;
    QMutexLocker lock(&m_mutex);
    auto it = m_files.find(canonical);
    if (it == m_files.end()) {
        QFile f(canonical);
        if (!f.open(QIODevice::ReadOnly))
            return false;
        QString text = QString::fromUtf8(f.readAll());
        text.replace(QLatin1String("\r\n"), QLatin1String("\n"));
        QStringList split = text.split(QLatin1Char('\n'));
        if (text.endsWith(QLatin1Char('\n')))
            split.removeLast();
        it = m_files.insert(canonical, split);
    }
    *lines = *it;
    return true;
}

bool SuggestionChecker::checkCitation(const Suggestion::Citation &c, QString *reason,
                                      QString *detail) const
{
    const Evidence &e = c.evidence;
    QStringList lines;
    if (!fileLines(e.file, &lines)) {
        *reason = QStringLiteral("evidence-file-missing");
        *detail = QStringLiteral("cited file '%1' is not a file in the workspace").arg(e.file);
        return false;
    }
    const int last = e.endLine > 0 ? e.endLine : e.line;
    if (e.line < 1 || last < e.line || last > lines.size()) {
        *reason = QStringLiteral("evidence-line-out-of-range");
        *detail = QStringLiteral("cited lines %1-%2 are not inside %3 (%4 lines)")
                      .arg(e.line)
                      .arg(last)
                      .arg(e.file)
                      .arg(lines.size());
        return false;
    }
    if (last - e.line > 200) {
        *reason = QStringLiteral("evidence-range-too-wide");
        *detail = QStringLiteral("cited lines %1-%2 of %3 span more than 200 lines")
                      .arg(e.line)
                      .arg(last)
                      .arg(e.file);
        return false;
    }
    const QString quote = normalized(c.quote);
    const QString cited =
        normalized(lines.mid(e.line - 1, last - e.line + 1).join(QLatin1Char(' ')));
    if (quote.isEmpty() || !cited.contains(quote)) {
        *reason = QStringLiteral("evidence-does-not-say");
        *detail = QStringLiteral("%1:%2-%3 does not contain \"%4\"")
                      .arg(e.file)
                      .arg(e.line)
                      .arg(last)
                      .arg(c.quote.left(80));
        return false;
    }
    return true;
}

QStringList SuggestionChecker::subtreeNodes(const QString &rootId) const
{
    QSet<QString> launchIds{rootId};
    // Instances are listed roots first, each followed by its includes, so parents come first.
    for (const LaunchFileInstance &lf : m_recovery.launch.instances)
        if (launchIds.contains(lf.parentId))
            launchIds.insert(lf.id);
    QStringList nodes;
    for (const NodeInstance &n : m_recovery.launch.nodes)
        if (launchIds.contains(n.launchFileId))
            nodes << n.id;
    return nodes;
}

QSet<QString> SuggestionChecker::subtreeFiles(const QString &rootId) const
{
    QSet<QString> launchIds{rootId};
    QSet<QString> files;
    for (const LaunchFileInstance &lf : m_recovery.launch.instances)
        if (lf.id == rootId || launchIds.contains(lf.parentId)) {
            launchIds.insert(lf.id);
            files.insert(lf.file);
            files.insert(lf.evidence.file); // the include lines live in the parent
        }
    files.remove(QString());
    return files;
}

bool SuggestionChecker::check(const Suggestion &s, QString *reason, QString *detail) const
{
    auto fail = [&](const char *code, const QString &what) {
        *reason = QString::fromLatin1(code);
        *detail = what;
        return false;
    };
    if (s.evidence.isEmpty())
        return fail("no-evidence", QStringLiteral("%1 for %2 cites no evidence")
                                       .arg(Suggestion::kindName(s.kind), s.targetId));
    for (const Suggestion::Citation &c : s.evidence)
        if (!checkCitation(c, reason, detail))
            return false;
    const QString value = s.value.trimmed();
    if (value.isEmpty() || value.contains(QLatin1Char('\n')))
        return fail(
            "invalid-proposal",
            QStringLiteral("the proposed value for %1 is empty or not one line").arg(s.targetId));
    auto citesOneOf = [&](const QSet<QString> &files) {
        for (const Suggestion::Citation &c : s.evidence)
            if (files.contains(QDir::cleanPath(c.evidence.file)))
                return true;
        return false;
    };

    switch (s.kind) {
    case Suggestion::Kind::NodeDescription: {
        const AtomicNode *node = m_recovery.nodes.node(s.targetId);
        if (!node)
            return fail("unknown-target",
                        QStringLiteral("no atomic node with id '%1'").arg(s.targetId));
        if (value.size() > 300)
            return fail("invalid-proposal",
                        QStringLiteral("the description of %1 is longer than 300 characters")
                            .arg(s.targetId));
        QSet<QString> files(node->sourceFiles.begin(), node->sourceFiles.end());
        files.unite(QSet<QString>(node->headerFiles.begin(), node->headerFiles.end()));
        files.insert(node->evidence.file);
        if (!citesOneOf(files))
            return fail("evidence-unrelated", QStringLiteral("no cited file belongs to %1 (%2)")
                                                  .arg(s.targetId, node->className));
        return true;
    }
    case Suggestion::Kind::SubsystemGrouping: {
        const LaunchFileInstance *root = m_recovery.launch.instance(s.targetId);
        if (!root || !root->parentId.isEmpty())
            return fail("unknown-target",
                        QStringLiteral("no root launch file with id '%1'").arg(s.targetId));
        static const QRegularExpression name(QStringLiteral("^[A-Za-z][A-Za-z0-9_ -]{0,39}$"));
        if (!name.match(value).hasMatch())
            return fail("invalid-proposal",
                        QStringLiteral("'%1' is not a usable group name").arg(value.left(60)));
        const QStringList members = subtreeNodes(s.targetId);
        QSet<QString> unique;
        for (const QString &m : s.memberIds) {
            if (!members.contains(m))
                return fail("unknown-member",
                            QStringLiteral("'%1' is not a node instance of %2").arg(m, s.targetId));
            unique.insert(m);
        }
        if (unique.size() < 2)
            return fail(
                "invalid-proposal",
                QStringLiteral("group '%1' has fewer than two distinct members").arg(value));
        if (!citesOneOf(subtreeFiles(s.targetId)))
            return fail(
                "evidence-unrelated",
                QStringLiteral("group '%1' cites no launch file of %2").arg(value, s.targetId));
        return true;
    }
    case Suggestion::Kind::NameResolution: {
        const auto it = m_items.constFind(s.targetId);
        if (it == m_items.constEnd())
            return fail("unknown-target",
                        QStringLiteral("no unresolved item with id '%1'").arg(s.targetId));
        if (it->kind == QLatin1String("port-name")) {
            static const QRegularExpression rosName(
                QStringLiteral("^(~/)?/?[A-Za-z_][A-Za-z0-9_]*(/[A-Za-z_][A-Za-z0-9_]*)*$"));
            if (!rosName.match(value).hasMatch())
                return fail("invalid-proposal",
                            QStringLiteral("'%1' is not a valid ROS name").arg(value.left(60)));
        } else if (it->kind == QLatin1String("condition") && value != QLatin1String("true") &&
                   value != QLatin1String("false")) {
            return fail(
                "invalid-proposal",
                QStringLiteral("a condition takes true or false, not '%1'").arg(value.left(60)));
        }
        if (!citesOneOf({QDir::cleanPath(it->evidence.file)}))
            return fail("evidence-unrelated", QStringLiteral("no citation in %1, where %2 is")
                                                  .arg(it->evidence.file, s.targetId));
        return true;
    }
    }
    return true;
}

} // namespace rosarch
