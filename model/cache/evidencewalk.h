#pragma once

#include "core/evidence.h"
#include "core/modelfields.h"

#include <QByteArray>
#include <QHash>
#include <QList>
#include <QMap>
#include <QString>

#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

// Walks over the source locations (Evidence) in model values, through their field lists
// (modelfields.h): to compare two values apart from their locations, and to rewrite the
// locations of one without copying the parts that hold none to rewrite.

namespace rosarch::evidencewalk {

/// Types that hold no Evidence at any depth: skipped whole.
template <class T>
constexpr bool kLeaf = std::is_arithmetic_v<T> || std::is_enum_v<T> || std::is_same_v<T, QString> ||
                       std::is_same_v<T, QByteArray>;

template <class T> struct IsLeafList : std::false_type
{
};
template <class T> struct IsLeafList<QList<T>> : std::bool_constant<kLeaf<T>>
{
};

template <class T, class F> bool same(const T &a, const T &b, F &pair);
template <class T, class F> bool same(const QList<T> &a, const QList<T> &b, F &pair);
template <class T, class F> bool same(const std::vector<T> &a, const std::vector<T> &b, F &pair);
template <class K, class V, class F> bool same(const QHash<K, V> &a, const QHash<K, V> &b, F &pair);
template <class K, class V, class F> bool same(const QMap<K, V> &a, const QMap<K, V> &b, F &pair);
template <class T, class F>
bool same(const std::optional<T> &a, const std::optional<T> &b, F &pair);
template <class X, class Y, class F>
bool same(const std::pair<X, Y> &a, const std::pair<X, Y> &b, F &pair);

/// True when `a` and `b` are equal but for their locations; `pair(const Evidence &before,
/// const Evidence &after)` is called on every pair of locations at the same place in both.
/// False at the first other difference (some pairs may have been reported by then).
template <class T, class F> bool same(const T &a, const T &b, F &pair)
{
    if constexpr (kLeaf<T> || IsLeafList<T>::value) {
        return a == b;
    } else if constexpr (std::is_same_v<T, Evidence>) {
        pair(a, b);
        return true;
    } else {
        bool equal = true;
        fields(const_cast<T &>(a), [&](auto &...xa) {
            fields(const_cast<T &>(b), [&](auto &...xb) {
                equal = (same(std::as_const(xa), std::as_const(xb), pair) && ...);
            });
        });
        return equal;
    }
}

template <class T, class F> bool same(const QList<T> &a, const QList<T> &b, F &pair)
{
    if constexpr (kLeaf<T>)
        return a == b;
    if (a.size() != b.size())
        return false;
    for (qsizetype i = 0; i < a.size(); ++i)
        if (!same(a.at(i), b.at(i), pair))
            return false;
    return true;
}

template <class T, class F> bool same(const std::vector<T> &a, const std::vector<T> &b, F &pair)
{
    if (a.size() != b.size())
        return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (!same(a[i], b[i], pair))
            return false;
    return true;
}

template <class Map, class F> bool sameMap(const Map &a, const Map &b, F &pair)
{
    if (a.size() != b.size())
        return false;
    for (auto it = a.cbegin(); it != a.cend(); ++it) {
        const auto other = b.constFind(it.key());
        if (other == b.cend() || !same(it.value(), other.value(), pair))
            return false;
    }
    return true;
}

template <class K, class V, class F> bool same(const QHash<K, V> &a, const QHash<K, V> &b, F &pair)
{
    static_assert(kLeaf<K>, "locations in keys are not walked");
    return sameMap(a, b, pair);
}

template <class K, class V, class F> bool same(const QMap<K, V> &a, const QMap<K, V> &b, F &pair)
{
    static_assert(kLeaf<K>, "locations in keys are not walked");
    return sameMap(a, b, pair);
}

template <class T, class F> bool same(const std::optional<T> &a, const std::optional<T> &b, F &pair)
{
    if (a.has_value() != b.has_value())
        return false;
    return !a || same(*a, *b, pair);
}

template <class X, class Y, class F>
bool same(const std::pair<X, Y> &a, const std::pair<X, Y> &b, F &pair)
{
    return same(a.first, b.first, pair) && same(a.second, b.second, pair);
}

template <class T, class P> bool any(const T &v, P &pick);
template <class T, class P> bool any(const QList<T> &v, P &pick);
template <class T, class P> bool any(const std::vector<T> &v, P &pick);
template <class K, class V, class P> bool any(const QHash<K, V> &v, P &pick);
template <class K, class V, class P> bool any(const QMap<K, V> &v, P &pick);
template <class T, class P> bool any(const std::optional<T> &v, P &pick);
template <class X, class Y, class P> bool any(const std::pair<X, Y> &v, P &pick);

/// True when `pick(const Evidence &)` holds for a location in `v`.
template <class T, class P> bool any(const T &v, P &pick)
{
    if constexpr (kLeaf<T> || IsLeafList<T>::value) {
        return false;
    } else if constexpr (std::is_same_v<T, Evidence>) {
        return pick(v);
    } else {
        bool found = false;
        fields(const_cast<T &>(v),
               [&](auto &...x) { found = (any(std::as_const(x), pick) || ...); });
        return found;
    }
}

template <class T, class P> bool any(const QList<T> &v, P &pick)
{
    if constexpr (kLeaf<T>)
        return false;
    for (const T &x : v)
        if (any(x, pick))
            return true;
    return false;
}

template <class T, class P> bool any(const std::vector<T> &v, P &pick)
{
    for (const T &x : v)
        if (any(x, pick))
            return true;
    return false;
}

template <class Map, class P> bool anyInMap(const Map &v, P &pick)
{
    for (auto it = v.cbegin(); it != v.cend(); ++it)
        if (any(it.value(), pick))
            return true;
    return false;
}

template <class K, class V, class P> bool any(const QHash<K, V> &v, P &pick)
{
    return anyInMap(v, pick);
}

template <class K, class V, class P> bool any(const QMap<K, V> &v, P &pick)
{
    return anyInMap(v, pick);
}

template <class T, class P> bool any(const std::optional<T> &v, P &pick)
{
    return v && any(*v, pick);
}

template <class X, class Y, class P> bool any(const std::pair<X, Y> &v, P &pick)
{
    return any(v.first, pick) || any(v.second, pick);
}

template <class T, class P, class F> void rewrite(T &v, P &pick, F &change);
template <class T, class P, class F> void rewrite(QList<T> &v, P &pick, F &change);
template <class T, class P, class F> void rewrite(std::vector<T> &v, P &pick, F &change);
template <class K, class V, class P, class F> void rewrite(QHash<K, V> &v, P &pick, F &change);
template <class K, class V, class P, class F> void rewrite(QMap<K, V> &v, P &pick, F &change);
template <class T, class P, class F> void rewrite(std::optional<T> &v, P &pick, F &change);
template <class X, class Y, class P, class F> void rewrite(std::pair<X, Y> &v, P &pick, F &change);

/// Calls `change(Evidence &)` on the locations in `v` that `pick` selects; a container is
/// touched (and so detached from the copies it shares its data with) only when it holds one.
template <class T, class P, class F> void rewrite(T &v, P &pick, F &change)
{
    if constexpr (kLeaf<T> || IsLeafList<T>::value) {
        return;
    } else if constexpr (std::is_same_v<T, Evidence>) {
        if (pick(std::as_const(v)))
            change(v);
    } else {
        fields(v, [&](auto &...x) {
            ((any(std::as_const(x), pick) ? rewrite(x, pick, change) : void()), ...);
        });
    }
}

template <class T, class P, class F> void rewrite(QList<T> &v, P &pick, F &change)
{
    for (qsizetype i = 0; i < v.size(); ++i)
        if (any(v.at(i), pick))
            rewrite(v[i], pick, change);
}

template <class T, class P, class F> void rewrite(std::vector<T> &v, P &pick, F &change)
{
    for (T &x : v)
        if (any(std::as_const(x), pick))
            rewrite(x, pick, change);
}

template <class Map, class P, class F> void rewriteMap(Map &v, P &pick, F &change)
{
    QList<typename Map::key_type> keys;
    for (auto it = v.cbegin(); it != v.cend(); ++it)
        if (any(it.value(), pick))
            keys.append(it.key());
    for (const auto &key : std::as_const(keys))
        rewrite(v[key], pick, change);
}

template <class K, class V, class P, class F> void rewrite(QHash<K, V> &v, P &pick, F &change)
{
    rewriteMap(v, pick, change);
}

template <class K, class V, class P, class F> void rewrite(QMap<K, V> &v, P &pick, F &change)
{
    rewriteMap(v, pick, change);
}

template <class T, class P, class F> void rewrite(std::optional<T> &v, P &pick, F &change)
{
    if (v)
        rewrite(*v, pick, change);
}

template <class X, class Y, class P, class F> void rewrite(std::pair<X, Y> &v, P &pick, F &change)
{
    rewrite(v.first, pick, change);
    rewrite(v.second, pick, change);
}

} // namespace rosarch::evidencewalk
