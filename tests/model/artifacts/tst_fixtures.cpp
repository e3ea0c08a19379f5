// Data-driven: every tests/data/<case>/ with expected/atomic_nodes.json is a row; when the case
// also has expected/launch_dependencies.json, stage 2's output is compared too, and with
// expected/stage1_diagnostics.txt the code and place of each stage-1 diagnostic; the folders
// expected/acd, expected/ccd and expected/graph (each root's communication graph), when the
// case has them, file by file. The case's
// workspace is <case>/ws, or the folder named (relative to the source tree) in <case>/workspace.
// Set ROSARCH_UPDATE_EXPECTED=1 to rewrite the expected files after a reviewed change.
#include "artifacts/architecturejson.h"
#include "artifacts/atomicnodesjson.h"
#include "artifacts/launchdependenciesjson.h"
#include "core/modelinvariants.h"
#include "nodes/nodeanalyzer.h"
#include "pipeline/recovery.h"
#include "plantuml/acdwriter.h"
#include "plantuml/ccdwriter.h"
#include "plantuml/communicationgraph.h"
#include "support/testsupport.h"

#include <QDirIterator>
#include <QtTest>

using namespace rosarch;

class TestFixtures : public QObject
{
    Q_OBJECT
private:
    static QString workspaceOf(const QString &caseDir)
    {
        const QByteArray pointer =
            test::readFile(QDir(caseDir).filePath(QStringLiteral("workspace"))).trimmed();
        if (!pointer.isEmpty())
            return QDir(QStringLiteral(ROSARCH_SOURCE_DIR)).filePath(QString::fromUtf8(pointer));
        return QDir(caseDir).filePath(QStringLiteral("ws"));
    }

private Q_SLOTS:
    static void compareDiagrams(const QMap<QString, QByteArray> &produced,
                                const QString &expectedDir,
                                const QString &pattern = QStringLiteral("*.puml"))
    {
        const QDir dir(expectedDir);
        if (!dir.exists())
            return;
        for (auto it = produced.cbegin(); it != produced.cend(); ++it)
            test::compareOrUpdate(it.value(), dir.filePath(it.key()));
        if (!qEnvironmentVariableIntValue("ROSARCH_UPDATE_EXPECTED"))
            QCOMPARE(produced.keys(), dir.entryList({pattern}, QDir::Files, QDir::Name));
    }

