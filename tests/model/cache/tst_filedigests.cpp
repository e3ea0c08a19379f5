// File digests: known by stat when nothing changed, and read again when anything stat shows
// changed, even a rewrite of the same size with the mtime set back; the memo survives a
// process and a damaged memo is no memo.
#include "cache/filedigests.h"
#include "cache/sha1.h"
#include "support/testsupport.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QFile>
#include <QSemaphore>
#include <QTemporaryDir>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentMap>
#include <QtConcurrent/QtConcurrentRun>
#include <QtTest>

#include <sys/stat.h>

using namespace rosarch;

namespace {

QByteArray sha1(const QByteArray &bytes)
{
    return QCryptographicHash::hash(bytes, QCryptographicHash::Sha1);
}

qint64 ctimeNs(const QString &path)
{
    struct stat st = {};
    ::stat(QFile::encodeName(path).constData(), &st);
    return qint64(st.st_ctim.tv_sec) * 1'000'000'000 + st.st_ctim.tv_nsec;
}

} // namespace

class TestFileDigests : public QObject
{
    Q_OBJECT

    QTemporaryDir m_temp;

private Q_SLOTS:
    void unchangedFilesAreNotReadAgain()
    {
        const QString file = m_temp.filePath(QStringLiteral("a.cpp"));
        test::writeFile(file, "int a;\n");
        FileDigests digests(QString(), 0);
        QCOMPARE(digests.digest(file), sha1("int a;\n"));
        QCOMPARE(digests.digest(file), sha1("int a;\n"));
        QCOMPARE(digests.hashed(), 1);
        QVERIFY(digests.digest(m_temp.filePath(QStringLiteral("missing"))).isEmpty());
    }

