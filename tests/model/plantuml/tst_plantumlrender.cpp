// Every diagram rosarch exports, rendered by PlantUML itself (the jar fetched by
// scripts/fetch-plantuml.sh, run once for all files): no PlantUML error, and each rendered CCD
// shows every part and every boundary port. Our own reader is more forgiving than PlantUML, so
// reading our output back proves nothing about whether it renders.
#include "compose/subsystemgrouping.h"
#include "pipeline/recovery.h"
#include "plantuml/acdwriter.h"
#include "plantuml/ccdwriter.h"
#include "plantuml/plantumltext.h"
#include "support/testsupport.h"

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

/// The fixture cases with a workspace: tests/data/<case>/ws or the folder named in
/// tests/data/<case>/workspace (as tst_fixtures reads them).
QMap<QString, QString> fixtureWorkspaces()
{
    QMap<QString, QString> out;
    const QDir data(QStringLiteral(ROSARCH_TEST_DATA));
    for (const QString &c : data.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        if (!QFileInfo::exists(data.filePath(c + QStringLiteral("/expected/atomic_nodes.json"))))
            continue;
        const QString pointer = data.filePath(c + QStringLiteral("/workspace"));
        out.insert(c, QFileInfo::exists(pointer)
                          ? QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                                .filePath(QString::fromUtf8(test::readFile(pointer)).trimmed())
                          : data.filePath(c + QStringLiteral("/ws")));
    }
    return out;
}

/// The texts of an SVG's <text> elements, unescaped.
QStringList svgTexts(const QString &svg)
{
    static const QRegularExpression text(QStringLiteral("<text[^>]*>([^<]*)</text>"));
    QStringList out;
    for (auto it = text.globalMatch(svg); it.hasNext();) {
        QString t = it.next().captured(1);
        t.replace(QLatin1String("&lt;"), QLatin1String("<"))
            .replace(QLatin1String("&gt;"), QLatin1String(">"))
            .replace(QLatin1String("&quot;"), QLatin1String("\""))
            .replace(QLatin1String("&#39;"), QLatin1String("'"))
            .replace(QLatin1String("&amp;"), QLatin1String("&"));
        out << t;
    }
    return out;
}

} // namespace

