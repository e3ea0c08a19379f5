// `rosarch site` as a person runs it: the site of a workspace, the same bytes from two runs,
// source links filled from git, and a clear message (never a crash) for bad input.
#include "support/testsupport.h"

#include <QDirIterator>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

QString exampleWorkspace()
{
    return QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
        .filePath(QStringLiteral("resources/example_ws"));
}

QMap<QString, QByteArray> tree(const QString &dir)
{
    QMap<QString, QByteArray> files;
    QDirIterator it(dir, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        files.insert(QDir(dir).relativeFilePath(path), test::readFile(path));
    }
    return files;
}

} // namespace

class TestSiteCommand : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void writesTheSameSiteTwice()
    {
        QTemporaryDir dir;
        const QString a = dir.filePath(QStringLiteral("a"));
        const QString b = dir.filePath(QStringLiteral("b"));
        const test::Run first =
            test::runRosarch({QStringLiteral("site"), exampleWorkspace(), QStringLiteral("--out"),
                              a, QStringLiteral("--title"), QStringLiteral("Example <robot>")});
        QVERIFY2(first.exitCode == 0, qPrintable(first.err));
        QVERIFY2(first.out.contains(QLatin1String("Wrote ")), qPrintable(first.out));
        const test::Run second =
            test::runRosarch({QStringLiteral("site"), exampleWorkspace(), QStringLiteral("--out"),
                              b, QStringLiteral("--title"), QStringLiteral("Example <robot>")});
        QVERIFY2(second.exitCode == 0, qPrintable(second.err));
        const QMap<QString, QByteArray> one = tree(a);
        const QMap<QString, QByteArray> two = tree(b);
        QVERIFY(one.size() > 30);
        QCOMPARE(one.keys(), two.keys());
        for (auto it = one.cbegin(); it != one.cend(); ++it)
            QVERIFY2(it.value() == two.value(it.key()), qPrintable(it.key()));
        const QByteArray index = one.value(QStringLiteral("index.html"));
        QVERIFY(index.contains("<title>Example &lt;robot&gt;</title>"));
        QVERIFY(index.contains("href=\"systems/robot.html\""));
        // Written again into its own folder: nothing changes, nothing is refused.
        const test::Run third =
            test::runRosarch({QStringLiteral("site"), exampleWorkspace(), QStringLiteral("--out"),
                              a, QStringLiteral("--title"), QStringLiteral("Example <robot>")});
        QVERIFY2(third.exitCode == 0, qPrintable(third.err));
        QCOMPARE(tree(a), one);
    }

    void sourceLinksFromGit()
    {
        QProcess git;
        git.setWorkingDirectory(QStringLiteral(ROSARCH_SOURCE_DIR));
        git.start(QStringLiteral("git"), {QStringLiteral("rev-parse"), QStringLiteral("HEAD")});
        if (!git.waitForFinished(10000) || git.exitCode() != 0)
            QSKIP("the source tree is not a git repository");
        const QString head = QString::fromUtf8(git.readAllStandardOutput()).trimmed();
        QTemporaryDir dir;
        const test::Run run = test::runRosarch(
            {QStringLiteral("site"), exampleWorkspace(), QStringLiteral("--out"), dir.path(),
             QStringLiteral("--source-url"),
             QStringLiteral("https://example.org/rosarch/blob/{commit}/{path}#L{line}")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const QByteArray page = test::readFile(dir.filePath(QStringLiteral("index.html")));
        QVERIFY(!page.isEmpty());
        const QMap<QString, QByteArray> files = tree(dir.path());
        const QByteArray expected = "href=\"https://example.org/rosarch/blob/" + head.toUtf8() +
                                    "/resources/example_ws/src/";
        int linked = 0;
        for (const QByteArray &data : files)
            linked += data.contains(expected) ? 1 : 0;
        QVERIFY2(linked > 10, expected.constData());
    }

    void badInputGetsAMessage()
    {
        QTemporaryDir dir;
        // No --out.
        test::Run r = test::runRosarch({QStringLiteral("site"), exampleWorkspace()});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QLatin1String("site needs --out")), qPrintable(r.err));
        // No such workspace.
        r = test::runRosarch({QStringLiteral("site"), dir.filePath(QStringLiteral("missing")),
                              QStringLiteral("--out"), dir.filePath(QStringLiteral("s1"))});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QLatin1String("Not a folder")), qPrintable(r.err));
        // An empty workspace.
        const QString empty = dir.filePath(QStringLiteral("empty"));
        QVERIFY(QDir().mkpath(empty));
        r = test::runRosarch({QStringLiteral("site"), empty, QStringLiteral("--out"),
                              dir.filePath(QStringLiteral("s2"))});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QLatin1String("no ROS 2 package")), qPrintable(r.err));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("s2"))));
        // A folder that cannot be written.
        r = test::runRosarch({QStringLiteral("site"), exampleWorkspace(), QStringLiteral("--out"),
                              QStringLiteral("/proc/rosarch-site")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QLatin1String("Cannot create the folder")), qPrintable(r.err));
        // A folder with someone's files in it.
        test::writeFile(dir.filePath(QStringLiteral("mine/notes.txt")), "keep");
        r = test::runRosarch({QStringLiteral("site"), exampleWorkspace(), QStringLiteral("--out"),
                              dir.filePath(QStringLiteral("mine"))});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QLatin1String("not empty")), qPrintable(r.err));
        QCOMPARE(tree(dir.filePath(QStringLiteral("mine"))).size(), 1);
        // A source pattern without {path}; one with {commit} outside any repository.
        r = test::runRosarch({QStringLiteral("site"), exampleWorkspace(), QStringLiteral("--out"),
                              dir.filePath(QStringLiteral("s3")), QStringLiteral("--source-url"),
                              QStringLiteral("https://example.org/x")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QLatin1String("{path}")), qPrintable(r.err));
        const QString copy = dir.filePath(QStringLiteral("copy"));
        test::copyTree(exampleWorkspace(), copy);
        r = test::runRosarch({QStringLiteral("site"), copy, QStringLiteral("--out"),
                              dir.filePath(QStringLiteral("s4")), QStringLiteral("--source-url"),
                              QStringLiteral("https://example.org/{commit}/{path}")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QLatin1String("give --commit")), qPrintable(r.err));
        r = test::runRosarch({QStringLiteral("site"), copy, QStringLiteral("--out"),
                              dir.filePath(QStringLiteral("s4")), QStringLiteral("--source-url"),
                              QStringLiteral("https://example.org/{commit}/{path}"),
                              QStringLiteral("--commit"), QStringLiteral("v1.0")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(test::readFile(dir.filePath(QStringLiteral("s4/index.html"))).size() > 0);
    }
};

QTEST_GUILESS_MAIN(TestSiteCommand)
#include "tst_sitecommand.moc"
