#pragma once

#include "cache/analysiscache.h"
#include "cache/cachecodec.h"

#include <QMap>

#include <memory>
#include <optional>

// Whole-stage memos: a stage's result in the analysis cache, under a key made of everything the
// stage reads. Templates over the workspace and control types, so that the cache library does
// not depend on the workspace scanner's.

namespace rosarch::stagememo {

/// What a stage knows of a scanned workspace besides the files' contents: its root, packages,
/// files (path, package, language, and the size when `sizes`), the scan's diagnostics, and the
/// files the control says to skip.
template <class Workspace, class Control>
QByteArray workspacePart(const Workspace &ws, const Control &control, bool sizes)
{
    QByteArray bytes;
    cachecodec::Sink s(&bytes);
    cachecodec::Writer w{s};
    auto root = ws.root;
    auto packages = ws.packages;
    auto diagnostics = ws.diagnostics;
    QMap<QString, QString> skipped; // sorted: a QHash's order differs between processes
    for (auto it = control.skipped.cbegin(); it != control.skipped.cend(); ++it)
        skipped.insert(it.key(), it.value());
    cachecodec::io(w, root);
    cachecodec::io(w, packages);
    cachecodec::io(w, diagnostics);
    cachecodec::io(w, skipped);
    s << quint32(ws.files.size());
    for (const auto &f : ws.files)
        s << f.path << f.package << qint32(f.language) << qint64(sizes ? f.size : 0);
    return bytes;
}

/// The entry of `kind` under `key` decoded by `decode` (bool(const QByteArray &, T *)), when
/// there is a good one: the value this process decoded before (AnalysisCache::recent), else
/// the entry read and decoded, and kept for the next run.
template <class T, class Decode>
std::optional<T> loadWith(AnalysisCache &cache, const QString &kind, const QByteArray &key,
                          Decode decode)
{
    if (const std::shared_ptr<const void> kept = cache.recent(kind, key))
        return *static_cast<const T *>(kept.get());
    const std::optional<QByteArray> bytes = cache.load(kind, key);
    T value;
    if (!bytes || !decode(*bytes, &value))
        return std::nullopt;
    cache.keepRecent(kind, key, std::make_shared<const T>(value));
    return value;
}

/// The memo of `kind` under `key`, when there is a good one.
template <class T>
std::optional<T> load(AnalysisCache &cache, const QString &kind, const QByteArray &key)
{
    return loadWith<T>(cache, kind, key, [](const QByteArray &bytes, T *value) {
        return cachecodec::decode(bytes, value);
    });
}

} // namespace rosarch::stagememo
