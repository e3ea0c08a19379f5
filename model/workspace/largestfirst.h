#pragma once

#include "workspace/workspace.h"

#include <QList>
#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <functional>
#include <numeric>

namespace rosarch {

/// The indexes of `files`, the largest file first; files of equal size in their own order.
inline QList<qsizetype> largestFirst(const QList<const SourceFile *> &files)
{
    QList<qsizetype> order(files.size());
    std::iota(order.begin(), order.end(), qsizetype(0));
    std::stable_sort(order.begin(), order.end(), [&files](qsizetype a, qsizetype b) {
        return files.at(a)->size > files.at(b)->size;
    });
    return order;
}

/// `work` for each of `files` on the global thread pool, the largest files first, with the
/// results in the files' own order. The pool hands out files in the order given: in the
/// workspace's order a large file met near the end is left to one core while the others
/// wait, so the longest jobs go first and the small ones fill in at the end.
template <class R>
QList<R> mapLargestFirst(const QList<const SourceFile *> &files,
                         const std::function<R(const SourceFile *)> &work)
{
    const QList<qsizetype> order = largestFirst(files);
    QList<const SourceFile *> sorted;
    sorted.reserve(files.size());
    for (const qsizetype i : std::as_const(order))
        sorted.append(files.at(i));
    QList<R> done = QtConcurrent::blockingMapped<QList<R>>(sorted, work);
    QList<R> results(files.size());
    for (qsizetype k = 0; k < done.size(); ++k)
        results[order.at(k)] = std::move(done[k]);
    return results;
}

} // namespace rosarch
