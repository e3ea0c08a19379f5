#include "diagram/rootchoice.h"

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

/// 0 = the stem is an entry word, 1 = it contains one, 2 = a folder on its path does (a
/// `robot_bringup` package), 3 = none.
int nameRank(const LaunchRoot &root)
{
    const QString lower = root.stem.toLower();
    if (entryWords().contains(lower))
        return 0;
    for (const QString &w : entryWords())
        if (lower.contains(w))
            return 1;
    const QString folder = root.file.section(QLatin1Char('/'), 0, -2).toLower();
    for (const QString &w : entryWords())
        if (folder.contains(w))
            return 2;
    return 3;
}

/// Tests, benchmarks, tools and examples start a system only to check, measure or show it; a
/// person rarely wants them first.
bool isAuxiliary(const QString &file)
{
    for (const QString &segment : file.toLower().split(QLatin1Char('/'), Qt::SkipEmptyParts))
        if (segment == QLatin1String("test") || segment == QLatin1String("tests") ||
            segment.startsWith(QLatin1String("test_")) ||
            segment.contains(QLatin1String("_test")) ||
            segment.contains(QLatin1String("benchmark")) || segment == QLatin1String("tools") ||
            segment == QLatin1String("example") || segment == QLatin1String("examples"))
            return true;
    return false;
}

/// The choice among roots of one kind (auxiliary or not); Ask when none stands out.
RootChoice chooseAmong(const QList<const LaunchRoot *> &roots)
{
    // By name: exact, then contained, each by shallower path, fewer unresolved.
    const auto byName = [](const LaunchRoot *r) {
        return std::make_tuple(nameRank(*r), int(r->file.count('/')), r->unresolved, r->file.size(),
                               r->file);
    };
    // In a bringup/robot/system folder: the one that includes the most, as below.
    const auto byFolder = [](const LaunchRoot *r) {
        return std::make_tuple(-r->includes, r->unresolved, int(r->file.count('/')), r->file.size(),
                               r->file);
    };
    const LaunchRoot *named = nullptr;
    const LaunchRoot *inFolder = nullptr;
    for (const LaunchRoot *r : roots) {
        const int rank = nameRank(*r);
        if (rank < 2 && (!named || byName(r) < byName(named)))
            named = r;
        else if (rank == 2 && (!inFolder || byFolder(r) < byFolder(inFolder)))
            inFolder = r;
    }
    if (named)
        return {named->instanceId, RootChoice::Reason::Name};
    if (inFolder)
        return {inFolder->instanceId, RootChoice::Reason::Name};

    const LaunchRoot *widest = nullptr;
    bool tie = false;
    for (const LaunchRoot *r : roots) {
        if (!widest || r->includes > widest->includes) {
            widest = r;
            tie = false;
        } else if (r->includes == widest->includes) {
            tie = true;
        }
    }
    if (widest && widest->includes > 0 && !tie)
        return {widest->instanceId, RootChoice::Reason::Includes};
    return {QString(), RootChoice::Reason::Ask};
}

} // namespace

QList<LaunchRoot> RootChoice::roots(const Architecture &architecture,
                                    const LaunchDependencies &launch)
{
    QHash<QString, QList<const Composite *>> children; // by the including instance
    for (const Composite &c : architecture.composites)
        if (!c.parentId.isEmpty())
            children[c.parentId] << &c;
    // What the analysis left unresolved, by instance id: LaunchDependencies' own look-ups scan
    // their lists, which made this quadratic (50 ms on the UI thread for 3,000 launch files).
    QHash<QString, int> unresolved;
    for (const LaunchFileInstance &lf : launch.instances)
        if (!unresolved.contains(lf.id)) // the first, as instance()
            unresolved.insert(lf.id, int(lf.unresolved.size()));
    QHash<QString, int> nodeUnresolved;
    for (const NodeInstance &n : launch.nodes)
        if (!nodeUnresolved.contains(n.id)) // the first, as node()
            nodeUnresolved.insert(n.id, int(n.unresolved.size()));

    QList<LaunchRoot> roots;
    for (const Composite &c : architecture.composites) {
        if (!c.parentId.isEmpty())
            continue;
        LaunchRoot root{c.instanceId, c.stem, c.file};
        root.executable = !c.executable.isEmpty();
        QList<const Composite *> todo{&c};
        QSet<QString> seen;
        while (!todo.isEmpty()) {
            const Composite *at = todo.takeLast();
            if (seen.contains(at->instanceId))
                continue; // defensive: stage 2 cuts include cycles
            seen.insert(at->instanceId);
            if (at != &c)
                ++root.includes;
            root.unresolved += unresolved.value(at->instanceId);
            for (const RosNodePart &part : at->parts) {
                if (part.kind != RosNodePart::Kind::Node)
                    continue;
                ++root.nodes;
                root.unresolved += nodeUnresolved.value(part.instanceId);
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

    // Systems first; tests, benchmarks, tools and examples only when no system stands out.
    for (const bool auxiliary : {false, true}) {
        QList<const LaunchRoot *> pool;
        for (const LaunchRoot &r : roots)
            if (isAuxiliary(r.file) == auxiliary)
                pool << &r;
        const RootChoice choice = chooseAmong(pool);
        if (choice.reason != Reason::Ask)
            return choice;
    }
    return {QString(), Reason::Ask};
}

} // namespace rosarch
