// End-to-end: the real `rosarch eval` on tests/data/eval_models (a reference and a recovered
// model broken on purpose) and tests/data/eval_broken (a file that is no ACD or CCD).
#include "support/testsupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

namespace {
using rosarch::test::Run;
using rosarch::test::runRosarch;

QString models(const QString &sub)
{
    return rosarch::test::dataDir(QStringLiteral("eval_models/") + sub);
}

QStringList eval(const QStringList &more)
{
    return QStringList{QStringLiteral("eval"), QStringLiteral("--reference"),
                       models(QStringLiteral("reference")), QStringLiteral("--recovered"),
                       models(QStringLiteral("recovered"))} +
           more;
}

QJsonObject kindOf(const QJsonArray &kinds, const QString &kind)
{
    for (const QJsonValue &k : kinds)
        if (k.toObject().value(QStringLiteral("kind")).toString() == kind)
            return k.toObject();
    return {};
}
} // namespace

class TestEvalCommand : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void textReport()
    {
        const Run r = runRosarch(eval({}));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList lines = r.out.split(QLatin1Char('\n'));
        // Both levels, with the averages worked out by hand in tst_evaluator.
        QVERIFY(lines.contains(QStringLiteral("== ACD (AtomicClassifierDiagrams) ==")));
        QVERIFY(lines.contains(
            QStringLiteral("3 reference diagrams, 3 recovered: 2 matched, 1 missing, 1 extra")));
        QVERIFY2(lines.contains(QStringLiteral("all kinds                 10     1     4   0.909 "
                                               "0.714 0.800   0.611 0.611 0.611")),
                 qPrintable(r.out));
        QVERIFY(lines.contains(QStringLiteral(
            "message type               2     1     2   0.667 0.500 0.571   0.333 0.333 0.333")));
        QVERIFY(lines.contains(QStringLiteral("  Planner                  0     0     3   0.000 "
                                              "0.000 0.000   missing: no recovered diagram")));
        QVERIFY(r.out.contains(QStringLiteral("extra recovered diagram, not scored: Extra (")));
        QVERIFY(lines.contains(QStringLiteral("== CCD (ComposedClassifierDiagrams) ==")));
        QVERIFY(lines.contains(QStringLiteral(
            "all kinds                 10     3     6   0.769 0.625 0.690   0.769 0.625 0.690")));
        // The differences name the element and where it was read.
        QVERIFY(
            r.out.contains(QStringLiteral("    FP connection: client listener -> robot1/reset  (") +
                           models(QStringLiteral("recovered/ccd/demo.puml:21)"))));
        QVERIFY(r.out.contains(QStringLiteral("    FN RosNodePart: monitor  (") +
                               models(QStringLiteral("reference/ccd/demo.puml:13)"))));
        QCOMPARE(r.out.count(QRegularExpression(QStringLiteral("(?m)^    FP "))), 4);
        QCOMPARE(r.out.count(QRegularExpression(QStringLiteral("(?m)^    FN "))), 10);
        // Reader notes go to stderr, with the file.
        QVERIFY(r.err.contains(
            models(QStringLiteral("reference/acd/Talker.puml")) +
            QStringLiteral(
                ": note: line 9: type 'geometry_msgs/Twist' read as geometry_msgs/msg/Twist")));
        QVERIFY(!r.out.contains(QStringLiteral("note:")));
    }

    void jsonReport()
    {
        const Run r = runRosarch(eval({QStringLiteral("--json")}));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QJsonParseError error;
        const QJsonObject root = QJsonDocument::fromJson(r.out.toUtf8(), &error).object();
        QCOMPARE(error.error, QJsonParseError::NoError);
        const QJsonArray levels = root.value(QStringLiteral("levels")).toArray();
        QCOMPARE(levels.size(), 2);
        const QJsonObject acd = levels.at(0).toObject();
        QCOMPARE(acd.value(QStringLiteral("level")).toString(), QStringLiteral("acd"));
        const QJsonObject micro = acd.value(QStringLiteral("micro")).toObject();
        QCOMPARE(micro.value(QStringLiteral("tp")).toInt(), 10);
        QCOMPARE(micro.value(QStringLiteral("fp")).toInt(), 1);
        QCOMPARE(micro.value(QStringLiteral("fn")).toInt(), 4);
        QCOMPARE(micro.value(QStringLiteral("precision")).toDouble(), 0.9091);
        QCOMPARE(
            acd.value(QStringLiteral("macro")).toObject().value(QStringLiteral("f1")).toDouble(),
            0.6111);
        QCOMPARE(
            kindOf(acd.value(QStringLiteral("kinds")).toArray(), QStringLiteral("message_type"))
                .value(QStringLiteral("micro"))
                .toObject()
                .value(QStringLiteral("f1"))
                .toDouble(),
            0.5714);
        const QJsonArray extra = acd.value(QStringLiteral("extra_diagrams")).toArray();
        QCOMPARE(extra.size(), 1);
        QCOMPARE(extra.at(0).toObject().value(QStringLiteral("name")).toString(),
                 QStringLiteral("Extra"));

        const QJsonObject ccd = levels.at(1).toObject();
        const QJsonObject demo = ccd.value(QStringLiteral("diagrams")).toArray().at(0).toObject();
        QCOMPARE(demo.value(QStringLiteral("name")).toString(), QStringLiteral("demo"));
        QCOMPARE(demo.value(QStringLiteral("missing")).toBool(), false);
        const QJsonObject connection =
            kindOf(demo.value(QStringLiteral("kinds")).toArray(), QStringLiteral("connection"));
        const QJsonArray fn = connection.value(QStringLiteral("false_negatives")).toArray();
        QCOMPARE(fn.size(), 2);
        QCOMPARE(fn.at(0).toObject().value(QStringLiteral("value")).toString(),
                 QStringLiteral("server listener -> robot1/reset"));
        QCOMPARE(fn.at(0).toObject().value(QStringLiteral("line")).toInt(), 22);

        // The reader's notes are in the JSON instead of on stderr.
        QVERIFY(r.err.isEmpty());
        bool found = false;
        for (const QJsonValue &d : root.value(QStringLiteral("recovered"))
                                       .toObject()
                                       .value(QStringLiteral("diagrams"))
                                       .toArray())
            for (const QJsonValue &n : d.toObject().value(QStringLiteral("notes")).toArray())
                found = found ||
                        n.toString() == QLatin1String("line 21: colour says 'client' but the arrow "
                                                      "ends say 'server'; the colour is read");
        QVERIFY(found);
    }

    void levelOptionAndSingleFiles()
    {
        const Run r =
            runRosarch({QStringLiteral("eval"), QStringLiteral("--level"), QStringLiteral("ccd"),
                        QStringLiteral("--json"), QStringLiteral("--reference"),
                        models(QStringLiteral("reference")), QStringLiteral("--recovered"),
                        models(QStringLiteral("recovered/ccd/demo.puml"))});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonArray levels = QJsonDocument::fromJson(r.out.toUtf8())
                                      .object()
                                      .value(QStringLiteral("levels"))
                                      .toArray();
        QCOMPARE(levels.size(), 1);
        QCOMPARE(levels.at(0).toObject().value(QStringLiteral("level")).toString(),
                 QStringLiteral("ccd"));
        QCOMPARE(levels.at(0)
                     .toObject()
                     .value(QStringLiteral("micro"))
                     .toObject()
                     .value(QStringLiteral("tp"))
                     .toInt(),
                 10);

        // The reference against itself: everything 1.
        const Run same =
            runRosarch({QStringLiteral("eval"), QStringLiteral("--reference"),
                        models(QStringLiteral("reference")), QStringLiteral("--recovered"),
                        models(QStringLiteral("reference"))});
        QCOMPARE(same.exitCode, 0);
        QCOMPARE(same.out.count(QStringLiteral("1.000 1.000 1.000   1.000 1.000 1.000")),
                 18); // 8 kinds + all kinds, two levels
        QVERIFY(!same.out.contains(QStringLiteral("Differences")));
    }

    void unparseableInputsExitOne()
    {
        const Run r =
            runRosarch({QStringLiteral("eval"), QStringLiteral("--reference"),
                        rosarch::test::dataDir(QStringLiteral("eval_broken")),
                        QStringLiteral("--recovered"), models(QStringLiteral("recovered"))});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains(rosarch::test::dataDir(QStringLiteral("eval_broken/junk.puml")) +
                               QStringLiteral(" is neither an ACD nor a CCD")));
        QVERIFY(
            r.err.contains(QStringLiteral("junk.puml: warning: line 2: cannot read 'class Foo'")));
        // The readable diagrams are still evaluated.
        QVERIFY(r.out.contains(QStringLiteral("  Planner                  0     0     3   0.000 "
                                              "0.000 0.000   missing: no recovered diagram")));
    }

    void usageErrorsExitTwo_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("no recovered")
            << QStringList{QStringLiteral("eval"), QStringLiteral("--reference"),
                           models(QStringLiteral("reference"))}
            << QStringLiteral("eval needs --reference and --recovered");
        QTest::newRow("no such path")
            << QStringList{QStringLiteral("eval"), QStringLiteral("--reference"),
                           models(QStringLiteral("nope")), QStringLiteral("--recovered"),
                           models(QStringLiteral("recovered"))}
            << QStringLiteral("no such file or folder: ") + models(QStringLiteral("nope"));
        QTest::newRow("bad level") << eval({QStringLiteral("--level"), QStringLiteral("arc")})
                                   << QStringLiteral("--level expects acd or ccd, got 'arc'");
        QTest::newRow("unknown option")
            << eval({QStringLiteral("--frobnicate")}) << QStringLiteral("frobnicate");
    }

    void usageErrorsExitTwo()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const Run r = runRosarch(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }

    void listedInTheUsage()
    {
        const Run r = runRosarch({QStringLiteral("--help")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(QStringLiteral("rosarch eval --reference <dir|file> --recovered "
                                              "<dir|file> [--level acd|ccd] [--json]")));
    }
};

QTEST_GUILESS_MAIN(TestEvalCommand)
#include "tst_evalcommand.moc"
