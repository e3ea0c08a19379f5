#pragma once

#include "cache/evidencewalk.h"
#include "core/evidence.h"

#include <QHash>
#include <QList>
#include <QSet>
#include <QString>

namespace rosarch {

/// How the source locations of a stage's inputs moved between two runs whose inputs are equal
/// but for their locations (an edit that only moved lines): each old location and its new one.
/// A stage's earlier result, computed from the old inputs, is the result of the new ones once
/// the locations it took from its inputs are rewritten (apply()). Only moves that a stage cannot
/// tell from the old ones are accepted: within one file, keeping the order of the file's
/// locations and which of them share a line or a start.
class EvidenceShift
{
public:
    /// Records a location of the old inputs and the one at the same place in the new inputs.
    void add(const Evidence &before, const Evidence &after);
    /// Checks the recorded moves; false when a stage could tell them apart (see the class).
    bool settle();

    /// Nothing moved (after settle()).
    bool isIdentity() const { return m_files.isEmpty(); }
    /// The files where locations moved.
    const QList<QString> &files() const { return m_files; }

    /// `value` (a stage's earlier result) with every location that moved at its new place; false
    /// when it holds a location in a file where locations moved that is none of the inputs'
    /// (then `value` is partly rewritten and must not be used).
    template <class T> bool apply(T &value) const
    {
        if (isIdentity())
            return true;
        bool known = true;
        auto pick = [this](const Evidence &e) { return m_files.contains(e.file); };
        auto change = [this, &known](Evidence &e) {
            const auto it = m_moves.constFind(Key{e});
            if (it == m_moves.cend())
                known = false;
            else
                e = *it;
        };
        evidencewalk::rewrite(value, pick, change);
        return known;
    }

    /// Compares the old inputs `before` with the new `after` (one of them, in the order the stage
    /// reads them): false when they differ in more than locations. Call settle() once all are
    /// compared. Two passes: the moved locations first, then every location in their files.
    template <class T> bool compare(const T &before, const T &after)
    {
        auto moved = [this](const Evidence &a, const Evidence &b) {
            if (!(a == b))
                add(a, b);
        };
        return evidencewalk::same(before, after, moved);
    }
    /// The second pass of compare(): records the unmoved locations in the files where some moved.
    template <class T> void compareUnmoved(const T &before, const T &after)
    {
        if (m_moved.isEmpty())
            return;
        auto unmoved = [this](const Evidence &a, const Evidence &b) {
            if (a == b && m_moved.contains(a.file))
                add(a, b);
        };
        evidencewalk::same(before, after, unmoved);
    }

private:
    struct Key
    {
        Evidence e;
        bool operator==(const Key &o) const { return e == o.e; }
        friend size_t qHash(const Key &k, size_t seed = 0)
        {
            return qHashMulti(seed, k.e.file, k.e.line, k.e.column, k.e.endLine, k.e.endColumn);
        }
    };
    QHash<Key, Evidence> m_moves; ///< old location -> new one, in the files where any moved
    QSet<QString> m_moved;        ///< files where some location moved (before settle())
    QList<QString> m_files;       ///< the same, once settled
    bool m_conflict = false;
};

} // namespace rosarch
