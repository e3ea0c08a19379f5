#pragma once
// The set-up shared by the tests of the analysis cache and of what it lets the stages reuse.
#include "support/testsupport.h"

#include <QTemporaryDir>
#include <QtTest>

namespace rosarch::test {

/// For init(): a fresh copy of compose_system/ws in `temp` as `*ws`, and a cache folder not yet
/// made as `*cache`, both named after the test function that runs.
inline void freshCacheCase(const QTemporaryDir &temp, QString *ws, QString *cache)
{
    *ws = temp.filePath(QStringLiteral("ws-%1").arg(QTest::currentTestFunction()));
    *cache = temp.filePath(QStringLiteral("cache-%1").arg(QTest::currentTestFunction()));
    copyTree(dataDir(QStringLiteral("compose_system/ws")), *ws);
}

} // namespace rosarch::test
