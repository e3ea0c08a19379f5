// What is exported is what was reviewed: corrections a person makes in the GUI (a renamed topic,
// an added connection, a renamed instance) name topics as the system shows them, resolved in the
// instance's namespace. The GUI draws the system; the CCD and Mermaid exports draw each launch
// file's own classifier, where the same topic is spelled relative to the file. On the example
// workspace (every node under /robot1), every export must wire the corrected connection as the
// GUI does, with no boundary port left over for it, and still render in PlantUML and parse in
// Mermaid.
#include "artifacts/artifactwriter.h"
#include "project/classifiercorrections.h"
#include "project/correctedmodel.h"
#include "support/testsupport.h"

#include <QDirIterator>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

QString exampleWorkspace()
{
    const QString pointer = test::dataDir(QStringLiteral("example_ws/workspace"));
    return QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
        .filePath(QString::fromUtf8(test::readFile(pointer)).trimmed());
}

/// A name of the root file's scope as the system spells it ("robot1/x" is "/robot1/x").
QString absolute(const QString &name)
{
    return name.startsWith(u'/') ? name : u'/' + name;
}

Correction correction(const QString &id, Correction::Kind kind, const QString &target,
                      const QString &oldValue, const QString &newValue)
{
    Correction c;
    c.id = id;
    c.kind = kind;
    c.target = target;
    c.oldValue = oldValue;
    c.newValue = newValue;
    c.author = QStringLiteral("tester");
    c.time = QDateTime::fromString(QStringLiteral("2026-11-29T10:00:00Z"), Qt::ISODate);
    return c;
}

/// A boundary port of a written diagram: its direction and the name it promotes.
struct Boundary
{
    bool in = false;
    QString family; ///< "topic", "service" or "action", from the port id's prefix
    QString name;
};

QString familyOfPortId(const QString &id)
{
    if (id.startsWith(QLatin1String("ps")) || id.startsWith(QLatin1String("rs")))
        return QStringLiteral("service");
    if (id.startsWith(QLatin1String("pa")) || id.startsWith(QLatin1String("ra")))
        return QStringLiteral("action");
    return QStringLiteral("topic");
}

/// What a written CCD draws: its channels (alias -> name), boundary ports (alias -> port) and
/// arrows ("from -> to").
struct WrittenCcd
{
    QHash<QString, QString> channels;
    QHash<QString, Boundary> boundary;
    QStringList arrows;

    static WrittenCcd parse(const QString &text)
    {
        static const QRegularExpression channel(
            QStringLiteral("^\\s*(?:queue|circle) \"([^\"]*)\" as (\\w+)"));
        static const QRegularExpression port(
            QStringLiteral("^\\s*(portin|portout) \"(\\w+) / [^\"]*\" as (b_\\w+)$"));
        static const QRegularExpression arrow(
            QStringLiteral("^\\s*(\\w+) --\\[[^\\]]*\\]--> (\\w+)$"));
        WrittenCcd out;
        QString comment;
        for (const QString &line : text.split(u'\n')) {
            if (const auto m = channel.match(line); m.hasMatch())
                out.channels.insert(m.captured(2), m.captured(1));
            else if (const auto p = port.match(line); p.hasMatch())
                out.boundary.insert(p.captured(3), {p.captured(1) == QLatin1String("portin"),
                                                    familyOfPortId(p.captured(2)), comment});
            else if (const auto a = arrow.match(line); a.hasMatch())
                out.arrows << a.captured(1) + QStringLiteral(" -> ") + a.captured(2);
            // a boundary port's name stands in the comment line above it
            comment =
                line.trimmed().startsWith(u'\'') ? line.trimmed().mid(1).trimmed() : QString();
        }
        return out;
    }
};

/// What a written Mermaid flowchart draws: channels (id -> name), boundary ports and arrows.
struct WrittenMermaid
{
    QHash<QString, QString> channels;
    QHash<QString, Boundary> boundary;
    QStringList arrows;

