// The architecture site's generator on the example workspace: which pages it writes, that the
// same model gives the same bytes, that every link between pages resolves and the source links
// point where they say, that the in-process layout equals the GUI's, and what writing into a
// folder refuses.
#include "diagram/diagrambuilder.h"
#include "diagram/graphlayout.h"
#include "pipeline/recovery.h"
#include "site/inprocesslayout.h"
#include "site/sitediagram.h"
#include "site/sitegenerator.h"
#include "site/sitemodel.h"
#include "site/sitesource.h"
#include "support/testsupport.h"

#include <QRegularExpression>
#include <QTest>

using namespace rosarch;

// Graphviz 2.42's dot layout leaks some of its label and rank buffers (gmalloc in libgvc, not
// ours): the in-process layout test would fail LeakSanitizer for them in the sanitized build.
extern "C" const char *__lsan_default_suppressions()
{
    return "leak:libgvc.so\nleak:libcgraph.so\nleak:libgvplugin_dot_layout.so\n";
}

namespace {

QString exampleWorkspace()
{
    return QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
        .filePath(QStringLiteral("resources/example_ws"));
}

QMap<QString, QByteArray> byPath(const QList<SiteFile> &files)
{
    QMap<QString, QByteArray> map;
    for (const SiteFile &f : files)
        map.insert(f.path, f.data);
    return map;
}

/// `to` resolved against the folder of `from` (site-relative, "a/../b" folded).
QString resolved(const QString &from, const QString &to)
{
    return QDir::cleanPath(QFileInfo(from).path() + u'/' + to);
}

} // namespace

class TestSiteGenerator : public QObject
{
    Q_OBJECT

    Recovery m_recovery;
    QTemporaryDir m_dir;
    QList<SiteFile> m_files;

    SiteOptions options(const QString &folder) const
    {
        SiteOptions o;
        o.title = QStringLiteral("Example robot");
        o.workspace = exampleWorkspace();
        o.siteFolder = folder;
        o.version = QStringLiteral("test");
        return o;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_recovery = recoverWorkspace(exampleWorkspace());
        QVERIFY(!m_recovery.architecture.composites.isEmpty());
        m_files =
            SiteGenerator::files(m_recovery, {}, options(m_dir.filePath(QStringLiteral("site"))));
        QVERIFY(!m_files.isEmpty());
    }

    void writesAPagePerElement()
    {
        const QMap<QString, QByteArray> files = byPath(m_files);
        for (const char *page : {"index.html", "findings.html", "search.html", "assets/site.css",
                                 "assets/site.js", "assets/search-index.js"})
            QVERIFY2(files.contains(QLatin1String(page)), page);
        const SiteModel model(m_recovery, {});
        QVERIFY(!model.systems().isEmpty());
        for (const SiteSystem &s : model.systems())
            QVERIFY2(files.contains(model.systemPage(s.root.instanceId)), qPrintable(s.title()));
        for (const AtomicNode &n : m_recovery.nodes.nodes)
            QVERIFY2(files.contains(model.nodePage(n.id)), qPrintable(n.className));
        for (const QString &f : m_recovery.launch.launchFiles)
            QVERIFY2(files.contains(model.launchPage(f)), qPrintable(f));
        QVERIFY(files.contains(QStringLiteral("topics/robot1.scan_filtered.html")));
        // The robot system's page shows its diagram, with its parts linked to their classes.
        const QString robot = QString::fromUtf8(files.value(QStringLiteral("systems/robot.html")));
        QVERIFY2(robot.contains(QLatin1String("<svg xmlns=\"http://www.w3.org/2000/svg\" "
                                              "class=\"diagram\"")),
                 "no diagram on the robot system's page");
        QVERIFY(robot.contains(QLatin1String("href=\"../launch/")));
        const QString sensing = QString::fromUtf8(files.value(
            model.launchPage(QStringLiteral("src/robot_bringup/launch/sensing.launch.py"))));
        QVERIFY2(sensing.contains(QLatin1String("<g class=\"part\"><a href=\"../nodes/")),
                 "the sensing diagram's parts do not link to node pages");
        // The scope a launch file is analysed in on its own is the analysis's, not a name.
        for (auto it = files.cbegin(); it != files.cend(); ++it)
            QVERIFY2(!it->contains("__rosarch_file_scope__"), qPrintable(it.key()));
        const QString navigation = QString::fromUtf8(files.value(
            model.launchPage(QStringLiteral("src/robot_bringup/launch/navigation.launch.xml"))));
        QVERIFY(navigation.contains(
            QLatin1String("<li><code>monitoring</code>: <a "
                          "href=\"../nodes/robot_mission.BatteryMonitor.html\">")));
        // The search index names nodes, topics and launch files with their pages.
        const QString index =
            QString::fromUtf8(files.value(QStringLiteral("assets/search-index.js")));
        QVERIFY(index.startsWith(QLatin1String("window.rosarchSearchIndex = [[")));
        QVERIFY(index.contains(QLatin1String(
            "[\"/robot1/scan_filtered\",\"topic\",\"topics/robot1.scan_filtered.html\"")));
        QVERIFY(index.contains(QLatin1String("[\"robot.launch.py\",\"launch file\",\"launch/")));
        QVERIFY(index.contains(
            QLatin1String("\"node class\",\"nodes/robot_sensing.LidarFilter.html\"")));
    }

