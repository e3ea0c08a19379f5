#pragma once

// Shared helpers for the Qt Test executables.
#include <QDir>
#include <QFile>
#include <QString>

namespace rosarch::test {

inline QString dataDir(const QString &sub = {})
{
    return sub.isEmpty() ? QStringLiteral(ROSARCH_TEST_DATA)
                         : QDir(QStringLiteral(ROSARCH_TEST_DATA)).filePath(sub);
}

inline QByteArray readFile(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return f.readAll();
}

} // namespace rosarch::test