    static WrittenMermaid parse(const QString &text)
    {
        static const QRegularExpression channel(QStringLiteral(
            "^\\s*(ch_\\w+)(?:\\(\\[|\\{\\{)\"([^\"]*?)(?: · [^\"]*)?\"(?:\\]\\)|\\}\\})"));
        static const QRegularExpression port(
            QStringLiteral("^\\s*(b_(\\w+))>\"(in|out) (.*?) · [^\"]*\"\\]$"));
        static const QRegularExpression arrow(QStringLiteral("^\\s*(\\w+) --> (\\w+)$"));
        WrittenMermaid out;
        for (const QString &line : text.split(u'\n')) {
            if (const auto m = channel.match(line); m.hasMatch())
                out.channels.insert(m.captured(1), m.captured(2));
            else if (const auto p = port.match(line); p.hasMatch())
                out.boundary.insert(p.captured(1), {p.captured(3) == QLatin1String("in"),
                                                    familyOfPortId(p.captured(2)), p.captured(4)});
            else if (const auto a = arrow.match(line); a.hasMatch())
                out.arrows << a.captured(1) + QStringLiteral(" -> ") + a.captured(2);
        }
        return out;
    }
};

/// A boundary port promoted for a name that another boundary port of the same diagram promotes
/// the other way: a connection the diagram should have wired inside ("" when none).
QString unwiredPair(const QHash<QString, Boundary> &boundary)
{
    for (const Boundary &a : boundary)
        for (const Boundary &b : boundary)
            if (a.in && !b.in && a.family == b.family && absolute(a.name) == absolute(b.name))
                return QStringLiteral("%1 %2 in and out").arg(a.family, a.name);
    return {};
}

/// The connections of a composite as "kind part/port -> channel or boundary name", the names
/// spelled from the root ("/robot1/x"): what the GUI draws of a root, compared with its CCD.
QSet<QString> connectionsOf(const Composite &c)
{
    QSet<QString> out;
    for (const Connection &k : c.connections) {
        const Channel *ch = c.channel(k.targetId);
        const BoundaryPort *b = c.boundaryPort(k.targetId);
        const QString target = ch ? absolute(ch->name) : b ? u'>' + absolute(b->name) : QString();
        out.insert(QStringLiteral("%1 %2_%3 %4")
                       .arg(connectionKindName(k.kind), k.partId, k.portId, target));
    }
    return out;
}

/// The same read from a written CCD (arrow colours stand for the kinds).
QSet<QString> connectionsOf(const WrittenCcd &ccd, const QString &text)
{
    static const QRegularExpression arrow(
        QStringLiteral("^\\s*(\\w+) --\\[#(\\w+),bold\\]--> (\\w+)$"),
        QRegularExpression::MultilineOption);
    QSet<QString> out;
    for (auto it = arrow.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        const QString from = m.captured(1), colour = m.captured(2), to = m.captured(3);
        const bool fromPart = !ccd.channels.contains(from) && !ccd.boundary.contains(from);
        const QString port = fromPart ? from : to;
        const QString other = fromPart ? to : from;
        const QString target = ccd.channels.contains(other)
                                   ? absolute(ccd.channels.value(other))
                                   : u'>' + absolute(ccd.boundary.value(other).name);
        QString kind;
        if (ccd.boundary.contains(other))
            kind = fromPart ? QStringLiteral("delegation_out") : QStringLiteral("delegation_in");
        else if (colour == QLatin1String("Green"))
            kind = QStringLiteral("publish");
        else if (colour == QLatin1String("Blue"))
            kind = QStringLiteral("subscribe");
        else if (colour == QLatin1String("Red"))
            kind = QStringLiteral("client");
        else
            kind = QStringLiteral("server");
        out.insert(QStringLiteral("%1 %2 %3").arg(kind, port, target));
    }
    return out;
}

const Composite *systemOf(const Architecture &a, const QString &stem)
{
    for (const Composite &c : a.composites)
        if (c.stem == stem)
            return &c;
    return nullptr;
}

const Composite *classifierOf(const Architecture &a, const QString &stem)
{
    for (const Composite &c : a.classifiers)
        if (c.stem == stem)
            return &c;
    return nullptr;
}

const RosNodePart *partTyped(const Composite &c, const QString &typeName)
{
    for (const RosNodePart &p : c.parts)
        if (p.typeName == typeName)
            return &p;
    return nullptr;
}

} // namespace

class TestCorrectedExports : public QObject
{
    Q_OBJECT

    Recovery m_recovered;
    CorrectedRecovery m_corrected;
    QTemporaryDir m_out;
    QStringList m_written;

