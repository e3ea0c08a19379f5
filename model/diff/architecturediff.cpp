#include "diff/architecturediff.h"
#include "artifacts/jsonsupport.h"
#include "core/visibletext.h"

#include <QHash>
#include <QSet>

namespace rosarch {

using JsonSupport::Json;
using JsonSupport::utf8;
using Change = ArchitectureChange;
using Snapshot = ArchitectureSnapshot;

namespace {

QString portText(const Snapshot::Port &p)
{
    return QStringLiteral("%1 %2 (%3)")
        .arg(p.kind, p.name, p.type.isEmpty() ? QStringLiteral("?") : p.type);
}

void comparePorts(const Snapshot::NodeClass &a, const Snapshot::NodeClass &b, QList<Change> *out)
{
    auto key = [](const Snapshot::Port &p) { return p.kind + QLatin1Char(' ') + p.name; };
    QList<Snapshot::Port> removed, added;
    for (const Snapshot::Port &p : a.ports) {
        const auto it = std::find_if(b.ports.begin(), b.ports.end(),
                                     [&](const Snapshot::Port &q) { return key(q) == key(p); });
        if (it == b.ports.end())
            removed << p;
        else if (it->type != p.type)
            out->append({Change::Kind::Changed, QStringLiteral("port"), b.name, portText(p),
                         portText(*it)});
    }
    for (const Snapshot::Port &p : b.ports)
        if (std::none_of(a.ports.begin(), a.ports.end(),
                         [&](const Snapshot::Port &q) { return key(q) == key(p); }))
            added << p;
    // A port that only changed its name: the one removed and the one added of a kind and type.
    for (qsizetype i = removed.size() - 1; i >= 0; --i) {
        const Snapshot::Port r = removed.at(i);
        auto same = [&](const Snapshot::Port &p) { return p.kind == r.kind && p.type == r.type; };
        if (std::count_if(removed.begin(), removed.end(), same) != 1 ||
            std::count_if(added.begin(), added.end(), same) != 1)
            continue;
        const auto it = std::find_if(added.begin(), added.end(), same);
        out->append(
            {Change::Kind::Renamed, QStringLiteral("port"), b.name, portText(r), portText(*it)});
        added.erase(it);
        removed.removeAt(i);
    }
    for (const Snapshot::Port &p : std::as_const(removed))
        out->append({Change::Kind::Removed, QStringLiteral("port"), a.name, portText(p), {}});
    for (const Snapshot::Port &p : std::as_const(added))
        out->append({Change::Kind::Added, QStringLiteral("port"), b.name, {}, portText(p)});
}

QString nameKey(const Snapshot::Name &n)
{
    return n.kind + QLatin1Char(' ') + n.name;
}

/// The connections that touch `name` ("topic /x"), with the name cut out: who and how.
QStringList neighbours(const QStringList &connections, const QString &name)
{
    QStringList out;
    for (const QString &c : connections)
        if (c.endsWith(QLatin1Char(' ') + name))
            out << c.left(c.size() - name.size());
    out.sort();
    return out;
}

void compareComposite(const Snapshot::Composite &a, const Snapshot::Composite &b,
                      QList<Change> *out)
{
    const QString &scope = b.file;
    for (const Snapshot::Part &p : a.parts) {
        const auto it = std::find_if(b.parts.begin(), b.parts.end(),
                                     [&](const Snapshot::Part &q) { return q.key == p.key; });
        if (it == b.parts.end())
            out->append({Change::Kind::Removed,
                         QStringLiteral("part"),
                         scope,
                         p.key + QStringLiteral(" : ") + p.type,
                         {}});
        else if (it->type != p.type)
            out->append({Change::Kind::Changed, QStringLiteral("part"), scope,
                         p.key + QStringLiteral(" : ") + p.type,
                         it->key + QStringLiteral(" : ") + it->type});
    }
    for (const Snapshot::Part &p : b.parts)
        if (std::none_of(a.parts.begin(), a.parts.end(),
                         [&](const Snapshot::Part &q) { return q.key == p.key; }))
            out->append({Change::Kind::Added,
                         QStringLiteral("part"),
                         scope,
                         {},
                         p.key + QStringLiteral(" : ") + p.type});

    QHash<QString, Snapshot::Name> before, after;
    for (const Snapshot::Name &n : a.names)
        before.insert(nameKey(n), n);
    for (const Snapshot::Name &n : b.names)
        after.insert(nameKey(n), n);
    QList<Snapshot::Name> removed, added;
    for (const Snapshot::Name &n : a.names) {
        if (!after.contains(nameKey(n)))
            removed << n;
        else if (after.value(nameKey(n)).type != n.type)
            out->append(
                {Change::Kind::Changed, n.kind, scope,
                 n.name + QStringLiteral(" (") + n.type + QLatin1Char(')'),
                 n.name + QStringLiteral(" (") + after.value(nameKey(n)).type + QLatin1Char(')')});
    }
    for (const Snapshot::Name &n : b.names)
        if (!before.contains(nameKey(n)))
            added << n;
    // A rename: same kind and type, and the same parts talk to it in the same ways.
    QHash<QString, QString> renamed; // old "topic /x" -> new "topic /y"
    for (const Snapshot::Name &r : std::as_const(removed)) {
        const QStringList was = neighbours(a.connections, nameKey(r));
        for (qsizetype i = 0; i < added.size(); ++i) {
            const Snapshot::Name &n = added.at(i);
            if (n.kind != r.kind || n.type != r.type ||
                neighbours(b.connections, nameKey(n)) != was)
                continue;
            renamed.insert(nameKey(r), nameKey(n));
            out->append({Change::Kind::Renamed, r.kind, scope, r.name, n.name});
            added.removeAt(i);
            break;
        }
    }
    for (const Snapshot::Name &n : std::as_const(removed))
        if (!renamed.contains(nameKey(n)))
            out->append({Change::Kind::Removed,
                         n.kind,
                         scope,
                         n.name + QStringLiteral(" (") + n.type + QLatin1Char(')'),
                         {}});
    for (const Snapshot::Name &n : std::as_const(added))
        out->append({Change::Kind::Added,
                     n.kind,
                     scope,
                     {},
                     n.name + QStringLiteral(" (") + n.type + QLatin1Char(')')});

    // Connections, with renamed names carried over first.
    QSet<QString> was;
    for (QString c : a.connections) {
        for (auto it = renamed.cbegin(); it != renamed.cend(); ++it)
            if (c.endsWith(QLatin1Char(' ') + it.key()))
                c = c.left(c.size() - it.key().size()) + it.value();
        was.insert(c);
    }
    const QSet<QString> is(b.connections.begin(), b.connections.end());
    QStringList gone(was.begin(), was.end()), come;
    gone.removeIf([&](const QString &c) { return is.contains(c); });
    for (const QString &c : b.connections)
        if (!was.contains(c))
            come << c;
    gone.sort();
    for (const QString &c : std::as_const(gone))
        out->append({Change::Kind::Removed, QStringLiteral("connection"), scope, c, {}});
    for (const QString &c : std::as_const(come))
        out->append({Change::Kind::Added, QStringLiteral("connection"), scope, {}, c});
}

} // namespace

QString ArchitectureChange::kindName(Kind kind)
{
    switch (kind) {
    case Kind::Added:
        return QStringLiteral("added");
    case Kind::Removed:
        return QStringLiteral("removed");
    case Kind::Changed:
        return QStringLiteral("changed");
    case Kind::Renamed:
        return QStringLiteral("renamed");
    }
    return {};
}

QString ArchitectureChange::describe() const
{
    const QString what = kind == Kind::Added     ? after
                         : kind == Kind::Removed ? before
                                                 : before + QStringLiteral(" -> ") + after;
    return QStringLiteral("%1 %2 %3").arg(kindName(kind), element, what);
}

QList<ArchitectureChange> ArchitectureDiff::compare(const ArchitectureSnapshot &before,
                                                    const ArchitectureSnapshot &after)
{
    QList<Change> out;
    for (auto it = before.classes.cbegin(); it != before.classes.cend(); ++it) {
        if (!after.classes.contains(it.key()))
            out.append(
                {Change::Kind::Removed, QStringLiteral("node class"), it->name, it.key(), {}});
        else
            comparePorts(*it, after.classes.value(it.key()), &out);
    }
    for (auto it = after.classes.cbegin(); it != after.classes.cend(); ++it)
        if (!before.classes.contains(it.key()))
            out.append({Change::Kind::Added, QStringLiteral("node class"), it->name, {}, it.key()});
    for (auto it = before.composites.cbegin(); it != before.composites.cend(); ++it) {
        if (!after.composites.contains(it.key()))
            out.append(
                {Change::Kind::Removed, QStringLiteral("launch file"), it.key(), it.key(), {}});
        else
            compareComposite(*it, after.composites.value(it.key()), &out);
    }
    for (auto it = after.composites.cbegin(); it != after.composites.cend(); ++it)
        if (!before.composites.contains(it.key()))
            out.append(
                {Change::Kind::Added, QStringLiteral("launch file"), it.key(), {}, it.key()});
    return out;
}

QString ArchitectureDiff::text(const QList<ArchitectureChange> &changes)
{
    int counts[4] = {0, 0, 0, 0};
    for (const Change &c : changes)
        ++counts[int(c.kind)];
    QString out =
        changes.isEmpty()
            ? QStringLiteral("No architecture changes.\n")
            : QStringLiteral("%1 changes: %2 added, %3 removed, %4 changed, %5 renamed.\n")
                  .arg(changes.size())
                  .arg(counts[0])
                  .arg(counts[1])
                  .arg(counts[2])
                  .arg(counts[3]);
    QString scope;
    for (const Change &c : changes) {
        if (c.scope != scope) {
            scope = c.scope;
            out += QLatin1Char('\n') + scope + QStringLiteral(":\n");
        }
        const QChar mark = c.kind == Change::Kind::Added     ? QLatin1Char('+')
                           : c.kind == Change::Kind::Removed ? QLatin1Char('-')
                                                             : QLatin1Char('~');
        out += QStringLiteral("  %1 %2\n").arg(mark).arg(c.describe());
    }
    return out;
}

QByteArray ArchitectureDiff::json(const QList<ArchitectureChange> &changes)
{
    int counts[4] = {0, 0, 0, 0};
    Json list = Json::array();
    for (const Change &c : changes) {
        ++counts[int(c.kind)];
        Json j;
        j["change"] = utf8(ArchitectureChange::kindName(c.kind));
        j["element"] = utf8(c.element);
        j["scope"] = utf8(c.scope);
        if (!c.before.isEmpty())
            j["before"] = utf8(c.before);
        if (!c.after.isEmpty())
            j["after"] = utf8(c.after);
        list.push_back(j);
    }
    Json root;
    root["version"] = 1;
    root["summary"] = {{"added", counts[0]},
                       {"removed", counts[1]},
                       {"changed", counts[2]},
                       {"renamed", counts[3]}};
    root["changes"] = list;
    return visibleJson(root.dump(2)) + '\n';
}

} // namespace rosarch
