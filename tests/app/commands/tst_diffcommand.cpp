// `rosarch diff` end to end: two git revisions of a workspace the test creates (the second
// adds a subscriber and renames a topic), two artifact folders, and usage errors.
#include "support/chatrepo.h"
#include "support/testsupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

namespace {
using rosarch::test::Run;
using rosarch::test::runRosarch;
using rosarch::test::chat::git;

QStringList changes(const QString &json)
{
    QStringList out;
    const QJsonArray list =
        QJsonDocument::fromJson(json.toUtf8()).object().value(QStringLiteral("changes")).toArray();
    for (const auto &v : list) {
        const QJsonObject c = v.toObject();
        out << QStringLiteral("%1 %2 [%3] %4 -> %5")
                   .arg(c.value(QStringLiteral("change")).toString(),
                        c.value(QStringLiteral("element")).toString(),
                        c.value(QStringLiteral("scope")).toString(),
                        c.value(QStringLiteral("before")).toString(),
                        c.value(QStringLiteral("after")).toString());
    }
    return out;
}

// What the second revision changed: the hearer's new subscription (its port, its topic and
// who subscribes to it), and the rename of /chatter, in both classes and in the launch file.
const QStringList kExpected{
    QStringLiteral("renamed port [Hearer] subscriber chatter (std_msgs/msg/String) -> "
                   "subscriber chat (std_msgs/msg/String)"),
    QStringLiteral("added port [Hearer]  -> subscriber clock (rosgraph_msgs/msg/Clock)"),
    QStringLiteral("renamed port [Speaker] publisher chatter (std_msgs/msg/String) -> "
                   "publisher chat (std_msgs/msg/String)"),
    QStringLiteral("renamed topic [ws/src/chat/launch/chat.launch.py] /chatter -> /chat"),
    QStringLiteral("added topic [ws/src/chat/launch/chat.launch.py]  -> /clock "
                   "(rosgraph_msgs/msg/Clock)"),
    QStringLiteral("added connection [ws/src/chat/launch/chat.launch.py]  -> /hearer "
                   "subscribes to topic /clock")};
} // namespace

class TestDiffCommand : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_repo.isValid());
        QVERIFY(rosarch::test::chat::createRepository(m_repo.path()));
    }

    void twoRevisions()
    {
        const Run r =
            runRosarch({QStringLiteral("diff"), m_repo.path(), QStringLiteral("--rev"),
                        QStringLiteral("HEAD~1"), QStringLiteral("--rev"), QStringLiteral("HEAD"),
                        QStringLiteral("--format"), QStringLiteral("json")});
        QVERIFY2(r.exitCode == 1, qPrintable(r.err)); // 1: there are changes
        QCOMPARE(changes(r.out), kExpected);
        // A subfolder of the repository works as the workspace too (paths stay relative).
        const Run sub =
            runRosarch({QStringLiteral("diff"), QDir(m_repo.path()).filePath(QStringLiteral("ws")),
                        QStringLiteral("--rev"), QStringLiteral("HEAD~1"), QStringLiteral("--rev"),
                        QStringLiteral("HEAD")});
        QCOMPARE(sub.exitCode, 1);
        QVERIFY2(sub.out.startsWith(
                     QLatin1String("6 changes: 3 added, 0 removed, 0 changed, 3 renamed.")),
                 qPrintable(sub.out));
        QVERIFY(sub.out.contains(QLatin1String("\nsrc/chat/launch/chat.launch.py:\n")));
        QVERIFY(sub.out.contains(QLatin1String("  ~ renamed topic /chatter -> /chat\n")));
        // One revision against itself: nothing, exit 0.
        const Run same =
            runRosarch({QStringLiteral("diff"), m_repo.path(), QStringLiteral("--rev"),
                        QStringLiteral("HEAD"), QStringLiteral("--rev"), QStringLiteral("HEAD")});
        QCOMPARE(same.exitCode, 0);
        QCOMPARE(same.out, QStringLiteral("No architecture changes.\n"));
    }

    void twoArtifactFolders()
    {
        QTemporaryDir outA, outB, old;
        QVERIFY(git(m_repo.path(), {QStringLiteral("worktree"), QStringLiteral("add"),
                                    QStringLiteral("-q"), QStringLiteral("--detach"),
                                    old.filePath(QStringLiteral("v1")), QStringLiteral("HEAD~1")}));
        QCOMPARE(
            runRosarch({QStringLiteral("recover"), old.filePath(QStringLiteral("v1")),
                        QStringLiteral("--out"), outA.path(), QStringLiteral("--no-decisions")})
                .exitCode,
            0);
        QCOMPARE(runRosarch({QStringLiteral("recover"), m_repo.path(), QStringLiteral("--out"),
                             outB.path(), QStringLiteral("--no-decisions")})
                     .exitCode,
                 0);
        const Run r = runRosarch({QStringLiteral("diff"), outA.path(), outB.path(),
                                  QStringLiteral("--format"), QStringLiteral("json")});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(changes(r.out), kExpected);
        git(m_repo.path(), {QStringLiteral("worktree"), QStringLiteral("remove"),
                            QStringLiteral("--force"), old.filePath(QStringLiteral("v1"))});
    }

    void usage()
    {
        QCOMPARE(runRosarch({QStringLiteral("diff"), m_repo.path()}).exitCode, 2);
        QCOMPARE(runRosarch({QStringLiteral("diff"), m_repo.path(), QStringLiteral("--rev"),
                             QStringLiteral("HEAD")})
                     .exitCode,
                 2);
        QCOMPARE(runRosarch({QStringLiteral("diff"), m_repo.path(), QStringLiteral("/no/where")})
                     .exitCode,
                 2);
        const Run bad = runRosarch({QStringLiteral("diff"), m_repo.path(), QStringLiteral("--rev"),
                                    QStringLiteral("no-such-rev"), QStringLiteral("--rev"),
                                    QStringLiteral("HEAD")});
        QCOMPARE(bad.exitCode, 3);
        QVERIFY(bad.err.contains(QLatin1String("git archive")));
    }

private:
    QTemporaryDir m_repo;
};

QTEST_GUILESS_MAIN(TestDiffCommand)
#include "tst_diffcommand.moc"