class TestPlantUmlRender : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void everyExportedDiagramRenders()
    {
        const QString jar = QStringLiteral(ROSARCH_PLANTUML_JAR);
        const QString java = QStringLiteral(ROSARCH_JAVA);
        QVERIFY2(
            QFileInfo::exists(jar),
            qPrintable(QStringLiteral("%1 is missing: run scripts/fetch-plantuml.sh").arg(jar)));
        QVERIFY2(!java.isEmpty() && QFileInfo(java).isExecutable(),
                 "java is missing: install default-jre-headless (setup.sh does)");

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QStringList files;
        QHash<QString, const Composite *> ccdOf; // file base name -> composite
        QList<Architecture> kept;
        kept.reserve(64);
        const auto write = [&](const QString &name, const QString &text) {
            const QString path = dir.filePath(name + QStringLiteral(".puml"));
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(text.toUtf8());
            files << path;
        };
        const QMap<QString, QString> cases = fixtureWorkspaces();
        QVERIFY(cases.size() >= 10);
        for (auto it = cases.cbegin(); it != cases.cend(); ++it) {
            const Recovery r = recoverWorkspace(it.value());
            const QMap<QString, QString> acdStems = AcdWriter::fileStems(r.nodes);
            for (const AtomicNode &n : r.nodes.nodes)
                write(it.key() + QStringLiteral("__acd__") + acdStems.value(n.id),
                      AcdWriter::write(n));
            // As exported, and with every root's node instances grouped into two subsystems
            // (nested <<Subsystem>> components).
            QList<SubsystemGroup> groups;
            for (const Composite &c : r.architecture.composites) {
                if (!c.parentId.isEmpty())
                    continue;
                QStringList nodes;
                for (const NodeInstance &n : r.launch.nodes)
                    nodes << n.id;
                groups.append(
                    {QStringLiteral("first"), nodes.mid(0, nodes.size() / 2), c.instanceId});
                groups.append(
                    {QStringLiteral("second"), nodes.mid(nodes.size() / 2), c.instanceId});
            }
            kept << r.architecture << SubsystemGrouping::apply(r.architecture, groups);
            for (const QString &variant : {QStringLiteral("ccd"), QStringLiteral("grouped")}) {
                const Architecture &arch =
                    variant == QLatin1String("ccd") ? kept.at(kept.size() - 2) : kept.last();
                const QMap<QString, QString> stems = CcdWriter::fileStems(arch);
                for (const Composite *c : arch.representatives()) {
                    const QString name = QStringLiteral("%1__%2__%3")
                                             .arg(it.key(), variant, stems.value(c->instanceId));
                    write(name, CcdWriter::write(*c));
                    ccdOf.insert(name, c);
                }
            }
        }
        QVERIFY(ccdOf.size() >= 10);

        QProcess plantuml;
        plantuml.setProcessChannelMode(QProcess::MergedChannels);
        plantuml.start(java, QStringList{QStringLiteral("-Djava.awt.headless=true"),
                                         QStringLiteral("-jar"), jar, QStringLiteral("-tsvg"),
                                         QStringLiteral("-nometadata")} +
                                 files);
        QVERIFY(plantuml.waitForStarted(30000));
        QVERIFY2(plantuml.waitForFinished(300000), "PlantUML did not finish in 5 minutes");
        const QString output = QString::fromUtf8(plantuml.readAll());
        QVERIFY2(plantuml.exitStatus() == QProcess::NormalExit && plantuml.exitCode() == 0 &&
                     !output.contains(QLatin1String("Error line")),
                 qPrintable(QStringLiteral("PlantUML rejected a diagram:\n") + output));

        for (auto it = ccdOf.cbegin(); it != ccdOf.cend(); ++it) {
            const QString svgPath = dir.filePath(it.key() + QStringLiteral(".svg"));
            QVERIFY2(QFileInfo::exists(svgPath), qPrintable(svgPath));
            const QStringList texts = svgTexts(QString::fromUtf8(test::readFile(svgPath)));
            const Composite &c = *it.value();
            for (const RosNodePart &p : c.parts) {
                if (!p.active)
                    continue;
                const QString shown = p.kind == RosNodePart::Kind::Launch
                                          ? QLatin1Char(':') + p.typeName
                                          : p.name + QLatin1Char(':');
                QVERIFY2(texts.contains(shown),
                         qPrintable(QStringLiteral("%1: part %2 not drawn").arg(it.key(), shown)));
            }
            for (const BoundaryPort &b : c.boundary) {
                const QString shown =
                    QStringLiteral("%1 / %2").arg(b.id, PlantUmlText::type(b.type));
                QVERIFY2(
                    texts.contains(shown),
                    qPrintable(
                        QStringLiteral("%1: boundary port %2 not drawn").arg(it.key(), shown)));
            }
        }
        qInfo("%d diagrams rendered by PlantUML, %d CCDs checked part by part", int(files.size()),
              int(ccdOf.size()));
    }

    void largeCompositeFitsTheDefaultLimit()
    {
        // A system of navigation2's size: ports side by side along the top edge would make the
        // image several times wider than PlantUML's default limit (4096 px), which crops it.
        Composite c;
        c.instanceId = QStringLiteral("lf1");
        c.stem = QStringLiteral("big");
        for (int n = 1; n <= 8; ++n) {
            RosNodePart part;
            part.id = QStringLiteral("part%1").arg(n);
            part.name = QStringLiteral("server_%1").arg(n);
            part.typeName = QStringLiteral("Server");
            for (int k = 1; k <= 10; ++k) {
                const QString id = QStringLiteral("s%1").arg(k);
                const QString name =
                    QStringLiteral("server_%1/some_long_input_topic_%2").arg(n).arg(k);
                PartPort port;
                port.id = id;
                port.kind = PortKind::Subscriber;
                port.name = name;
                port.type = QStringLiteral("geometry_msgs/msg/PoseWithCovarianceStamped");
                part.ports.append(port);
                const QString boundary = QStringLiteral("s%1").arg(c.boundary.size() + 1);
                c.boundary.append({boundary, PortKind::Subscriber, name, part.ports.last().type});
                c.connections.append({Connection::Kind::DelegationIn, part.id, id, boundary});
            }
            c.parts.append(part);
        }
        const QString text = CcdWriter::write(c);
        QVERIFY(text.contains(QLatin1String("\nleft to right direction\n")));
        QVERIFY(text.contains(
            QLatin1String(R"(portin "s3\nserver_2/some_long_input_topic_3" as part2_s3)")));

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("big.puml"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text.toUtf8());
        f.close();
        QProcess plantuml;
        plantuml.setProcessChannelMode(QProcess::MergedChannels);
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("PLANTUML_LIMIT_SIZE"));
        plantuml.setProcessEnvironment(env);
        plantuml.start(QStringLiteral(ROSARCH_JAVA),
                       {QStringLiteral("-Djava.awt.headless=true"), QStringLiteral("-jar"),
                        QStringLiteral(ROSARCH_PLANTUML_JAR), QStringLiteral("-tpng"),
                        QStringLiteral("-nometadata"), path});
        QVERIFY(plantuml.waitForStarted(30000));
        QVERIFY(plantuml.waitForFinished(300000));
        QCOMPARE(plantuml.exitCode(), 0);
        // PNG: the IHDR chunk holds width and height, big-endian, at bytes 16 and 20.
        const QByteArray png = test::readFile(dir.filePath(QStringLiteral("big.png")));
        QVERIFY(png.size() > 24);
        const auto be32 = [&](int at) {
            return quint32(quint8(png[at])) << 24 | quint32(quint8(png[at + 1])) << 16 |
                   quint32(quint8(png[at + 2])) << 8 | quint32(quint8(png[at + 3]));
        };
        const quint32 width = be32(16), height = be32(20);
        qInfo("large composite rendered at %u x %u px", width, height);
        // Below the limit, not cropped at it (nor shrunk to it): the layout alone makes it fit.
        QVERIFY2(width < 4096 && height < 4096,
                 qPrintable(QStringLiteral("%1 x %2 px").arg(width).arg(height)));
    }
};

QTEST_GUILESS_MAIN(TestPlantUmlRender)
#include "tst_plantumlrender.moc"
