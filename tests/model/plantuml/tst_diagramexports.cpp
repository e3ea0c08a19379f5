// The Mermaid and DOT exports on every fixture workspace, read by their real consumers: DOT
// by Graphviz itself (cgraph, in process) and laid out with dot; Mermaid by Mermaid's own
// parser (Node, scripts/fetch-mermaid.sh), after checks of what the diagram must hold: one
// node per active part, channel and boundary port, one coloured arrow per connection, ids
// that are never Mermaid keywords, and labels without raw quotes.
#include "core/rosnames.h"
#include "pipeline/recovery.h"
#include "plantuml/communicationgraph.h"
#include "plantuml/mermaidwriter.h"
#include "support/testsupport.h"

#include <graphviz/cgraph.h>
#include <graphviz/gvc.h>

#include <QRegularExpression>
#include <QtTest>

using namespace rosarch;

namespace {

QStringList fixtures()
{
    QStringList out;
    const QDir data(test::dataDir());
    for (const QString &c : data.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        const QString ws = data.filePath(c + QStringLiteral("/ws"));
        out << (QFileInfo(ws).isDir() ? ws : data.filePath(c));
    }
    return out;
}

} // namespace

class TestDiagramExports : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void dotIsReadAndLaidOutByGraphviz()
    {
        GVC_t *gvc = gvContext();
        int graphs = 0;
        for (const QString &ws : fixtures()) {
            const Recovery r = recoverWorkspace(ws);
            for (const Composite &root : r.architecture.composites) {
                if (!root.parentId.isEmpty())
                    continue;
                const QByteArray text = CommunicationGraph::dot(r.architecture, root).toUtf8();
                Agraph_t *g = agmemread(text.constData());
                QVERIFY2(g, qPrintable(ws + QStringLiteral(": ") + root.file));
                // Every active node of the system, and one edge per resolved active port.
                QSet<QString> nodes;
                int ports = 0;
                QList<const Composite *> stack{&root};
                while (!stack.isEmpty()) {
                    const Composite *c = stack.takeLast();
                    for (const RosNodePart &p : c->parts) {
                        if (!p.active)
                            continue;
                        if (p.kind == RosNodePart::Kind::Launch) {
                            if (const Composite *child = r.architecture.composite(p.typeId))
                                stack << child;
                            continue;
                        }
                        nodes.insert(RosNames::fullyQualified(p.nameSpace, p.name));
                        for (const PartPort &port : p.ports)
                            ports += port.active && port.resolved;
                    }
                }
                int nodeCount = 0;
                for (Agnode_t *n = agfstnode(g); n; n = agnxtnode(g, n))
                    nodeCount += QByteArray(agnameof(n)).startsWith("node ");
                QCOMPARE(nodeCount, int(nodes.size()));
                QVERIFY2(agnedges(g) <= ports && (ports == 0 || agnedges(g) > 0),
                         qPrintable(root.file));
                QCOMPARE(gvLayout(gvc, g, "dot"), 0);
                gvFreeLayout(gvc, g);
                agclose(g);
                ++graphs;
            }
        }
        gvFreeContext(gvc);
        QVERIFY(graphs >= 8);
    }

    void dotOfASystem()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("check_system/ws")));
        const QString dot = CommunicationGraph::dot(r.architecture, r.architecture.composites[0]);
        QVERIFY(
            dot.contains(QLatin1String("\"node /lidar\" -> \"topic /scan\" [color=darkgreen];")));
        QVERIFY(dot.contains(QLatin1String("\"topic /scan\" -> \"node /mapper\" [color=blue];")));
        QVERIFY(dot.contains(
            QLatin1String("\"topic /scan\" [label=\"/scan\\nsensor_msgs/msg/LaserScan\", "
                          "shape=box];")));
        QCOMPARE(dot, CommunicationGraph::dot(r.architecture, r.architecture.composites[0]));
    }

    void mermaidParsesWithMermaid()
    {
        const QDir modules(QStringLiteral(ROSARCH_MERMAID_DIR));
        QVERIFY2(modules.exists(QStringLiteral("node_modules/mermaid/package.json")),
                 "Mermaid's parser is missing: run scripts/fetch-mermaid.sh build/_mermaid "
                 "(./setup.sh does)");
        QTemporaryDir dir;
        QStringList files;
        for (const QString &ws : fixtures()) {
            const Recovery r = recoverWorkspace(ws);
            for (const Composite *c : r.architecture.representatives()) {
                const QString file =
                    dir.filePath(QStringLiteral("%1_%2.md").arg(files.size()).arg(c->stem));
                test::writeFile(file, MermaidWriter::write(*c).toUtf8());
                files << file;
            }
        }
        // A label with every character Mermaid treats as markup.
        Composite odd;
        odd.stem = QStringLiteral("odd");
        RosNodePart part;
        part.id = QStringLiteral("part1");
        part.name = QStringLiteral("end");
        part.typeName = QStringLiteral("T<\"quoted\">[x]{y}(z)|w;");
        odd.parts << part;
        odd.channels << Channel{QStringLiteral("q_end"), Channel::Kind::Topic,
                                QStringLiteral("/a\"b"), QStringLiteral("p/msg/T")};
        odd.connections << Connection{Connection::Kind::Publish, QStringLiteral("part1"),
                                      QStringLiteral("p1"), QStringLiteral("q_end")};
        files << dir.filePath(QStringLiteral("odd.md"));
        test::writeFile(files.last(), MermaidWriter::write(odd).toUtf8());
        QProcess node;
        node.setProcessChannelMode(QProcess::MergedChannels);
        node.start(QStringLiteral(ROSARCH_NODE),
                   QStringList{QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                                   .filePath(QStringLiteral("tests/support/parse-mermaid.mjs")),
                               modules.path()} +
                       files);
        QVERIFY(node.waitForFinished(120000));
        QVERIFY2(node.exitCode() == 0, node.readAll().constData());
        QVERIFY(files.size() >= 11);
        // The parser does reject a broken diagram.
        test::writeFile(dir.filePath(QStringLiteral("broken.mmd")), "flowchart LR\n  a[\"x\n");
        node.start(QStringLiteral(ROSARCH_NODE),
                   {QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                        .filePath(QStringLiteral("tests/support/parse-mermaid.mjs")),
                    modules.path(), dir.filePath(QStringLiteral("broken.mmd"))});
        QVERIFY(node.waitForFinished(120000));
        QCOMPARE(node.exitCode(), 1);
    }

    void mermaidHasEveryElement()
    {
        static const QRegularExpression node(QStringLiteral(R"(^\s+(\w+)[\[\(\{>])"));
        static const QRegularExpression arrow(QStringLiteral(R"(^\s+(\w+) --> (\w+)$)"));
        static const QSet<QString> keywords{QStringLiteral("end"),      QStringLiteral("graph"),
                                            QStringLiteral("subgraph"), QStringLiteral("style"),
                                            QStringLiteral("class"),    QStringLiteral("click")};
        int diagrams = 0;
        for (const QString &ws : fixtures()) {
            const Recovery r = recoverWorkspace(ws);
            for (const Composite *c : r.architecture.representatives()) {
                const QString md = MermaidWriter::write(*c);
                QVERIFY(md.contains(QLatin1String("```mermaid\nflowchart LR\n")));
                QVERIFY(md.endsWith(QLatin1String("```\n")));
                QSet<QString> declared;
                int arrows = 0, styles = 0;
                for (const QString &line : MermaidWriter::flowchart(*c).split(QLatin1Char('\n'))) {
                    if (const auto m = arrow.match(line); m.hasMatch()) {
                        QVERIFY2(declared.contains(m.captured(1)), qPrintable(line));
                        QVERIFY2(declared.contains(m.captured(2)), qPrintable(line));
                        ++arrows;
                    } else if (line.trimmed().startsWith(QLatin1String("linkStyle"))) {
                        ++styles;
                    } else if (const auto n = node.match(line);
                               n.hasMatch() && !line.contains(QLatin1String("subgraph"))) {
                        QVERIFY(!keywords.contains(n.captured(1)));
                        declared.insert(n.captured(1));
                        // A label is one quoted string: no quote inside it.
                        const QString label = line.section(QLatin1Char('"'), 1, -2);
                        QVERIFY2(!label.contains(QLatin1Char('"')), qPrintable(line));
                    }
                }
                int parts = 0, connections = 0;
                for (const RosNodePart &p : c->parts)
                    parts += p.active;
                for (const Connection &k : c->connections)
                    connections += c->part(k.partId) && c->part(k.partId)->active;
                QCOMPARE(int(declared.size()),
                         parts + int(c->channels.size()) + int(c->boundary.size()));
                QCOMPARE(arrows, connections);
                QCOMPARE(styles, arrows);
                ++diagrams;
            }
        }
        QVERIFY(diagrams >= 10);
    }
};

QTEST_GUILESS_MAIN(TestDiagramExports)
#include "tst_diagramexports.moc"
