#include "rootchoice.h"

#include <QHash>
#include <QSet>

#include <algorithm>
#include <tuple>

namespace rosarch {

namespace {

const QStringList &entryWords()
{
    static const QStringList words{QStringLiteral("bringup"), QStringLiteral("robot"),
                                   QStringLiteral("system")};
    return words;
}

/// 0 = the stem is an entry word, 1 = it contains one, 2 = neither.
int nameRank(const QString &stem)
{
    const QString lower = stem.toLower();
    if (entryWords().contains(lower))
        return 0;
    for (const QString &w : entryWords())
        if (lower.contains(w))
            return 1;
    return 2;
}

/// Test launch files start a system only to check it; a person rarely wants them first.
bool isTestFile(const QString &file)
{
    for (const QString &segment : file.toLower().split(QLatin1Char('/'), Qt::SkipEmptyParts))
        if (segment == QLatin1String("test") || segment == QLatin1String("tests") ||
            segment.startsWith(QLatin1String("test_")) || segment.contains(QLatin1String("_test")))
            return true;
    return false;
}

} // namespace

QList<LaunchRoot> RootChoice::roots(const Architecture &architecture,
                                    const LaunchDependencies &launch)
{
    QHash<QString, QList<const Composite *>> children; // by the including instance
    for (const Composite &c : architecture.composites)
        if (!c.parentId.isEmpty())
            children[c.parentId] << &c;

    QList<LaunchRoot> roots;
    for (const Composite &c : architecture.composites) {
        if (!c.parentId.isEmpty())
            continue;
        LaunchRoot root{c.instanceId, c.stem, c.file};
        QList<const Composite *> todo{&c};
        QSet<QString> seen;
        while (!todo.isEmpty()) {
            const Composite *at = todo.takeLast();
            if (seen.contains(at->instanceId))
                continue; // defensive: stage 2 cuts include cycles
            seen.insert(at->instanceId);
            if (at != &c)
                ++root.includes;
            if (const LaunchFileInstance *lf = launch.instance(at->instanceId))
                root.unresolved += int(lf->unresolved.size());
            for (const RosNodePart &part : at->parts) {
                if (part.kind != RosNodePart::Kind::Node)
                    continue;
                ++root.nodes;
                if (const NodeInstance *node = launch.node(part.instanceId))
                    root.unresolved += int(node->unresolved.size());
            }
            todo << children.value(at->instanceId);
        }
        roots << root;
    }
    return roots;
}

RootChoice RootChoice::choose(const QList<LaunchRoot> &roots, const QString &remembered)
{
    if (roots.isEmpty())
        return {};
    if (!remembered.isEmpty())
        for (const LaunchRoot &r : roots)
            if (r.file == remembered)
                return {r.instanceId, Reason::Remembered};
    if (roots.size() == 1)
        return {roots.first().instanceId, Reason::Only};

    const auto order = [](const LaunchRoot &r) {
        return std::make_tuple(isTestFile(r.file), nameRank(r.stem), int(r.file.count('/')),
                               r.unresolved, r.file.size(), r.file);
    };
    const LaunchRoot *named = nullptr;
    for (const LaunchRoot &r : roots)
        if (nameRank(r.stem) < 2 && (!named || order(r) < order(*named)))
            named = &r;
    if (named)
        return {named->instanceId, Reason::Name};

    const LaunchRoot *widest = nullptr;
    bool tie = false;
    for (const LaunchRoot &r : roots) {
        if (!widest || r.includes > widest->includes) {
            widest = &r;
            tie = false;
        } else if (r.includes == widest->includes) {
            tie = true;
        }
    }
    if (widest->includes > 0 && !tie)
        return {widest->instanceId, Reason::Includes};
    return {QString(), Reason::Ask};
}

} // namespace rosarch