    void topicPagesNameTheRemapThatLedThere()
    {
        // The rule the composition recorded for the port, its own or its scope's, as evaluated.
        const QMap<QString, QByteArray> files = byPath(m_files);
        const QString lidar =
            QString::fromUtf8(files.value(QStringLiteral("topics/robot1.lidar.scan.html")));
        QVERIFY2(lidar.contains(QStringLiteral("<td><code>scan → lidar/scan</code>")),
                 qPrintable(lidar));
        const QString diagnostics =
            QString::fromUtf8(files.value(QStringLiteral("topics/robot_diagnostics.html")));
        QVERIFY(diagnostics.contains(
            QStringLiteral("<td><code>/diagnostics → /robot_diagnostics</code>")));
        // Every remapped port on the composed systems records which rule renamed it.
        for (const Composite &c : m_recovery.architecture.composites)
            for (const RosNodePart &part : c.parts)
                for (const PartPort &port : part.ports)
                    QCOMPARE(port.remapped, port.remap >= 0);
    }

    void launchPagesShowConditionsAsWrittenAndEvaluated()
    {
        // On its own, sensing.launch.py declares use_camera false: the camera does not start.
        const SiteModel model(m_recovery, {});
        const QString sensing = QString::fromUtf8(
            byPath(m_files).value(model.launchPage(QStringLiteral("src/robot_bringup/launch/"
                                                                  "sensing.launch.py"))));
        QVERIFY2(sensing.contains(QLatin1String(
                     "<code>IfCondition(LaunchConfiguration(&#39;use_camera&#39;))</code> "
                     "<span class=\"tag off\">not started</span>")),
                 qPrintable(sensing));

        // A group's condition, a node's that holds, one that does not, and undecidable ones.
        const QString ws = QStringLiteral(ROSARCH_TEST_DATA "/check_scope/ws");
        const Recovery scope = recoverWorkspace(ws);
        SiteOptions o = options(m_dir.filePath(QStringLiteral("scope")));
        o.workspace = ws;
        const SiteModel scopeModel(scope, {});
        const QString robot = QString::fromUtf8(
            byPath(SiteGenerator::files(scope, {}, o))
                .value(scopeModel.launchPage(QStringLiteral("src/depot/launch/robot.launch.xml"))));
        QVERIFY2(robot.contains(QLatin1String("<h2 id=\"conditions\">Conditional groups</h2>")),
                 qPrintable(robot));
        QVERIFY(robot.contains(QLatin1String(
            "<code>if=&quot;$(var use_sim)&quot;</code> <span class=\"tag off\">does not hold")));
        QVERIFY(robot.contains(QLatin1String("<code>$(equals $(var mode) navigation)</code> "
                                             "<span class=\"tag\">holds</span>")));
        QVERIFY(robot.contains(QLatin1String("<code>$(not-equals $(var mode) navigation)</code> "
                                             "<span class=\"tag off\">not started</span>")));
        QVERIFY(robot.contains(QLatin1String("<code>$(equals $(var backup) grid)</code> "
                                             "<span class=\"tag\">undecided")));
        QVERIFY(robot.contains(QLatin1String("<code>$(equals $(var mode) mapping)</code> "
                                             "<span class=\"tag off\">not included</span>")));
    }