    void recovery_data()
    {
        QTest::addColumn<QString>("caseDir");
        QDir data(test::dataDir());
        const QStringList cases = data.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name);
        int rows = 0;
        for (const QString &c : cases) {
            if (!QFileInfo::exists(
                    data.filePath(c + QStringLiteral("/expected/atomic_nodes.json"))))
                continue;
            QTest::newRow(qPrintable(c)) << data.filePath(c);
            ++rows;
        }
        QVERIFY2(rows > 0, "no fixture cases found");
    }

    void recovery()
    {
        QFETCH(QString, caseDir);
        const QString ws = workspaceOf(caseDir);
        QVERIFY2(QFileInfo(ws).isDir(), qPrintable(ws));
        const Recovery recovery = recoverWorkspace(ws);
        const AtomicNodeList &list = recovery.nodes;
        QVERIFY(!list.canceled);
        test::compareOrUpdate(AtomicNodesJson::write(list),
                              QDir(caseDir).filePath(QStringLiteral("expected/atomic_nodes.json")));
        const QString launchExpected =
            QDir(caseDir).filePath(QStringLiteral("expected/launch_dependencies.json"));
        if (QFileInfo::exists(launchExpected))
            test::compareOrUpdate(LaunchDependenciesJson::write(recovery.launch), launchExpected);

        // Stage 1's diagnostics, one "code file:line" per line, when the case lists them.
        const QString diagnosticsExpected =
            QDir(caseDir).filePath(QStringLiteral("expected/stage1_diagnostics.txt"));
        if (QFileInfo::exists(diagnosticsExpected)) {
            QStringList lines;
            for (const Diagnostic &d : list.diagnostics)
                lines
                    << QStringLiteral("%1 %2:%3").arg(d.code, d.evidence.file).arg(d.evidence.line);
            lines.sort();
            test::compareOrUpdate((lines.join(u'\n') + u'\n').toUtf8(), diagnosticsExpected);
        }

        const QString archExpected =
            QDir(caseDir).filePath(QStringLiteral("expected/architecture.json"));
        const QMap<QString, QString> ccdStems = CcdWriter::fileStems(recovery.architecture);
        if (QFileInfo::exists(archExpected))
            test::compareOrUpdate(ArchitectureJson::write(recovery.architecture, ccdStems,
                                                          &recovery.nodes, &recovery.launch),
                                  archExpected);

        // Expected ACDs and CCDs, when the case has them, must match file by file.
        QMap<QString, QByteArray> acds;
        const QMap<QString, QString> stems = AcdWriter::fileStems(list);
        for (const AtomicNode &n : list.nodes)
            acds.insert(stems.value(n.id) + QStringLiteral(".puml"), AcdWriter::write(n).toUtf8());
        compareDiagrams(acds, QDir(caseDir).filePath(QStringLiteral("expected/acd")));
        QMap<QString, QByteArray> ccds;
        for (const Composite *c : recovery.architecture.representatives())
            ccds.insert(ccdStems.value(c->instanceId) + QStringLiteral(".puml"),
                        CcdWriter::write(*c).toUtf8());
        compareDiagrams(ccds, QDir(caseDir).filePath(QStringLiteral("expected/ccd")));
        // and the communication graph of each root, as launched (graph/<root>.dot)
        QMap<QString, QByteArray> graphs;
        for (const Composite &c : recovery.architecture.composites)
            if (c.parentId.isEmpty())
                graphs.insert(ccdStems.value(c.instanceId, c.stem) + QStringLiteral(".dot"),
                              CommunicationGraph::dot(recovery.architecture, c).toUtf8());
        compareDiagrams(graphs, QDir(caseDir).filePath(QStringLiteral("expected/graph")),
                        QStringLiteral("*.dot"));
    }

    void modelInvariantsHold_data() { recovery_data(); }

    // Names are names, ports are listed once, whatever the fixture.
    void modelInvariantsHold()
    {
        QFETCH(QString, caseDir);
        const QStringList violations =
            modelInvariantViolations(recoverWorkspace(workspaceOf(caseDir)).nodes);
        QVERIFY2(violations.isEmpty(), qPrintable(violations.join(QLatin1Char('\n'))));
    }

    void ccdChannelsAreTheGraphs_data() { recovery_data(); }

    // One wiring rule (blueprint §1): for every system, the channels of its CCDs (the root's
    // and its includes') are the names the communication graph shows with both sides; for a
    // root that includes nothing, so are the channels of the launch file's own CCD, whose
    // relative and absolute spellings of one name are one channel.
    void ccdChannelsAreTheGraphs()
    {
        QFETCH(QString, caseDir);
        const Recovery r = recoverWorkspace(workspaceOf(caseDir));
        const Architecture &arch = r.architecture;
        const auto absolute = [](const Channel &ch) {
            const QString family = ch.kind == Channel::Kind::Topic     ? QStringLiteral("topic")
                                   : ch.kind == Channel::Kind::Service ? QStringLiteral("service")
                                                                       : QStringLiteral("action");
            return family + QLatin1Char(' ') +
                   (ch.name.startsWith(QLatin1Char('/')) ? ch.name : QLatin1Char('/') + ch.name);
        };
        for (const Composite &root : arch.composites) {
            if (!root.parentId.isEmpty())
                continue;
            // the graph: channel nodes with an edge in and an edge out
            const QString dot = CommunicationGraph::dot(arch, root);
            static const QRegularExpression edge(QStringLiteral(R"re(^  "(.+)" -> "(.+)" \[)re"));
            QSet<QString> into, outOf;
            for (const QString &line : dot.split(QLatin1Char('\n'))) {
                const QRegularExpressionMatch m = edge.match(line);
                if (!m.hasMatch())
                    continue;
                // a guessed name ("topic /x?") is a channel of its own, as in the CCD
                if (!m.captured(1).startsWith(QLatin1String("node ")))
                    outOf.insert(m.captured(1));
                if (!m.captured(2).startsWith(QLatin1String("node ")))
                    into.insert(m.captured(2));
            }
            QStringList graph;
            const QSet<QString> both = QSet<QString>(into).intersect(outOf);
            for (const QString &name : both)
                graph << (name.endsWith(QLatin1Char('?')) ? name.chopped(1) : name);
            graph.sort();
            // the system's CCDs: the root and every composite below it
            QSet<QString> below{root.instanceId};
            QSet<QString> channels;
            qsizetype composites = 0;
            for (bool grew = true; grew;) {
                grew = false;
                for (const Composite &c : arch.composites)
                    if (below.contains(c.parentId) && !below.contains(c.instanceId)) {
                        below.insert(c.instanceId);
                        grew = true;
                    }
            }
            const auto sameAsGraph = [&](const QString &what, const QSet<QString> &names) {
                QStringList sorted = names.values();
                sorted.sort();
                return sorted == graph ? QString()
                                       : root.file + what + sorted.join(u',') +
                                             QStringLiteral(" / graph ") + graph.join(u',');
            };
            for (const Composite &c : arch.composites)
                if (below.contains(c.instanceId)) {
                    ++composites;
                    for (const Channel &ch : c.channels)
                        channels.insert(absolute(ch));
                }
            QString problem = sameAsGraph(QStringLiteral(": CCDs "), channels);
            QVERIFY2(problem.isEmpty(), qPrintable(problem));
            if (composites != 1)
                continue;
            for (const Composite &own : arch.classifiers) {
                if (own.file != root.file)
                    continue;
                QSet<QString> names;
                for (const Channel &ch : own.channels)
                    names.insert(absolute(ch));
                problem = sameAsGraph(QStringLiteral(": own CCD "), names);
                QVERIFY2(problem.isEmpty(), qPrintable(problem));
            }
        }
    }

    void outputIsDeterministic()
    {
        const QString ws = QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                               .filePath(QStringLiteral("resources/example_ws"));
        const QByteArray first = AtomicNodesJson::write(recoverAtomicNodes(ws));
        const QByteArray second = AtomicNodesJson::write(recoverAtomicNodes(ws));
        QCOMPARE(first, second);
        QVERIFY(first.contains("\"list_packages\""));
    }
};

QTEST_GUILESS_MAIN(TestFixtures)
#include "tst_fixtures.moc"
