// The recovered model scored against the hand-checked expected diagrams of each fixture case
// (tests/data/<case>/expected/{acd,ccd}), and deliberately broken variants of the
// compose_system CCDs (tests/data/compose_system/broken) scored below 1.0 on exactly the
// elements that were broken.
#include "evaluation/evaluator.h"
#include "evaluation/recovereddiagrams.h"
#include "pipeline/recovery.h"
#include "plantuml/plantumlreader.h"
#include "plantuml/umlmodel.h"
#include "support/testsupport.h"

#include <QtTest>

using namespace rosarch;

namespace {

QStringList differences(const LevelEvaluation &level)
{
    QStringList out;
    for (const DiagramEvaluation &d : level.diagrams)
        for (const KindEvaluation &k : d.kinds) {
            for (const UmlElement &e : k.falsePositives)
                out << QStringLiteral("FP %1: %2").arg(e.kind, e.value);
            for (const UmlElement &e : k.falseNegatives)
                out << QStringLiteral("FN %1: %2").arg(e.kind, e.value);
        }
    out.sort();
    return out;
}

} // namespace

class TestModelEvaluation : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void recoveredModelScoresOne_data()
    {
        QTest::addColumn<QString>("caseName");
        QTest::addColumn<QString>("workspace");
        QTest::newRow("compose_system")
            << "compose_system" << test::dataDir(QStringLiteral("compose_system/ws"));
        // one launch file per ROS 2 launch-time rule (blueprint §1), expected CCDs hand-checked
        QTest::newRow("ros_rules") << "ros_rules" << test::dataDir(QStringLiteral("ros_rules/ws"));
        QTest::newRow("example_ws") << "example_ws"
                                    << QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                                           .filePath(QStringLiteral("resources/example_ws"));
    }

    void recoveredModelScoresOne()
    {
        QFETCH(QString, caseName);
        QFETCH(QString, workspace);
        const Recovery r = recoverWorkspace(workspace);
        const QList<UmlDiagram> recovered = recoveredDiagrams(r.nodes, r.architecture);
        for (const QString &level : {QStringLiteral("acd"), QStringLiteral("ccd")}) {
            const QString dir = test::dataDir(caseName + QStringLiteral("/expected/") + level);
            if (!QFileInfo(dir).isDir())
                continue;
            UmlModel reference;
            QString error;
            QVERIFY2(UmlModel::load(dir, &reference, &error), qPrintable(error));
            const UmlLevel l = level == QLatin1String("acd") ? UmlLevel::Acd : UmlLevel::Ccd;
            QVERIFY(!reference.ofLevel(l).isEmpty());
            const LevelEvaluation e = Evaluator::evaluateLevel(reference.ofLevel(l), recovered, l);
            QVERIFY2(differences(e).isEmpty(), qPrintable(differences(e).join(QLatin1Char('\n'))));
            QCOMPARE(e.micro.f1, 1.0);
            QCOMPARE(e.macro.f1, 1.0);
            QVERIFY(e.extra.isEmpty());
            QVERIFY(e.micro.tp > 10);
        }
    }

    void brokenVariantsScoreBelowOne_data()
    {
        QTest::addColumn<QString>("broken");
        QTest::addColumn<QString>("reference");
        QTest::addColumn<QStringList>("expected");
        QTest::newRow("wrong boundary type")
            << "system_wrong_boundary_type"
            << "system"
            << QStringList{
                   QStringLiteral("FN boundary_port: (out, vision_msgs/msg/Detection2DArray)"),
                   QStringLiteral("FP boundary_port: (out, vision_msgs/msg/Detection3DArray)"),
                   // the delegation's end is reduced to the boundary port's type
                   QStringLiteral("FN connection: delegation vision -> "
                                  "boundary:out/vision_msgs/msg/Detection2DArray"),
                   QStringLiteral("FP connection: delegation vision -> "
                                  "boundary:out/vision_msgs/msg/Detection3DArray")};
        QTest::newRow("extra topic") << "system_extra_topic"
                                     << "system" << QStringList{QStringLiteral("FP topic: odom")};
        QTest::newRow("client drawn as server")
            << "system_client_as_server"
            << "system"
            << QStringList{QStringLiteral("FN connection: client commander -> navigate"),
                           QStringLiteral("FP connection: server commander -> navigate")};
        QTest::newRow("missing part")
            << "vision_missing_detector"
            << "vision"
            << QStringList{
                   QStringLiteral("FN part: detector"),
                   QStringLiteral("FN part_type: detector:Detector"),
                   QStringLiteral("FN namespace: (/, detector)"),
                   QStringLiteral("FN connection: subscribe rectified -> detector"),
                   QStringLiteral("FN connection: delegation detector -> "
                                  "boundary:out/vision_msgs/msg/Detection2DArray"),
                   QStringLiteral(
                       "FN connection: delegation detector -> boundary:out/std_srvs/srv/Trigger")};
        QTest::newRow("wrong namespace")
            << "vision_wrong_namespace"
            << "vision"
            << QStringList{QStringLiteral("FN namespace: (/, front_camera)"),
                           QStringLiteral("FP namespace: (cam, front_camera)")};
    }

    void brokenVariantsScoreBelowOne()
    {
        QFETCH(QString, broken);
        QFETCH(QString, reference);
        QFETCH(QStringList, expected);
        const QString refPath =
            test::dataDir(QStringLiteral("compose_system/expected/ccd/%1.puml").arg(reference));
        const QString brokenPath =
            test::dataDir(QStringLiteral("compose_system/broken/%1.puml").arg(broken));
        const QList<UmlDiagram> ref =
            PlantUmlReader::read(QString::fromUtf8(test::readFile(refPath)), refPath);
        const QList<UmlDiagram> rec =
            PlantUmlReader::read(QString::fromUtf8(test::readFile(brokenPath)), brokenPath);
        QCOMPARE(ref.size(), 1);
        QCOMPARE(rec.size(), 1);
        QCOMPARE(rec.first().name,
                 reference); // matched by the launch stem inside, not the file name
        const LevelEvaluation e = Evaluator::evaluateLevel(ref, rec, UmlLevel::Ccd);
        QCOMPARE(e.diagrams.size(), 1);
        QVERIFY(!e.diagrams.first().missing);
        expected.sort();
        QCOMPARE(differences(e), expected);
        QVERIFY(e.micro.f1 < 1.0);
        QVERIFY(e.micro.f1 > 0.5); // everything else still matches
    }

    void recoveredElementsCarryTheKeyOfWhatIsDrawn()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("compose_system/ws")));
        const QList<UmlDiagram> recovered = recoveredDiagrams(r.nodes, r.architecture);
        int ccdElements = 0;
        for (const UmlDiagram &d : recovered) {
            if (d.level != UmlLevel::Ccd)
                continue;
            const Composite *c = nullptr;
            for (const Composite *rep : r.architecture.representatives())
                if (rep->stem == d.name)
                    c = rep;
            QVERIFY2(c, qPrintable(d.name));
            for (const UmlElement &e : d.elements) {
                ++ccdElements;
                const QString kind = e.key.section(QLatin1Char(':'), 0, 0);
                const QString id = e.key.section(QLatin1Char(':'), 1);
                if (e.kind == QLatin1String("part") || e.kind == QLatin1String("part_type") ||
                    e.kind == QLatin1String("namespace")) {
                    QCOMPARE(kind, QStringLiteral("part"));
                    QVERIFY(c->part(id));
                    if (e.kind == QLatin1String("part"))
                        QVERIFY2(e.value == c->part(id)->name ||
                                     c->part(id)->kind == RosNodePart::Kind::Launch,
                                 qPrintable(e.value + QLatin1Char(' ') + e.key));
                } else if (e.kind == QLatin1String("boundary_port")) {
                    QCOMPARE(kind, QStringLiteral("boundary"));
                    QVERIFY(c->boundaryPort(id));
                } else if (e.kind == QLatin1String("connection")) {
                    QCOMPARE(kind, QStringLiteral("connection"));
                    QVERIFY(id.toInt() >= 0 && id.toInt() < c->connections.size());
                } else {
                    QCOMPARE(kind, QStringLiteral("channel"));
                    QVERIFY(c->channel(id));
                    QVERIFY2(c->channel(id)->name.endsWith(e.value), qPrintable(e.value));
                }
            }
        }
        QVERIFY(ccdElements > 20);

        // A reference without the detector: what the recovered model has in excess points at
        // the detector's part and its connections, so the GUI can mark them where drawn.
        const QString brokenPath =
            test::dataDir(QStringLiteral("compose_system/broken/vision_missing_detector.puml"));
        const LevelEvaluation e = Evaluator::evaluateLevel(
            PlantUmlReader::read(QString::fromUtf8(test::readFile(brokenPath)), brokenPath),
            recovered, UmlLevel::Ccd);
        QCOMPARE(e.diagrams.size(), 1);
        const Composite *vision = nullptr;
        for (const Composite *rep : r.architecture.representatives())
            if (rep->stem == QLatin1String("vision"))
                vision = rep;
        QVERIFY(vision);
        QString detectorKey;
        for (const RosNodePart &p : vision->parts)
            if (p.name == QLatin1String("detector"))
                detectorKey = QStringLiteral("part:") + p.id;
        QStringList extraParts;
        int extraConnections = 0;
        for (const KindEvaluation &k : e.diagrams.first().kinds)
            for (const UmlElement &fp : k.falsePositives) {
                QVERIFY2(!fp.key.isEmpty(), qPrintable(fp.value));
                if (fp.kind == QLatin1String("part"))
                    extraParts << fp.key;
                if (fp.kind == QLatin1String("connection"))
                    ++extraConnections;
            }
        QCOMPARE(extraParts, QStringList{detectorKey});
        QCOMPARE(extraConnections, 3);
    }
};

QTEST_GUILESS_MAIN(TestModelEvaluation)
#include "tst_modelevaluation.moc"