    void nodePagesNameEverySystemOfTheirInstances()
    {
        // Instances that show the same are one entry, which still links every system.
        const SiteModel model(m_recovery, {});
        const QMap<QString, QByteArray> files = byPath(m_files);
        for (const AtomicNode &n : m_recovery.nodes.nodes) {
            const QList<SitePortUse> uses = model.instancesOf(n.id);
            const QString page = QString::fromUtf8(files.value(model.nodePage(n.id)));
            QVERIFY(page.count(QLatin1String("<details>")) <= uses.size());
            QCOMPARE(page.count(QLatin1String("<details>")) > 0, !uses.isEmpty());
            for (const SitePortUse &use : uses)
                QVERIFY2(page.contains(QLatin1String("href=\"../") + model.systemPage(use.system) +
                                       u'"'),
                         qPrintable(n.className));
        }
    }

    void sameModelSameBytes()
    {
        // Another run, into another folder at the same depth: every byte equal.
        const Recovery again = recoverWorkspace(exampleWorkspace());
        const QList<SiteFile> second =
            SiteGenerator::files(again, {}, options(m_dir.filePath(QStringLiteral("other"))));
        QCOMPARE(second.size(), m_files.size());
        for (qsizetype i = 0; i < second.size(); ++i) {
            QCOMPARE(second[i].path, m_files[i].path);
            QVERIFY2(second[i].data == m_files[i].data, qPrintable(second[i].path));
        }
        // And written to disk, twice, the files stay byte-identical.
        QString error;
        const QString a = m_dir.filePath(QStringLiteral("a"));
        const QString b = m_dir.filePath(QStringLiteral("b"));
        QVERIFY2(SiteGenerator::write(m_files, a, &error), qPrintable(error));
        QVERIFY2(SiteGenerator::write(second, b, &error), qPrintable(error));
        for (const SiteFile &f : m_files)
            QCOMPARE(test::readFile(QDir(a).filePath(f.path)),
                     test::readFile(QDir(b).filePath(f.path)));
    }

    void everyLinkResolves()
    {
        const QMap<QString, QByteArray> files = byPath(m_files);
        static const QRegularExpression href(QStringLiteral("href=\"([^\"]*)\""));
        static const QRegularExpression id(QStringLiteral(" id=\"([^\"]*)\""));
        QMap<QString, QSet<QString>> ids;
        for (auto it = files.cbegin(); it != files.cend(); ++it)
            for (const auto &m : id.globalMatch(QString::fromUtf8(*it)))
                ids[it.key()].insert(m.captured(1));
        int internal = 0;
        int source = 0;
        for (auto it = files.cbegin(); it != files.cend(); ++it) {
            if (!it.key().endsWith(QLatin1String(".html")))
                continue;
            for (const auto &m : href.globalMatch(QString::fromUtf8(*it))) {
                const QString link =
                    m.captured(1).replace(QLatin1String("&amp;"), QLatin1String("&"));
                const QString file = link.section(u'#', 0, 0).section(u'?', 0, 0);
                const QString fragment = link.section(u'#', 1);
                const QString target = file.isEmpty() ? it.key() : resolved(it.key(), file);
                if (files.contains(target)) {
                    ++internal;
                    QVERIFY2(fragment.isEmpty() || ids.value(target).contains(fragment),
                             qPrintable(it.key() + QStringLiteral(" -> ") + link));
                    continue;
                }
                // Not a page: a source link, relative from the site folder to the workspace.
                ++source;
                const QString onDisk =
                    QDir::cleanPath(m_dir.filePath(QStringLiteral("site/")) + target);
                QVERIFY2(QFileInfo(QUrl::fromPercentEncoding(onDisk.toUtf8())).isFile(),
                         qPrintable(it.key() + QStringLiteral(" -> ") + link));
                QVERIFY2(fragment.startsWith(u'L'), qPrintable(link));
            }
        }
        QVERIFY(internal > 100);
        QVERIFY(source > 20);
    }

