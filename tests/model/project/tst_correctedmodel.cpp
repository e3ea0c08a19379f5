// The corrected model (blueprint §5): a project with one correction of each kind applied to
// tests/data/project_corrections gives exactly the expected artifacts; after a code change that
// shifts every id, each correction still lands on its own element or is listed as orphaned.
// Also: stable keys, and the project file's format, schema and error messages.
// Set ROSARCH_UPDATE_EXPECTED=1 to rewrite the expected files after a reviewed change.
#include "artifacts/artifactwriter.h"
#include "project/correctedmodel.h"
#include "support/testsupport.h"

#include <QDirIterator>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

QString caseDir()
{
    return test::dataDir(QStringLiteral("project_corrections"));
}

Project caseProject()
{
    Project p;
    QString error;
    if (!ProjectFile::read(QDir(caseDir()).filePath(QStringLiteral("rosarch.project.json")), &p,
                           &error))
        qWarning("%s", qPrintable(error));
    return p;
}

QString orphansText(const QList<Orphan> &orphans)
{
    QString out;
    for (const Orphan &o : orphans)
        out += QStringLiteral("%1 %2 %3 | %4 | %5\n")
                   .arg(o.source == Orphan::Source::Correction ? QStringLiteral("correction")
                                                               : QStringLiteral("decision"),
                        o.id, o.kind, o.reason, o.said);
    return out;
}

/// The artifacts of `recovery` compared with (or written to) `expectedDir`: the three JSON
/// artifacts and every ACD and CCD.
void compareArtifacts(const Recovery &recovery, const QString &expectedDir)
{
    QTemporaryDir out;
    QStringList written;
    QString error;
    QVERIFY2(ArtifactWriter::writeAll(recovery, out.path(), &written, &error), qPrintable(error));
    for (const QString &file : std::as_const(written)) {
        const QString rel = QDir(out.path()).relativeFilePath(file);
        if (rel.endsWith(QLatin1String(".puml")) || rel == QLatin1String("atomic_nodes.json") ||
            rel == QLatin1String("launch_dependencies.json") ||
            rel == QLatin1String("architecture.json"))
            test::compareOrUpdate(test::readFile(file), QDir(expectedDir).filePath(rel));
    }
}

const AtomicNode *nodeNamed(const Recovery &r, const QString &className)
{
    for (const AtomicNode &n : r.nodes.nodes)
        if (n.className == className)
            return &n;
    return nullptr;
}

const NodeInstance *instanceNamed(const Recovery &r, const QString &name)
{
    for (const NodeInstance &n : r.launch.nodes)
        if (n.nodeName == name)
            return &n;
    return nullptr;
}

} // namespace

