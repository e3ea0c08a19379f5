// Accepted subsystem groupings as nested composites: the pure model step on
// tests/data/compose_system, the CCD writer's <<Subsystem>> blocks read back and scored
// against the ungrouped expected CCDs, the diagram's subsystem clusters, and the path from an
// accepted suggestion in the Document to the drawn and exported architecture (with undo).
#include "app/mainwindow.h"
#include "compose/subsystemgrouping.h"
#include "diagram/diagrambuilder.h"
#include "document/document.h"
#include "evaluation/evaluator.h"
#include "plantuml/ccdwriter.h"
#include "plantuml/plantumlreader.h"
#include "project/project.h"
#include "suggestions/suggestionengine.h"
#include "support/acceptedwait.h"
#include "support/guifixture.h"
#include "support/testsupport.h"
#include "widgets/diagram/diagrampanel.h"

#include <QDirIterator>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

QString exampleWorkspace()
{
    return QFileInfo(QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                         .filePath(QStringLiteral("resources/example_ws")))
        .canonicalFilePath();
}

/// "composite/part=subsystem" for every grouped part, sorted.
QStringList grouped(const Architecture &arch)
{
    QStringList out;
    for (const Composite &c : arch.composites)
        for (const RosNodePart &p : c.parts)
            if (!p.subsystem.isEmpty())
                out << QStringLiteral("%1/%2=%3").arg(c.instanceId, p.id, p.subsystem);
    out.sort();
    return out;
}

/// The instance ids of the parts in subsystem `name`, sorted.
QStringList membersOf(const Architecture &arch, const QString &name)
{
    QStringList out;
    for (const Composite &c : arch.composites)
        for (const RosNodePart &p : c.parts)
            if (p.subsystem == name)
                out << p.instanceId;
    out.sort();
    return out;
}

/// The aliases of the <<RosNodePart>>s written inside the <<Subsystem>> block labelled `name`
/// (every block of that label, in order); empty when there is none.
QStringList partsInBlock(const QString &ccd, const QString &name)
{
    QStringList out;
    const QStringList lines = ccd.split(QLatin1Char('\n'));
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString &line = lines.at(i);
        if (!line.contains(QStringLiteral("component \"%1\" as sub_").arg(name)) ||
            !line.endsWith(QLatin1String("<<Subsystem>> {")))
            continue;
        const QString close = line.left(line.indexOf(QLatin1Char('c'))) + QLatin1Char('}');
        for (++i; i < lines.size() && lines.at(i) != close; ++i) {
            const QString &inner = lines.at(i);
            if (inner.contains(QLatin1String("<<RosNodePart>>")))
                out << inner.section(QLatin1String(" as "), 1).section(QLatin1Char(' '), 0, 0);
        }
    }
    return out;
}

QStringList clusterOfNodes(const LayoutGraph &g, const QString &clusterId)
{
    QStringList out;
    for (const LayoutNode &n : g.nodes)
        if (n.cluster == clusterId)
            out << n.key;
    out.sort();
    return out;
}

QStringList exportedCcds(MainWindow &w, const QString &folder)
{
    QDir(folder).removeRecursively();
    if (!w.exportArtifactsTo(folder))
        return {};
    QStringList texts;
    QDirIterator it(folder, {QStringLiteral("*.puml")}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        if (path.contains(QLatin1String("/ccd/")))
            texts << QString::fromUtf8(test::readFile(path));
    }
    return texts;
}

} // namespace