    void sourceLinksByPattern()
    {
        const SiteSource s = SiteSource::pattern(
            QStringLiteral("https://example.org/r/blob/{commit}/{path}#L{line}"),
            QStringLiteral("abc123"), QStringLiteral("ws/"));
        QCOMPARE(s.url({QStringLiteral("src/a b/x.py"), 12, 1, 12, 4}, 1),
                 QStringLiteral("https://example.org/r/blob/abc123/ws/src/a%20b/x.py#L12"));
        QCOMPARE(s.url({}, 1), QString());
        const SiteSource r =
            SiteSource::relative(QStringLiteral("/tmp/w/site"), QStringLiteral("/tmp/w"));
        QCOMPARE(r.url({QStringLiteral("src/x.py"), 3, 1, 3, 2}, 1),
                 QStringLiteral("../../src/x.py#L3"));
        QVERIFY(SiteSource::needsCommit(QStringLiteral("{commit}/{path}")));

        SiteOptions o = options(m_dir.filePath(QStringLiteral("site")));
        o.sourceUrl = QStringLiteral("https://example.org/r/blob/{commit}/{path}#L{line}");
        o.commit = QStringLiteral("0123abc");
        const QMap<QString, QByteArray> files = byPath(SiteGenerator::files(m_recovery, {}, o));
        const QString node =
            QString::fromUtf8(files.value(QStringLiteral("nodes/robot_sensing.LidarFilter.html")));
        QVERIFY2(node.contains(
                     QLatin1String("href=\"https://example.org/r/blob/0123abc/src/robot_sensing/")),
                 "no hosted source link on the LidarFilter page");
    }

    void inProcessLayoutEqualsTheHelpers()
    {
        if (GraphLayout::helperPath().isEmpty())
            QSKIP("rosarch-layout is not built");
        const Composite *c = m_recovery.architecture.composites.value(0).parts.isEmpty()
                                 ? nullptr
                                 : &m_recovery.architecture.composites.first();
        QVERIFY(c);
        const LayoutGraph graph = DiagramBuilder::build(*c);
        const LayoutResult ours = InProcessLayout::layout(graph);
        const LayoutResult helper = GraphLayout::layout(graph);
        QVERIFY2(ours.ok, qPrintable(ours.error));
        QVERIFY2(helper.ok, qPrintable(helper.error));
        QCOMPARE(ours.geometry.bounds, helper.geometry.bounds);
        for (const LayoutNode &n : graph.nodes)
            QCOMPARE(ours.geometry.nodes.value(n.id), helper.geometry.nodes.value(n.id));
        const QString svg =
            SiteDiagram::svg(graph, ours.geometry, QStringLiteral("t<"), QStringLiteral("d"),
                             [](const QString &) { return QString(); });
        QVERIFY(svg.contains(QLatin1String("<title id=\"d-title\">t&lt;</title>")));
        QCOMPARE(svg.count(QLatin1String("<g class=\"part")), c->parts.size());
    }