class TestCorrectedModel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void stableKeysNameWhatTheCodeSays()
    {
        const Recovery r = recoverWorkspace(QDir(caseDir()).filePath(QStringLiteral("ws")));
        const StableKeys keys(r);
        const AtomicNode *odometry = nodeNamed(r, QStringLiteral("OdometryNode"));
        QVERIFY(odometry);
        QCOMPARE(keys.keyOf(odometry->id),
                 QStringLiteral("class:cart_base|cart_base.odometry.OdometryNode"));
        QCOMPARE(keys.idOf(keys.keyOf(odometry->id)), odometry->id);
        QCOMPARE(keys.keyOf(odometry->id + QStringLiteral("/s1")),
                 QStringLiteral("port:cart_base|cart_base.odometry.OdometryNode|subscriber|"
                                "wheel_ticks"));
        const NodeInstance *front = instanceNamed(r, QStringLiteral("front_bumper"));
        QVERIFY(front);
        QCOMPARE(keys.keyOf(front->id),
                 QStringLiteral("instance:src/cart_base/launch/cart.launch.py>"
                                "src/cart_base/launch/sensors.launch.xml|front_bumper"));
        // the part of sensors.launch.xml's CCD names the declaration, wherever it is included
        QVERIFY(keys.instancesOf(QStringLiteral("part:src/cart_base/launch/sensors.launch.xml|"
                                                "front_bumper"))
                    .contains(front->id));
        QVERIFY(keys.contains(QStringLiteral("topic:/odom")));
        QVERIFY(keys.contains(QStringLiteral("include:src/cart_base/launch/cart.launch.py")));
        QCOMPARE(keys.keyOf(QStringLiteral("arc_999")), QString());
        QCOMPARE(StableKeys::family(QStringLiteral("topic:/odom")), QStringLiteral("topic"));
        QCOMPARE(StableKeys::family(QStringLiteral("arc_1")), QString());
    }

    void anInstanceCorrectionShowsInTheCcdOfItsLaunchFile()
    {
        // front_bumper is declared in sensors.launch.xml, included by cart.launch.py: renamed
        // there, it is renamed in that system and in sensors.launch.xml's own CCD
        const Recovery r = recoverWorkspace(QDir(caseDir()).filePath(QStringLiteral("ws")));
        Project p;
        Correction c;
        c.id = QStringLiteral("c1");
        c.kind = Correction::Kind::Rename;
        c.target = QStringLiteral("instance:src/cart_base/launch/cart.launch.py>"
                                  "src/cart_base/launch/sensors.launch.xml|front_bumper");
        c.newValue = QStringLiteral("left_bumper");
        p.corrections = {c};
        const CorrectedRecovery corrected = CorrectedModel::apply(r, p);
        QVERIFY(corrected.orphans.isEmpty());
        QStringList named;
        for (const QList<Composite> *list : {&corrected.recovery.architecture.composites,
                                             &corrected.recovery.architecture.classifiers})
            for (const Composite &composite : *list)
                for (const RosNodePart &part : composite.parts)
                    if (part.name.contains(QLatin1String("bumper")))
                        named << QStringLiteral("%1 %2").arg(composite.file, part.name);
        named.sort();
        QCOMPARE(named, QStringList({QStringLiteral("src/cart_base/launch/sensors.launch.xml "
                                                    "left_bumper"),
                                     QStringLiteral("src/cart_base/launch/sensors.launch.xml "
                                                    "left_bumper"),
                                     QStringLiteral("src/cart_base/launch/sensors.launch.xml "
                                                    "rear_bumper"),
                                     QStringLiteral("src/cart_base/launch/sensors.launch.xml "
                                                    "rear_bumper")}));
    }

    void identicalSiblingsGetOrdinals()
    {
        Recovery r;
        LaunchFileInstance lf;
        lf.id = QStringLiteral("lf1");
        lf.file = QStringLiteral("src/a/launch/a.launch.py");
        lf.nodes = {QStringLiteral("n1"), QStringLiteral("n2")};
        r.launch.instances = {lf};
        for (const QString &id : lf.nodes) {
            NodeInstance n;
            n.id = id;
            n.launchFileId = lf.id;
            n.execName = QStringLiteral("worker");
            r.launch.nodes.append(n);
        }
        const StableKeys keys(r);
        QCOMPARE(keys.keyOf(QStringLiteral("n1")),
                 QStringLiteral("instance:src/a/launch/a.launch.py|worker"));
        QCOMPARE(keys.keyOf(QStringLiteral("n2")),
                 QStringLiteral("instance:src/a/launch/a.launch.py|worker#2"));
        QCOMPARE(keys.instancesOf(QStringLiteral("part:src/a/launch/a.launch.py|worker#2")),
                 QStringList{QStringLiteral("n2")});
    }

    void oneCorrectionOfEachKindGivesTheExpectedArtifacts()
    {
        const Project project = caseProject();
        QSet<Correction::Kind> kinds;
        for (const Correction &c : project.corrections)
            kinds.insert(c.kind);
        QCOMPARE(kinds.size(), 10); // every kind there is
        const Recovery recovered =
            recoverWorkspace(QDir(caseDir()).filePath(QStringLiteral("ws")), project.launch);
        const CorrectedRecovery corrected = CorrectedModel::apply(recovered, project);
        QCOMPARE(orphansText(corrected.orphans), QString());
        QCOMPARE(corrected.decisions.size(), 1);
        compareArtifacts(corrected.recovery, QDir(caseDir()).filePath(QStringLiteral("corrected")));

        // spot checks of what the expected files hold
        const Recovery &r = corrected.recovery;
        const AtomicNode *safety = nodeNamed(r, QStringLiteral("SafetyMonitor"));
        QVERIFY(safety);
        QCOMPARE(safety->marks.provenance, Provenance::Suggested);
        QCOMPARE(safety->description,
                 QStringLiteral("Stops the cart when odometry reports a hazard."));
        QCOMPARE(safety->ports.size(), 4);
        QCOMPARE(safety->ports.last().marks.provenance, Provenance::Corrected);
        QVERIFY(nodeNamed(r, QStringLiteral("OdometryNode"))->marks.reviewed);
        QVERIFY(!instanceNamed(r, QStringLiteral("recorder")));
        QVERIFY(!instanceNamed(r, QStringLiteral("safety_monitor")));
        QCOMPARE(instanceNamed(r, QStringLiteral("safety"))->marks.provenance,
                 Provenance::Corrected);
        QCOMPARE(instanceNamed(r, QStringLiteral("watchdog"))->classId, safety->id);
        // the recovered model itself is untouched
        QVERIFY(instanceNamed(recovered, QStringLiteral("safety_monitor")));
        QCOMPARE(recovered.nodes.nodes,
                 recoverWorkspace(QDir(caseDir()).filePath(QStringLiteral("ws"))).nodes.nodes);
    }

    void afterTheIdsShiftNothingLandsElsewhere()
    {
        QTemporaryDir ws;
        test::copyTree(QDir(caseDir()).filePath(QStringLiteral("ws")), ws.path());
        test::copyTree(QDir(caseDir()).filePath(QStringLiteral("change")), ws.path());
        const Project project = caseProject();
        const Recovery before =
            recoverWorkspace(QDir(caseDir()).filePath(QStringLiteral("ws")), project.launch);
        Recovery after = recoverWorkspace(ws.path(), project.launch);
        // the change shifts the ids of the corrected class and instance
        QVERIFY(nodeNamed(before, QStringLiteral("OdometryNode"))->id !=
                nodeNamed(after, QStringLiteral("OdometryNode"))->id);
        QVERIFY(instanceNamed(before, QStringLiteral("odometry"))->id !=
                instanceNamed(after, QStringLiteral("odometry"))->id);
        after.nodes.workspaceRoot.clear();

        const CorrectedRecovery corrected = CorrectedModel::apply(after, project);
        const QString orphans = orphansText(corrected.orphans);
        test::compareOrUpdate(orphans.toUtf8(), QDir(caseDir()).filePath(QStringLiteral(
                                                    "corrected_after_change/orphans.txt")));
        // the rename of safety_monitor and the group that names it by its new name
        QVERIFY2(orphans.contains(QLatin1String("correction c1 rename")), qPrintable(orphans));
        QVERIFY2(orphans.contains(QLatin1String("correction c10 group")), qPrintable(orphans));
        compareArtifacts(corrected.recovery,
                         QDir(caseDir()).filePath(QStringLiteral("corrected_after_change")));

        const Recovery &r = corrected.recovery;
        // the inserted class and instance carry nothing a person decided
        const AtomicNode *arbiter = nodeNamed(r, QStringLiteral("Arbiter"));
        QVERIFY(arbiter);
        QVERIFY(arbiter->marks.isDefault());
        QVERIFY(arbiter->description.isEmpty());
        for (const Port &p : arbiter->ports)
            QVERIFY(p.marks.isDefault());
        QVERIFY(instanceNamed(r, QStringLiteral("arbiter"))->marks.isDefault());
        // what still matches lands where it did
        QVERIFY(nodeNamed(r, QStringLiteral("OdometryNode"))->marks.reviewed);
        QCOMPARE(nodeNamed(r, QStringLiteral("SafetyMonitor"))->description,
                 QStringLiteral("Stops the cart when odometry reports a hazard."));
        QVERIFY(instanceNamed(r, QStringLiteral("safety_supervisor"))->marks.isDefault());
        QVERIFY(!instanceNamed(r, QStringLiteral("recorder")));
        QVERIFY(instanceNamed(r, QStringLiteral("watchdog")));
        for (const Composite &c : r.architecture.composites)
            for (const RosNodePart &part : c.parts)
                QVERIFY2(part.subsystem.isEmpty(), qPrintable(part.name)); // the group is orphaned
    }

    void decisionsAreStoredByKeyAndBoundById()
    {
        const Recovery r = recoverWorkspace(QDir(caseDir()).filePath(QStringLiteral("ws")));
        const StableKeys keys(r);
        const AtomicNode *odometry = nodeNamed(r, QStringLiteral("OdometryNode"));
        SuggestionDecision d;
        d.kind = Suggestion::Kind::NameResolution;
        d.targetId = odometry->id + QStringLiteral("/p2");
        d.proposal = QStringLiteral("/cart/pose");
        SuggestionDecision k;
        QVERIFY(CorrectedModel::keyed(d, keys, &k));
        QCOMPARE(k.targetId, QStringLiteral("port:cart_base|cart_base.odometry.OdometryNode|"
                                            "publisher|self.frame_prefix() + '/pose'"));
        SuggestionDecision b;
        QString reason;
        QVERIFY(CorrectedModel::bound(k, keys, &b, &reason));
        QCOMPARE(b, d);
        k.targetId = QStringLiteral("class:cart_base|cart_base.gone.Gone");
        QVERIFY(!CorrectedModel::bound(k, keys, &b, &reason));
        QVERIFY(reason.contains(QLatin1String("class:cart_base|cart_base.gone.Gone")));

        // an accepted name of an expression port is applied and marked as suggested
        Project p;
        SuggestionDecision accepted;
        QVERIFY(CorrectedModel::keyed(d, keys, &accepted));
        accepted.status = Suggestion::Status::Accepted;
        p.decisions = {accepted};
        const CorrectedRecovery c = CorrectedModel::apply(r, p);
        const Port &port = nodeNamed(c.recovery, QStringLiteral("OdometryNode"))->ports.at(2);
        QCOMPARE(port.name, QStringLiteral("/cart/pose"));
        QCOMPARE(port.marks.provenance, Provenance::Suggested);
    }

    void theProjectFileRoundTripsByteForByte()
    {
        const QString file = QDir(caseDir()).filePath(QStringLiteral("rosarch.project.json"));
        Project p;
        QString error;
        QVERIFY2(ProjectFile::read(file, &p, &error), qPrintable(error));
        QCOMPARE(p.corrections.size(), 13);
        QCOMPARE(p.launch.rootFile, QStringLiteral("src/cart_base/launch/cart.launch.py"));
        QCOMPARE(p.nextCorrectionId(), QStringLiteral("c14"));
        QTemporaryDir dir;
        const QString copy = dir.filePath(QStringLiteral("p.json"));
        QVERIFY2(ProjectFile::write(copy, p, &error), qPrintable(error));
        Project again;
        QVERIFY2(ProjectFile::read(copy, &again, &error), qPrintable(error));
        QCOMPARE(again, p);
        QCOMPARE(ProjectFile::toJson(again), test::readFile(copy));
        QVERIFY(!ProjectFile::toJson(p).contains("api_key"));
        QCOMPARE(ProjectFile::autosavePath(copy), dir.filePath(QStringLiteral(".p.json.autosave")));
    }

    void expectedExternalsRoundTripAsVersion3()
    {
        Project p;
        QCOMPARE(p.version(), 1);
        p.launch.externals = {{QStringLiteral("/scan"), false, QStringLiteral("lidar driver")},
                              {QStringLiteral("/**/debug/*"), true, QString()}};
        QCOMPARE(p.version(), 3);
        const QByteArray json = ProjectFile::toJson(p);
        QVERIFY(json.contains("\"direction\": \"input\""));
        QVERIFY(json.contains("\"direction\": \"output\""));
        Project again;
        QString error;
        QVERIFY2(ProjectFile::fromJson(json, &again, &error), qPrintable(error));
        QCOMPARE(again.launch.externals, p.launch.externals);
        QCOMPARE(again, p);
    }

    void aBadProjectFileGetsAClearMessage_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("message");
        QTest::newRow("not json") << QByteArray("{\n  \"version\": 1,\n  oops\n}")
                                  << QStringLiteral("not valid JSON (line 3");
        QTest::newRow("not an object")
            << QByteArray("[1, 2]") << QStringLiteral("top level is not an object");
        QTest::newRow("newer") << QByteArray("{\"version\": 7, \"whatever\": {}}")
                               << QStringLiteral("newer rosarch (project version 7");
        QTest::newRow("no version") << QByteArray("{\"corrections\": []}")
                                    << QStringLiteral("missing required property \"version\"");
        QTest::newRow("unknown kind")
            << QByteArray("{\"version\": 1, \"corrections\": [{\"id\": \"c1\", \"kind\": "
                          "\"paint\", \"target\": \"topic:/a\"}]}")
            << QStringLiteral("$.corrections[0].kind");
        QTest::newRow("unknown field") << QByteArray("{\"version\": 1, \"secret\": \"sk-1\"}")
                                       << QStringLiteral("unexpected property \"secret\"");
        QTest::newRow("duplicate id")
            << QByteArray("{\"version\": 1, \"corrections\": [{\"id\": \"c1\", \"kind\": "
                          "\"review\", \"target\": \"topic:/a\"}, {\"id\": \"c1\", \"kind\": "
                          "\"review\", \"target\": \"topic:/b\"}]}")
            << QStringLiteral("two corrections have the id c1");
        QTest::newRow("external not fully qualified")
            << QByteArray("{\"version\": 3, \"externals\": [{\"name\": \"scan\", "
                          "\"direction\": \"input\"}]}")
            << QStringLiteral("the expected external scan is not a fully qualified name");
        QTest::newRow("external without direction")
            << QByteArray("{\"version\": 3, \"externals\": [{\"name\": \"/scan\"}]}")
            << QStringLiteral("missing required property \"direction\"");
        QTest::newRow("argument not text")
            << QByteArray("{\"version\": 1, \"launch\": {\"arguments\": {\"sim\": true}}}")
            << QStringLiteral("$.launch.arguments.sim: expected string");
    }

    void aBadProjectFileGetsAClearMessage()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("rosarch.project.json"));
        test::writeFile(file, content);
        Project p;
        p.launch.rootFile = QStringLiteral("kept.launch.py");
        QString error;
        QVERIFY(!ProjectFile::read(file, &p, &error));
        QVERIFY2(error.contains(message), qPrintable(error));
        QVERIFY2(error.startsWith(file), qPrintable(error));
        QCOMPARE(p.launch.rootFile, QStringLiteral("kept.launch.py")); // untouched on failure
        const QString kept = ProjectFile::keepUnreadable(file);
        QVERIFY(kept.startsWith(file + QStringLiteral(".unreadable-")));
        QCOMPARE(test::readFile(kept), content);
    }

    void theSchemaInTheRepositoryIsTheOneChecked()
    {
        const QByteArray repo =
            test::readFile(QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                               .filePath(QStringLiteral("schemas/project.schema.json")));
        QVERIFY(!repo.isEmpty());
        QCOMPARE(QJsonDocument(ProjectFile::schema()), QJsonDocument::fromJson(repo));
    }
};

QTEST_GUILESS_MAIN(TestCorrectedModel)
#include "tst_correctedmodel.moc"