class TestSubsystemGrouping : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_home;
    Architecture m_arch;
    const QList<SubsystemGroup> m_groups = {
        {QStringLiteral("perception"),
         {QStringLiteral("n3"), QStringLiteral("n4"), QStringLiteral("n7")},
         QStringLiteral("lf1")},
        {QStringLiteral("planning"), {QStringLiteral("n9"), QStringLiteral("n10")}, QString()},
        // n4 is perception's already (first wins); n8 is free.
        {QStringLiteral("detection"),
         {QStringLiteral("n4"), QStringLiteral("n8")},
         QStringLiteral("lf1")},
        // Not a root: a grouping applies below the root it was accepted for, so nothing here.
        {QStringLiteral("wrong_root"), {QStringLiteral("n1")}, QStringLiteral("lf2")},
    };

    QString expectedCcd(const QString &stem) const
    {
        return QString::fromUtf8(test::readFile(
            test::dataDir(QStringLiteral("compose_system/expected/ccd/%1.puml").arg(stem))));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_home.isValid());
        // Decisions are stored per workspace under the data location: keep them in m_home.
        qputenv("XDG_DATA_HOME", m_home.filePath(QStringLiteral("data")).toUtf8());
        qputenv("XDG_CONFIG_HOME", m_home.filePath(QStringLiteral("config")).toUtf8());
        // The application's names, so that the decisions file is the one `rosarch` reads.
        QCoreApplication::setOrganizationName(QStringLiteral("rosarch"));
        QCoreApplication::setApplicationName(QStringLiteral("rosarch"));
        m_arch = recoverWorkspace(test::dataDir(QStringLiteral("compose_system/ws"))).architecture;
        QVERIFY(m_arch.composite(QStringLiteral("lf1")));
        QVERIFY(m_arch.composite(QStringLiteral("lf3")));
    }

    void groupsMarkTheMemberPartsInTheirComposites()
    {
        const Architecture g = SubsystemGrouping::apply(m_arch, m_groups);
        QCOMPARE(grouped(g), (QStringList{QStringLiteral("lf1/part3=planning"),
                                          QStringLiteral("lf1/part4=planning"),
                                          QStringLiteral("lf2/part2=perception"),
                                          QStringLiteral("lf2/part3=perception"),
                                          QStringLiteral("lf3/part2=perception"),
                                          QStringLiteral("lf3/part3=detection")}));
        QCOMPARE(membersOf(g, QStringLiteral("perception")),
                 (QStringList{QStringLiteral("n3"), QStringLiteral("n4"), QStringLiteral("n7")}));
        QCOMPARE(membersOf(g, QStringLiteral("wrong_root")), QStringList());
        // Launch parts are never grouped, and nothing but `subsystem` changes.
        for (qsizetype i = 0; i < g.composites.size(); ++i) {
            const Composite &a = m_arch.composites.at(i), &b = g.composites.at(i);
            QCOMPARE(b.instanceId, a.instanceId);
            QCOMPARE(b.parts.size(), a.parts.size());
            for (qsizetype k = 0; k < a.parts.size(); ++k) {
                RosNodePart stripped = b.parts.at(k);
                QVERIFY(stripped.kind == RosNodePart::Kind::Node || stripped.subsystem.isEmpty());
                stripped.subsystem.clear();
                QVERIFY(stripped == a.parts.at(k));
            }
            QVERIFY(b.connections == a.connections && b.channels == a.channels &&
                    b.boundary == a.boundary);
        }
        QCOMPARE(SubsystemGrouping::rootOf(m_arch, QStringLiteral("lf3")), QStringLiteral("lf1"));
    }

    void withoutGroupsNothingChanges()
    {
        for (const QList<SubsystemGroup> &groups :
             {QList<SubsystemGroup>(),
              QList<SubsystemGroup>{
                  {QStringLiteral("ghost"), {QStringLiteral("n99")}, QString()}}}) {
            const Architecture g = SubsystemGrouping::apply(m_arch, groups);
            QCOMPARE(grouped(g), QStringList());
            const QMap<QString, QString> stems = CcdWriter::fileStems(g);
            for (const Composite *c : g.representatives())
                QCOMPARE(CcdWriter::write(*c), expectedCcd(stems.value(c->instanceId)));
        }
    }

    void ccdNestsTheSubsystemAndScoresLikeTheUngroupedReference()
    {
        const Architecture g = SubsystemGrouping::apply(m_arch, m_groups);
        // The CCDs are the launch files' classifiers: they show the grouping of the same nodes
        // in the system.
        const QList<const Composite *> reps = g.representatives();
        QCOMPARE(reps.size(), 2);
        const QString system = CcdWriter::write(*reps.at(0));
        const QString vision = CcdWriter::write(*reps.at(1));
        QVERIFY(system != expectedCcd(QStringLiteral("system")));
        QCOMPARE(partsInBlock(system, QStringLiteral("planning")),
                 (QStringList{QStringLiteral("part3"), QStringLiteral("part4")}));
        QCOMPARE(system.count(QLatin1String("<<Subsystem>>")), 1);
        // The file on its own declares no namespace: the subsystem sits in the composite.
        QVERIFY(!vision.contains(QLatin1String("<<namespace>>")));
        QVERIFY(vision.contains(QStringLiteral("  component \"perception\" as sub_perception "
                                               "<<Subsystem>> {\n"
                                               "    component \"rectifier:\\nRectifier\" as part2 "
                                               "<<RosNodePart>> {\n")));
        QCOMPARE(partsInBlock(vision, QStringLiteral("perception")),
                 (QStringList{QStringLiteral("part2"), QStringLiteral("part3")}));
        QCOMPARE(partsInBlock(vision, QStringLiteral("detection")), QStringList());

        // Read back: grouping adds structure but no element.
        for (const auto &[stem, text] : {std::pair{QStringLiteral("system"), system},
                                         std::pair{QStringLiteral("vision"), vision}}) {
            const QList<UmlDiagram> rec =
                PlantUmlReader::read(text, stem + QStringLiteral(".puml"));
            const QList<UmlDiagram> ref =
                PlantUmlReader::read(expectedCcd(stem), stem + QStringLiteral(".puml"));
            QCOMPARE(rec.size(), 1);
            QCOMPARE(rec.first().level, UmlLevel::Ccd);
            QCOMPARE(rec.first().warnings, QStringList());
            QCOMPARE(rec.first().notes, ref.first().notes);
            QCOMPARE(rec.first().elements.size(), ref.first().elements.size());
            const LevelEvaluation e = Evaluator::evaluateLevel(ref, rec, UmlLevel::Ccd);
            QCOMPARE(e.diagrams.size(), 1);
            QVERIFY(!e.diagrams.first().missing);
            QCOMPARE(e.micro.f1, 1.0);
            QCOMPARE(e.macro.f1, 1.0);
        }
    }

    void oneBlockPerNamespace()
    {
        Composite c = *m_arch.composite(QStringLiteral("lf1"));
        c.parts[2].nameSpace = QStringLiteral("/left"); // planner
        c.parts[2].subsystem = QStringLiteral("planning");
        c.parts[3].subsystem = QStringLiteral("planning"); // backup_planner, at the root
        const QString ccd = CcdWriter::write(c);
        QCOMPARE(ccd.count(QLatin1String("component \"planning\" as sub_planning <<Subsystem>> {")),
                 1);
        QCOMPARE(
            ccd.count(QLatin1String("component \"planning\" as sub_planning_2 <<Subsystem>> {")),
            1);
        QCOMPARE(partsInBlock(ccd, QStringLiteral("planning")),
                 (QStringList{QStringLiteral("part3"), QStringLiteral("part4")}));

        const LayoutGraph g = DiagramBuilder::build(c);
        QStringList parents;
        for (const LayoutCluster &k : g.clusters)
            if (k.key == DiagramBuilder::subsystemKey(QStringLiteral("planning")))
                parents << k.parent + QLatin1Char('>') +
                               clusterOfNodes(g, k.id).join(QLatin1Char(','));
        parents.sort();
        QCOMPARE(parents, (QStringList{QStringLiteral(">part:part4"),
                                       QStringLiteral("namespace:/left>part:part3")}));
    }

    void diagramDrawsTheSubsystemInsideItsNamespace()
    {
        const Architecture grouped = SubsystemGrouping::apply(m_arch, m_groups);
        const LayoutGraph plain = DiagramBuilder::build(*m_arch.composite(QStringLiteral("lf2")));
        const LayoutGraph g = DiagramBuilder::build(*grouped.composite(QStringLiteral("lf2")));
        const QString key = DiagramBuilder::subsystemKey(QStringLiteral("perception"));
        QVERIFY(!plain.cluster(key));
        const LayoutCluster *sub = g.cluster(key);
        QVERIFY(sub);
        QCOMPARE(sub->key, key);
        QCOMPARE(sub->label, QStringLiteral("perception"));
        QCOMPARE(sub->parent, DiagramBuilder::namespaceKey(QStringLiteral("/front")));
        QCOMPARE(DiagramKey::parse(key).kind, DiagramKey::Kind::Subsystem);
        // The members, and the topic only they use; the camera's topic stays in the namespace.
        QCOMPARE(clusterOfNodes(g, key),
                 (QStringList{QStringLiteral("channel:q_front_rectified"),
                              QStringLiteral("part:part2"), QStringLiteral("part:part3")}));
        QCOMPARE(g.node(QStringLiteral("channel:q_front_camera_image"))->cluster,
                 DiagramBuilder::namespaceKey(QStringLiteral("/front")));
        // Parents before children, as the layout needs them.
        QStringList seen;
        for (const LayoutCluster &k : g.clusters) {
            QVERIFY(k.parent.isEmpty() || seen.contains(k.parent));
            seen << k.id;
        }
        QCOMPARE(g.nodes.size(), plain.nodes.size());
        QVERIFY(g.edges == plain.edges);
    }

    void acceptedGroupingReachesThePanelAndTheExport()
    {
        QFile::remove(ProjectFile::locate(exampleWorkspace()));
        Recovery recovery = recoverWorkspace(exampleWorkspace());
        recovery.nodes.workspaceRoot = exampleWorkspace();
        const SuggestionReport report =
            SuggestionEngine(exampleWorkspace(), recovery, SuggestionEngine::Options()).run();
        MainWindow w;
        Document *doc = test::child<Document>(w);
        doc->setRecovery(recovery);
        doc->session()->setSuggestions(report);
        const Suggestion *grouping = nullptr;
        for (const Suggestion &s : doc->session()->suggestions())
            if (s.kind == Suggestion::Kind::SubsystemGrouping)
                grouping = &s;
        QVERIFY(grouping);
        const QString id = grouping->id;
        QCOMPARE(grouped(test::child<DiagramPanel>(w)->architecture()), QStringList());
        const QString out = m_home.filePath(QStringLiteral("export"));
        for (const QString &ccd : exportedCcds(w, out))
            QVERIFY(!ccd.contains(QLatin1String("<<Subsystem>>")));

        QVERIFY(doc->session()->acceptSuggestion(id));
        QVERIFY(test::acceptedSettled(*doc));
        QCOMPARE(doc->session()->acceptedGroupings().size(), 1);
        const QString name = doc->session()->acceptedGroupings().first().name;
        QVERIFY(!name.isEmpty());
        QStringList members = doc->session()->acceptedGroupings().first().memberInstanceIds;
        members.sort();
        QCOMPARE(membersOf(test::child<DiagramPanel>(w)->architecture(), name), members);
        QCOMPARE(grouped(doc->architecture()), QStringList()); // the model itself is unchanged
        QStringList blocks;
        for (const QString &ccd : exportedCcds(w, out))
            blocks << partsInBlock(ccd, name);
        QVERIFY(!blocks.isEmpty());

        doc->undoStack()->undo();
        QVERIFY(test::acceptedSettled(*doc));
        QCOMPARE(grouped(test::child<DiagramPanel>(w)->architecture()), QStringList());
        for (const QString &ccd : exportedCcds(w, out))
            QVERIFY(!ccd.contains(QLatin1String("<<Subsystem>>")));
        doc->undoStack()->redo();
        QVERIFY(test::acceptedSettled(*doc));
        QCOMPARE(membersOf(test::child<DiagramPanel>(w)->architecture(), name), members);

        // The headless command applies the same decisions through the same function: every
        // artifact is byte-identical to the GUI's export.
        exportedCcds(w, out);
        QVERIFY(doc->session()->save());
        QVERIFY(QFileInfo::exists(ProjectFile::locate(exampleWorkspace())));
        const QString headless = m_home.filePath(QStringLiteral("headless"));
        const test::Run run = test::runRosarch(
            {QStringLiteral("recover"), exampleWorkspace(), QStringLiteral("--out"), headless});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QLatin1String("Applied 1 accepted decisions")),
                 qPrintable(run.out));
        QStringList files;
        QDirIterator it(out, QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext())
            files << QDir(out).relativeFilePath(it.next());
        QVERIFY(files.contains(QStringLiteral("architecture.json")));
        for (const QString &f : std::as_const(files))
            QVERIFY2(test::readFile(QDir(out).filePath(f)) ==
                         test::readFile(QDir(headless).filePath(f)),
                     qPrintable(f));
        QVERIFY(test::readFile(QDir(headless).filePath(QStringLiteral("architecture.json")))
                    .contains(name.toUtf8()));
        const test::Run raw =
            test::runRosarch({QStringLiteral("recover"), exampleWorkspace(),
                              QStringLiteral("--out"), headless, QStringLiteral("--no-decisions")});
        QCOMPARE(raw.exitCode, 0);
        for (const QString &f : std::as_const(files))
            if (f.startsWith(QLatin1String("ccd/")))
                QVERIFY(!test::readFile(QDir(headless).filePath(f)).contains("<<Subsystem>>"));
        QFile::remove(ProjectFile::locate(exampleWorkspace()));
    }
};

QTEST_MAIN(TestSubsystemGrouping)
#include "tst_subsystemgrouping.moc"