    void writingRefusesWhatItShould()
    {
        QString error;
        // A folder with someone else's files.
        const QString foreign = m_dir.filePath(QStringLiteral("foreign"));
        test::writeFile(QDir(foreign).filePath(QStringLiteral("notes.txt")), "mine");
        QVERIFY(!SiteGenerator::write(m_files, foreign, &error));
        QVERIFY2(error.contains(QLatin1String("not empty")), qPrintable(error));
        QCOMPARE(test::readFile(QDir(foreign).filePath(QStringLiteral("notes.txt"))),
                 QByteArray("mine"));
        // A file where the folder should be.
        const QString file = QDir(foreign).filePath(QStringLiteral("notes.txt"));
        QVERIFY(!SiteGenerator::write(m_files, file, &error));
        QVERIFY2(error.contains(QLatin1String("is a file")), qPrintable(error));
        // A folder that cannot be made.
        QVERIFY(!SiteGenerator::write(m_files, QStringLiteral("/proc/rosarch-site"), &error));
        QVERIFY2(error.contains(QLatin1String("Cannot create")), qPrintable(error));
        // A site written before is rewritten, and a page the model no longer has goes.
        const QString again = m_dir.filePath(QStringLiteral("again"));
        QList<SiteFile> more = m_files;
        more << SiteFile{QStringLiteral("nodes/gone.html"), "<!DOCTYPE html>"};
        QVERIFY2(SiteGenerator::write(more, again, &error), qPrintable(error));
        QVERIFY(QFileInfo::exists(QDir(again).filePath(QStringLiteral("nodes/gone.html"))));
        test::writeFile(QDir(again).filePath(QStringLiteral("CNAME")), "docs.example.org");
        QVERIFY2(SiteGenerator::write(m_files, again, &error), qPrintable(error));
        QVERIFY(!QFileInfo::exists(QDir(again).filePath(QStringLiteral("nodes/gone.html"))));
        QVERIFY2(QFileInfo::exists(QDir(again).filePath(QStringLiteral("CNAME"))),
                 "a file the site did not write was removed");
    }

    void projectMarksShowOnTheFindingsPage()
    {
        QList<Diagnostic> all = m_recovery.nodes.diagnostics + m_recovery.launch.diagnostics +
                                m_recovery.architecture.diagnostics;
        QVERIFY(all.size() >= 2);
        Project project;
        FindingMark accepted;
        accepted.key = all[0].key();
        accepted.status = FindingMark::Status::Accepted;
        accepted.reason = QStringLiteral("the planner <waits> for it");
        FindingMark hidden;
        hidden.key = all[1].key();
        hidden.status = FindingMark::Status::Hidden;
        project.findings = {accepted, hidden};
        const QMap<QString, QByteArray> files = byPath(SiteGenerator::files(
            m_recovery, project, options(m_dir.filePath(QStringLiteral("site")))));
        const QString page = QString::fromUtf8(files.value(QStringLiteral("findings.html")));
        QVERIFY(page.contains(QLatin1String("1 accepted and 1 hidden in the project")));
        QCOMPARE(page.count(QLatin1String(" data-mark=\"accepted\"")), 1);
        QCOMPARE(page.count(QLatin1String(" data-mark=\"hidden\"")), 1);
        QVERIFY(page.contains(QLatin1String("the planner &lt;waits&gt; for it")));
        // Every kind of finding on the page is explained.
        for (const Diagnostic &d : all)
            QVERIFY2(page.contains(QStringLiteral("<section id=\"kind-%1\"").arg(d.code)),
                     qPrintable(d.code));
    }

    void pluginPagesListWhoLoadsThem()
    {
        const QString ws = test::dataDir(QStringLiteral("cpp_plugins/ws"));
        const Recovery r = recoverWorkspace(ws);
        SiteOptions o = options(m_dir.filePath(QStringLiteral("plugins")));
        o.workspace = ws;
        const QMap<QString, QByteArray> files = byPath(SiteGenerator::files(r, {}, o));
        const QString page = QString::fromUtf8(
            files.value(QStringLiteral("nodes/rover_nav_plugins.PathFollower.html")));
        QVERIFY2(page.contains(
                     QLatin1String("<caption>Node instances that load PathFollower</caption>")),
                 qPrintable(page.left(3000)));
        QVERIFY(page.contains(QLatin1String("<code>FollowPath</code>")));
        QVERIFY(page.contains(QLatin1String("href=\"../systems/navigation.html\"")));
    }

    void emptyModelStillMakesASite()
    {
        const QList<SiteFile> files =
            SiteGenerator::files({}, {}, options(m_dir.filePath(QStringLiteral("empty"))));
        const QMap<QString, QByteArray> map = byPath(files);
        QVERIFY(map.contains(QStringLiteral("index.html")));
        QVERIFY(map.value(QStringLiteral("index.html"))
                    .contains("No launch file or executable starts a system here."));
    }
};

QTEST_GUILESS_MAIN(TestSiteGenerator)
#include "tst_sitegenerator.moc"
