#pragma once

// Shared helpers for the Qt Test executables: fixture paths, files, the real executable.
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QMap>
#include <QProcess>
#include <QString>
#include <QTemporaryDir>
#include <QTest>
#include <QThreadPool>

namespace rosarch::test {

/// The global thread pool's size for a scope.
class PoolSize
{
public:
    explicit PoolSize(int threads) : m_before(QThreadPool::globalInstance()->maxThreadCount())
    {
        QThreadPool::globalInstance()->setMaxThreadCount(threads);
    }
    ~PoolSize() { QThreadPool::globalInstance()->setMaxThreadCount(m_before); }
    PoolSize(const PoolSize &) = delete;
    PoolSize &operator=(const PoolSize &) = delete;

private:
    int m_before;
};

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

/// Writes `content` to `path`, creating the folders on the way; fails the test if it cannot.
inline void writeFile(const QString &path, const QByteArray &content)
{
    QDir().mkpath(QFileInfo(path).path());
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(content);
}

/// Copies every file below `from` to the same place below `to` (replacing what is there).
inline void copyTree(const QString &from, const QString &to)
{
    QDirIterator it(from, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        const QString target = QDir(to).filePath(QDir(from).relativeFilePath(file));
        QDir().mkpath(QFileInfo(target).path());
        QFile::remove(target);
        QVERIFY(QFile::copy(file, target));
    }
}

/// Compares `actual` with the expected file, or writes it there when ROSARCH_UPDATE_EXPECTED
/// is set (after a reviewed change). On a difference the actual output is written next to the
/// temporary folder's copy for diffing, and the test fails.
inline void compareOrUpdate(const QByteArray &actual, const QString &expectedPath)
{
    if (qEnvironmentVariableIntValue("ROSARCH_UPDATE_EXPECTED")) {
        QDir().mkpath(QFileInfo(expectedPath).path());
        QFile f(expectedPath);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(actual);
        return;
    }
    QFile in(expectedPath);
    const QByteArray expected = in.open(QIODevice::ReadOnly) ? in.readAll() : QByteArray();
    if (actual != expected) {
        const QString actualPath =
            QDir::temp().filePath(QFileInfo(expectedPath).fileName() + QStringLiteral(".actual"));
        QFile f(actualPath);
        if (f.open(QIODevice::WriteOnly))
            f.write(actual);
        QFAIL(qPrintable(QStringLiteral("%1 differs; actual output written to %2 (diff them)")
                             .arg(expectedPath, actualPath)));
    }
}

/// An executable shell script `name` in `dir` running `body` (a stand-in helper program).
inline QString script(const QTemporaryDir &dir, const QString &name, const QByteArray &body)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write("#!/bin/sh\n" + body + "\n");
    f.close();
    f.setPermissions(f.permissions() | QFileDevice::ExeOwner);
    return path;
}

/// What the real `rosarch` executable did.
struct Run
{
    int exitCode = -1; ///< -1: did not finish in time; -2: crashed
    QString out;
    QString err;
};

/// Runs the real `rosarch` headless: without a display, without LLM settings from the
/// developer's environment, plus `extraEnv`. The event loop keeps running while it waits, so
/// a server in the test (the fake LLM) can answer.
inline Run runRosarch(const QStringList &args, const QMap<QString, QString> &extraEnv = {})
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"ROSARCH_LLM_ENDPOINT", "ROSARCH_LLM_MODEL", "ROSARCH_PROMPT_DIR",
                             "ROSARCH_LLM_API_KEY", "OPENAI_API_KEY", "DISPLAY", "QT_QPA_PLATFORM"})
        env.remove(QString::fromLatin1(name));
    for (auto it = extraEnv.begin(); it != extraEnv.end(); ++it)
        env.insert(it.key(), it.value());
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(ROSARCH_BINARY), args);
    Run r;
    if (!p.waitForStarted(10000) ||
        !QTest::qWaitFor([&] { return p.state() == QProcess::NotRunning; }, 120000))
        return r;
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

} // namespace rosarch::test