    QString written(const QString &relative) const
    {
        return QString::fromUtf8(test::readFile(QDir(m_out.path()).filePath(relative)));
    }

private Q_SLOTS:
    void initTestCase()
    {
        m_recovered = recoverWorkspace(exampleWorkspace());
        QVERIFY(systemOf(m_recovered.architecture, QStringLiteral("robot")));
        // As recovered: mission_planner publishes mission_status, nobody listens to it.
        const Composite *recoveredRobot =
            systemOf(m_recovered.architecture, QStringLiteral("robot"));
        QVERIFY(std::none_of(
            recoveredRobot->channels.cbegin(), recoveredRobot->channels.cend(),
            [](const Channel &ch) { return ch.name.contains(QLatin1String("mission")); }));

        // What a person does in the GUI: rename the topic, connect the navigator to it (the
        // dialog takes the absolute name the diagram shows), then rename the navigator.
        const StableKeys keys(m_recovered);
        QString navigator;
        for (const NodeInstance &n : m_recovered.launch.nodes)
            if (n.nodeName == QLatin1String("navigator"))
                navigator = keys.keyOf(n.id);
        QVERIFY(navigator.startsWith(QLatin1String("instance:")));
        Project project;
        project.corrections << correction(QStringLiteral("c1"), Correction::Kind::Rename,
                                          QStringLiteral("topic:/robot1/mission_status"),
                                          QStringLiteral("/robot1/mission_status"),
                                          QStringLiteral("/robot1/mission/status"));
        Correction connect = correction(QStringLiteral("c2"), Correction::Kind::AddConnection,
                                        navigator, {}, QStringLiteral("/robot1/mission/status"));
        connect.portKind = PortKind::Subscriber;
        connect.type = QStringLiteral("robot_interfaces/msg/MissionStatus");
        project.corrections << connect;
        project.corrections << correction(QStringLiteral("c3"), Correction::Kind::Rename, navigator,
                                          QStringLiteral("navigator"),
                                          QStringLiteral("navigator_main"));
        m_corrected = CorrectedModel::apply(m_recovered, project);
        QStringList orphans;
        for (const Orphan &o : std::as_const(m_corrected.orphans))
            orphans << o.id + QStringLiteral(": ") + o.reason;
        QVERIFY2(orphans.isEmpty(), qPrintable(orphans.join(u'\n')));

        QVERIFY(m_out.isValid());
        QString error;
        QVERIFY2(ArtifactWriter::writeAll(m_corrected.recovery, m_out.path(), &m_written, &error),
                 qPrintable(error));
    }

    void theGuiWiresTheConnection()
    {
        // What the diagram draws: the system, as launched.
        const Composite *robot =
            systemOf(m_corrected.recovery.architecture, QStringLiteral("robot"));
        QVERIFY(robot);
        const auto ch =
            std::find_if(robot->channels.cbegin(), robot->channels.cend(), [](const Channel &c) {
                return c.name == QLatin1String("/robot1/mission/status");
            });
        QVERIFY(ch != robot->channels.cend());
        const QSet<QString> gui = connectionsOf(*robot);
        const QString mission = partTyped(*robot, QStringLiteral("mission"))->id;
        const QString navigation = partTyped(*robot, QStringLiteral("navigation"))->id;
        QStringList ends;
        for (const QString &k : gui)
            if (k.endsWith(QLatin1String(" /robot1/mission/status")))
                ends << k.section(u' ', 0, 1).section(u'_', 0, 0);
        ends.sort();
        QCOMPARE(ends, (QStringList{QStringLiteral("publish ") + mission,
                                    QStringLiteral("subscribe ") + navigation}));
    }