    void sameSizeAndRewoundMtimeIsStillSeen()
    {
        const QString file = m_temp.filePath(QStringLiteral("b.cpp"));
        test::writeFile(file, "int b = 1;\n");
        FileDigests digests(QString(), 0);
        QCOMPARE(digests.digest(file), sha1("int b = 1;\n"));
        const QDateTime mtime = QFileInfo(file).lastModified();
        const qint64 ctime = ctimeNs(file);
        // ctime moves with the clock's tick: wait for a tick, so that the rewrite's differs.
        QTRY_VERIFY_WITH_TIMEOUT((test::writeFile(m_temp.filePath(QStringLiteral("tick")), "t"),
                                  ctimeNs(m_temp.filePath(QStringLiteral("tick"))) > ctime),
                                 5000);
        // The same size, in place (same inode), the mtime set back: only ctime tells.
        test::writeFile(file, "int b = 2;\n");
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadWrite));
        QVERIFY(f.setFileTime(mtime, QFileDevice::FileModificationTime));
        f.close();
        QCOMPARE(QFileInfo(file).size(), qint64(11));
        QCOMPARE(digests.digest(file), sha1("int b = 2;\n"));
        // Replaced by another file (a new inode), as editors save.
        const QString other = m_temp.filePath(QStringLiteral("b.new"));
        test::writeFile(other, "int b = 3;\n");
        QVERIFY(QFile::remove(file));
        QVERIFY(QFile::rename(other, file));
        QCOMPARE(digests.digest(file), sha1("int b = 3;\n"));
        QCOMPARE(digests.hashed(), 3);
    }

    void aFileChangedJustNowIsNotMemoised()
    {
        // Within the racy window a second write could keep every stat field: read each time.
        const QString file = m_temp.filePath(QStringLiteral("c.cpp"));
        test::writeFile(file, "int c;\n");
        FileDigests digests;
        digests.digest(file);
        digests.digest(file);
        QCOMPARE(digests.hashed(), 2);
    }

    void theMemoSurvivesAndADamagedOneIsIgnored()
    {
        const QString file = m_temp.filePath(QStringLiteral("d.cpp"));
        const QString memo = m_temp.filePath(QStringLiteral("digests"));
        test::writeFile(file, "int d;\n");
        {
            FileDigests first(memo, 0);
            first.digest(file);
            QString error;
            QVERIFY2(first.save(&error), qPrintable(error));
        }
        FileDigests second(memo, 0);
        QCOMPARE(second.digest(file), sha1("int d;\n"));
        QCOMPARE(second.hashed(), 0);

        QByteArray bytes = test::readFile(memo);
        bytes[bytes.size() / 2] = char(bytes.at(bytes.size() / 2) ^ 0x21);
        test::writeFile(memo, bytes);
        FileDigests third(memo, 0);
        QCOMPARE(third.digest(file), sha1("int d;\n"));
        QCOMPARE(third.hashed(), 1);
    }

    void digestAllListsEachFile()
    {
        test::writeFile(m_temp.filePath(QStringLiteral("e/x.py")), "x = 1\n");
        test::writeFile(m_temp.filePath(QStringLiteral("e/y.py")), "y = 2\n");
        FileDigests digests(QString(), 0);
        const QByteArray all = digests.digestAll(m_temp.filePath(QStringLiteral("e")),
                                                 {QStringLiteral("x.py"), QStringLiteral("y.py")});
        QCOMPARE(all, QByteArray("x.py") + '\0' + sha1("x = 1\n").toHex() + '\n' + "y.py" + '\0' +
                          sha1("y = 2\n").toHex() + '\n');
    }

    // The C++ macro index takes its key on a pool thread while the Python files hold the
    // pool's other threads: digestAll there must not wait for the pool (it waited until they
    // were done, with its own thread idle).
    void digestAllOnAPoolThreadDoesNotWaitForThePool()
    {
        test::writeFile(m_temp.filePath(QStringLiteral("f/x.py")), "x = 1\n");
        test::writeFile(m_temp.filePath(QStringLiteral("f/y.py")), "y = 2\n");
        FileDigests digests(QString(), 0);
        QThreadPool *pool = QThreadPool::globalInstance();
        const int threads = pool->maxThreadCount();
        pool->setMaxThreadCount(2);
        QSemaphore digested;
        QFuture<QByteArray> all = QtConcurrent::run([&] {
            QByteArray out = digests.digestAll(m_temp.filePath(QStringLiteral("f")),
                                               {QStringLiteral("x.py"), QStringLiteral("y.py")});
            digested.release();
            return out;
        });
        // The other thread is busy, as a map over files holds it, until the digests are there
        // (or 10 s have passed).
        const QList<bool> waited = QtConcurrent::blockingMapped<QList<bool>>(
            QList<int>{1},
            std::function<bool(int)>([&](int) { return digested.tryAcquire(1, 10000); }));
        QVERIFY2(waited.value(0), "the digests waited for the pool's busy thread");
        QCOMPARE(all.result(), QByteArray("x.py") + '\0' + sha1("x = 1\n").toHex() + '\n' + "y.py" +
                                   '\0' + sha1("y = 2\n").toHex() + '\n');
        pool->setMaxThreadCount(threads);
    }

    void opensslsSha1GivesQtsDigests()
    {
        // Keys written before the change of implementation stay valid: the same digests.
        QByteArray large(3 * 1024 * 1024 + 17, Qt::Uninitialized);
        for (qsizetype i = 0; i < large.size(); ++i)
            large[i] = char((i * 131) ^ (i >> 7));
        for (const QByteArray &bytes :
             {QByteArray(), QByteArray("x = 1\n"), QByteArray(64, 'a'), large}) {
            QCOMPARE(Sha1::hash(bytes), QCryptographicHash::hash(bytes, QCryptographicHash::Sha1));
            Sha1 parts; // in pieces, an empty one among them
            QCryptographicHash qt(QCryptographicHash::Sha1);
            for (qsizetype at = 0, step = 1; at < bytes.size(); at += step, step = step * 3 + 1) {
                parts.addData(QByteArrayView(bytes).sliced(at, std::min(step, bytes.size() - at)));
                parts.addData({});
                qt.addData(QByteArrayView(bytes).sliced(at, std::min(step, bytes.size() - at)));
            }
            QCOMPARE(parts.result(), qt.result());
        }
    }
};

QTEST_GUILESS_MAIN(TestFileDigests)
#include "tst_filedigests.moc"
