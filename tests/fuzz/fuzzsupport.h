#pragma once

// What every libFuzzer target of rosarch shares: a Qt core application (some readers use
// Qt's text codecs and paths), and a scratch workspace on disk for the analyzers that read
// files rather than buffers.
#include <QByteArray>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <cstddef>
#include <cstdint>

namespace rosarch::fuzz {

inline QByteArray bytes(const uint8_t *data, size_t size)
{
    return QByteArray(reinterpret_cast<const char *>(data), qsizetype(size));
}

/// A process-wide temporary folder, created at the first call.
inline QTemporaryDir &scratch()
{
    static QTemporaryDir dir;
    return dir;
}

/// Writes `content` to `relative` inside the scratch folder; the absolute path.
inline QString writeScratch(const QString &relative, const QByteArray &content)
{
    const QString path = scratch().filePath(relative);
    QDir().mkpath(QFileInfo(path).path());
    QFile f(path);
    if (f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        f.write(content);
    return path;
}

} // namespace rosarch::fuzz