    void everyRootExportDrawsWhatTheGuiDraws()
    {
        // robot.launch.py is the root: its own CCD is the system the GUI draws, names spelled
        // from the file's scope. Every connection, the corrected one included, is the same.
        const Composite *robot =
            systemOf(m_corrected.recovery.architecture, QStringLiteral("robot"));
        const QString ccdText = written(QStringLiteral("ccd/robot.puml"));
        const WrittenCcd ccd = WrittenCcd::parse(ccdText);
        QVERIFY(!ccd.arrows.isEmpty());
        QCOMPARE(connectionsOf(ccd, ccdText), connectionsOf(*robot));
        QVERIFY(std::find(ccd.channels.cbegin(), ccd.channels.cend(),
                          QStringLiteral("robot1/mission/status")) != ccd.channels.cend());
        for (const Boundary &b : ccd.boundary)
            QVERIFY2(!b.name.contains(QLatin1String("mission")), qPrintable(b.name));

        const WrittenMermaid md =
            WrittenMermaid::parse(written(QStringLiteral("mermaid/robot.md")));
        const QString mission =
            QStringLiteral("part_") + partTyped(*robot, QStringLiteral("mission"))->id;
        const QString navigation =
            QStringLiteral("part_") + partTyped(*robot, QStringLiteral("navigation"))->id;
        const QString status = md.channels.key(QStringLiteral("robot1/mission/status"));
        QVERIFY2(!status.isEmpty(), qPrintable(QStringList(md.channels.values()).join(u',')));
        QVERIFY(md.arrows.contains(mission + QStringLiteral(" -> ") + status));
        QVERIFY(md.arrows.contains(status + QStringLiteral(" -> ") + navigation));
        for (const Boundary &b : md.boundary)
            QVERIFY2(!b.name.contains(QLatin1String("mission")), qPrintable(b.name));
        // as many arrows and channels as the GUI draws
        QCOMPARE(md.arrows.size(), robot->connections.size());
        QCOMPARE(md.channels.size(), robot->channels.size());

        const QString dot = written(QStringLiteral("graph/robot.dot"));
        QVERIFY(dot.contains(
            QLatin1String("\"node /robot1/mission_planner\" -> \"topic /robot1/mission/status\"")));
        QVERIFY(dot.contains(
            QLatin1String("\"topic /robot1/mission/status\" -> \"node /robot1/navigator_main\"")));
        QVERIFY(!dot.contains(QLatin1String("mission_status")));
    }

    void noExportLeavesAConnectionOnTheBoundary()
    {
        int diagrams = 0;
        QDirIterator it(m_out.path(), {QStringLiteral("*.puml"), QStringLiteral("*.md")},
                        QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString file = it.next();
            if (file.contains(QLatin1String("/acd/")))
                continue;
            const QString text = QString::fromUtf8(test::readFile(file));
            const bool mermaid = file.endsWith(QLatin1String(".md"));
            const QHash<QString, Boundary> boundary =
                mermaid ? WrittenMermaid::parse(text).boundary : WrittenCcd::parse(text).boundary;
            const QString pair = unwiredPair(boundary);
            QVERIFY2(pair.isEmpty(), qPrintable(file + QStringLiteral(": ") + pair));
            // the old name is gone everywhere: no channel, no boundary port is named so
            QStringList names = mermaid ? WrittenMermaid::parse(text).channels.values()
                                        : WrittenCcd::parse(text).channels.values();
            for (const Boundary &b : boundary)
                names << b.name;
            QVERIFY2(!names.isEmpty(), qPrintable(file));
            for (const QString &name : std::as_const(names))
                QVERIFY2(!name.contains(QLatin1String("mission_status")),
                         qPrintable(file + QStringLiteral(": ") + name));
            ++diagrams;
        }
        QCOMPARE(diagrams, 8); // four launch files, a CCD and a Mermaid diagram each
    }

    void eachFileSpellsTheConnectionInItsOwnScope()
    {
        // navigation.launch.xml and mission.launch.yaml on their own run in the root namespace:
        // the connection is theirs relative, a boundary port of the file, as the GUI's renamed
        // channel is there.
        const Composite *navigation =
            classifierOf(m_corrected.recovery.architecture, QStringLiteral("navigation"));
        const Composite *mission =
            classifierOf(m_corrected.recovery.architecture, QStringLiteral("mission"));
        QVERIFY(navigation && mission);
        const auto promotes = [](const Composite &c, const QString &name, bool in) {
            return std::any_of(c.boundary.cbegin(), c.boundary.cend(), [&](const BoundaryPort &b) {
                return b.name == name && b.isInput() == in;
            });
        };
        QVERIFY(promotes(*navigation, QStringLiteral("mission/status"), true));
        QVERIFY(promotes(*mission, QStringLiteral("mission/status"), false));
        const WrittenCcd ccd = WrittenCcd::parse(written(QStringLiteral("ccd/navigation.puml")));
        QVERIFY(std::any_of(ccd.boundary.cbegin(), ccd.boundary.cend(), [](const Boundary &b) {
            return b.in && b.name == QLatin1String("mission/status");
        }));
        // the renamed part keeps its new name in its file's CCD
        QVERIFY(written(QStringLiteral("ccd/navigation.puml"))
                    .contains(QLatin1String("\"navigator_main:\\nNavigator\"")));
    }

    void namesCarriedIntoAClassifier_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("system");
        QTest::addColumn<QString>("classifier");
        QTest::addColumn<QString>("relative");
        QTest::addColumn<QString>("carried");
        QTest::newRow("in the namespace, file alone") << "/robot1/odom"
                                                      << "/robot1"
                                                      << ""
                                                      << "odom"
                                                      << "odom";
        QTest::newRow("in the namespace, the file pushes it") << "/robot1/odom"
                                                              << "/robot1"
                                                              << "robot1"
                                                              << "odom"
                                                              << "robot1/odom";
        QTest::newRow("deeper") << "/robot1/nav/odom"
                                << "/robot1/"
                                << "/"
                                << "nav/odom"
                                << "nav/odom";
        QTest::newRow("outside the namespace") << "/cmd_vel"
                                               << "/robot1"
                                               << "robot1"
                                               << "/cmd_vel"
                                               << "/cmd_vel";
        QTest::newRow("a sibling namespace") << "/robot10/odom"
                                             << "/robot1"
                                             << ""
                                             << "/robot10/odom"
                                             << "/robot10/odom";
        QTest::newRow("root namespace: nothing tells") << "/scan"
                                                       << "/"
                                                       << ""
                                                       << "/scan"
                                                       << "/scan";
        QTest::newRow("already relative") << "scan"
                                          << "/robot1"
                                          << "robot1"
                                          << "scan"
                                          << "robot1/scan";
        QTest::newRow("the namespace itself") << "/robot1"
                                              << "/robot1"
                                              << ""
                                              << "/robot1"
                                              << "/robot1";
    }

    void namesCarriedIntoAClassifier()
    {
        QFETCH(QString, name);
        QFETCH(QString, system);
        QFETCH(QString, classifier);
        QFETCH(QString, relative);
        QFETCH(QString, carried);
        QCOMPARE(ClassifierCorrections::relativeTo(name, system), relative);
        QCOMPARE(ClassifierCorrections::carried(name, system, classifier), carried);
    }

    void correctedExportsRenderInPlantUml()
    {
        const QString jar = QStringLiteral(ROSARCH_PLANTUML_JAR);
        const QString java = QStringLiteral(ROSARCH_JAVA);
        QVERIFY2(
            QFileInfo::exists(jar),
            qPrintable(QStringLiteral("%1 is missing: run scripts/fetch-plantuml.sh").arg(jar)));
        QVERIFY2(!java.isEmpty() && QFileInfo(java).isExecutable(),
                 "java is missing: install default-jre-headless (setup.sh does)re");
        QStringList files;
        for (const QString &f : std::as_const(m_written))
            if (f.endsWith(QLatin1String(".puml")) && f.contains(QLatin1String("/ccd/")))
                files << f;
        QCOMPARE(files.size(), 4);
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
        // the corrected channel is drawn in the rendered root CCD
        const QString svg = QString::fromUtf8(
            test::readFile(QDir(m_out.path()).filePath(QStringLiteral("ccd/robot.svg"))));
        QVERIFY(svg.contains(QLatin1String(">robot1/mission/status<")));
    }

    void correctedExportsParseInMermaid()
    {
        const QDir modules(QStringLiteral(ROSARCH_MERMAID_DIR));
        QVERIFY2(modules.exists(QStringLiteral("node_modules/mermaid/package.json")),
                 "Mermaid's parser is missing: run scripts/fetch-mermaid.sh build/_mermaid "
                 "(./setup.sh does)re");
        QStringList files;
        for (const QString &f : std::as_const(m_written))
            if (f.endsWith(QLatin1String(".md")))
                files << f;
        QCOMPARE(files.size(), 4);
        QProcess node;
        node.setProcessChannelMode(QProcess::MergedChannels);
        node.start(QStringLiteral(ROSARCH_NODE),
                   QStringList{QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                                   .filePath(QStringLiteral("tests/support/parse-mermaid.mjs")),
                               modules.path()} +
                       files);
        QVERIFY(node.waitForFinished(120000));
        QVERIFY2(node.exitCode() == 0, node.readAll().constData());
    }
};

QTEST_GUILESS_MAIN(TestCorrectedExports)
#include "tst_correctedexports.moc"
