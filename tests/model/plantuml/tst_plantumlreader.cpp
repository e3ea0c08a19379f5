// The PlantUML reader on ACDs, several diagrams per file, the blueprint examples and our ACD
// writer read back; the CCD cases are in tst_plantumlccdreader.cpp.
#include "plantuml/acdwriter.h"
#include "plantuml/plantumlreader.h"
#include "plantuml/umlmodel.h"
#include "support/testsupport.h"
#include "support/umltestsupport.h"

#include <QDir>
#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::uml;

namespace {

Port makePort(const QString &id, PortKind kind, const QString &name, const QString &type,
              const QString &callback)
{
    Port p;
    p.id = id;
    p.kind = kind;
    p.name = name;
    p.type = type;
    p.callback = callback;
    return p;
}

} // namespace

class TestPlantUmlReader : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void ourAcd()
    {
        const UmlDiagram d = readOne(QString::fromUtf8(kAcd));
        QCOMPARE(d.level, UmlLevel::Acd);
        QCOMPARE(d.name, QStringLiteral("Talker"));
        QCOMPARE(d.file, QStringLiteral("/refs/some_file.puml"));
        QCOMPARE(describe(d), sorted(kAcdElements));
        QCOMPARE(d.notes, QStringList());
        QCOMPARE(d.warnings, QStringList());
        // Elements keep the line they were read from.
        QCOMPARE(d.elements.first().line, 2);
        QCOMPARE(d.values(UmlKind::ServiceFunction), QStringList{QStringLiteral("on_reset")});
    }

    void acdVariants_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QStringList>("elements");
        QTest::addColumn<QStringList>("notes");
        QTest::addColumn<QStringList>("warnings");
        const QStringList node = {QStringLiteral("arc_name=Talker"),
                                  QStringLiteral("arc_stereotype=AtomicRosNodeClassifier")};

        QTest::newRow("stereotype after the alias, misspelled and lower-case")
            << QStringLiteral(
                   "@startuml\ncomponent \"Talker\" as node <<atomicrosnodeclasifier>> {\n"
                   "  portin \"on_cmd\" as s1\n}\n@enduml\n")
            << node + QStringList{QStringLiteral("callback=on_cmd")}
            << QStringList{QStringLiteral(
                   "line 2: stereotype 'atomicrosnodeclasifier' read as AtomicRosNodeClassifier")}
            << QStringList();
        QTest::newRow("stereotype only differently cased")
            << QStringLiteral("component \"<<atomicRosNodeClassifier>>\\nTalker\" as node\n")
            << node
            << QStringList{QStringLiteral(
                               "line 1: no @startuml; read the whole text as one diagram"),
                           QStringLiteral("line 1: stereotype 'atomicRosNodeClassifier' read as "
                                          "AtomicRosNodeClassifier")}
            << QStringList();
        QTest::newRow("types as pkg/msg/T and pkg/T, without **, kind from the context")
            << QStringLiteral(R"uml(@startuml
component "<<AtomicRosNodeClassifier>>\nTalker" as node
frame "s1" as topic_s1 {
  rectangle "geometry_msgs/Twist" as t_s1
}
frame "p1" as topic_p1 {
  rectangle "std_msgs/msg/String" as t_p1
}
folder "ps1" as srv_ps1 {
  rectangle "std_srvs/Trigger" as st_ps1
  rectangle "on_reset(...)" as sf_ps1
}
folder "pa1" as act_pa1 {
  rectangle "**nav2_msgs::NavigateToPose**" as at_pa1
  rectangle "Talker::on_goal" as af_pa1
}
folder "ra1" as act_ra1 {
  rectangle "nav2_msgs/action/Spin" as at_ra1
}
@enduml
)uml")
            << node + QStringList{QStringLiteral("message_type=geometry_msgs/msg/Twist"),
                                  QStringLiteral("message_type=std_msgs/msg/String"),
                                  QStringLiteral("service_type=std_srvs/srv/Trigger"),
                                  QStringLiteral("service_function=on_reset"),
                                  QStringLiteral("action_type=nav2_msgs/action/NavigateToPose"),
                                  QStringLiteral("action_function=on_goal"),
                                  QStringLiteral("action_type=nav2_msgs/action/Spin")}
            << QStringList{QStringLiteral("line 4: type 'geometry_msgs/Twist' read as "
                                          "geometry_msgs/msg/Twist"),
                           QStringLiteral(
                               "line 10: type 'std_srvs/Trigger' read as std_srvs/srv/Trigger"),
                           QStringLiteral("line 14: type 'nav2_msgs::NavigateToPose' read as "
                                          "nav2_msgs/action/NavigateToPose"),
                           QStringLiteral("line 15: function 'Talker::on_goal' read as on_goal")}
            << QStringList();
        QTest::newRow("callbacks as arrow labels, arrows either way round")
            << QStringLiteral(R"uml(@startuml
component "<<AtomicRosNodeClassifier>>\nTalker" as node {
  portin " " as s1
  portin "s2" as s2
  portin "old_name" as s3
}
frame "s1" as topic_s1 {
  rectangle "**geometry_msgs::msg::Twist**" as t_s1
}
frame "s2" as topic_s2 {
  rectangle "**nav_msgs::msg::Odometry**" as t_s2
}
frame "s3" as topic_s3 {
  rectangle "**std_msgs::msg::Empty**" as t_s3
}
topic_s1 ---> s1 : on_cmd
s2 <-- topic_s2 : on_odom()
t_s3 -[#blue,bold]-> s3 : "on_empty"
@enduml
)uml")
            << node + QStringList{QStringLiteral("callback=on_cmd"),
                                  QStringLiteral("callback=on_odom"),
                                  QStringLiteral("callback=on_empty"),
                                  QStringLiteral("message_type=geometry_msgs/msg/Twist"),
                                  QStringLiteral("message_type=nav_msgs/msg/Odometry"),
                                  QStringLiteral("message_type=std_msgs/msg/Empty")}
            << QStringList{QStringLiteral(
                               "line 4: label 's2' of port s2 names the port, not a callback"),
                           QStringLiteral(
                               "line 16: callback 'on_cmd' of port s1 taken from the arrow label"),
                           QStringLiteral("line 17: callback 'on_odom()' of port s2 taken from the "
                                          "arrow label"),
                           QStringLiteral("line 18: callback of port s3 is 'on_empty' on the arrow "
                                          "but 'old_name' "
                                          "on the port; the arrow's is read")}
            << QStringList();
        QTest::newRow("comments, title, skinparam, theme, backslash-newline, no @startuml")
            << QStringLiteral(R"uml(!theme plain
title Talker ACD
skinparam componentStyle uml2
skinparam component {
  BackgroundColor white
}
/' a block comment
component "Fake" as fake <<AtomicRosNodeClassifier>>
'/
' component "Other" as other <<AtomicRosNodeClassifier>>
component "<<AtomicRosNodeClassifier>>\
Talker" as node {   ' the node
  portin "on_cmd" as s1 /' inline '/
}
frame "s1" as topic_s1 {
  rectangle "**geometry_msgs::msg::Twist**" as t_s1
}
note right of node : a note
legend
  component "Legend" as legend <<AtomicRosNodeClassifier>>
endlegend
)uml")
            << node + QStringList{QStringLiteral("callback=on_cmd"),
                                  QStringLiteral("message_type=geometry_msgs/msg/Twist")}
            << QStringList{QStringLiteral(
                               "line 1: no @startuml; read the whole text as one diagram"),
                           QStringLiteral("line 11: backslash-newline joined with line 12")}
            << QStringList();
        QTest::newRow("unreadable lines are warnings")
            << QStringLiteral(
                   "@startuml\ncomponent \"<<AtomicRosNodeClassifier>>\\nTalker\" as node\n"
                   "this is not plantuml\nnode --> : on_x\n@enduml\n")
            << node << QStringList()
            << QStringList{QStringLiteral("line 3: cannot read 'this is not plantuml'"),
                           QStringLiteral("line 4: cannot read 'node --> : on_x'")};
    }

    void acdVariants()
    {
        QFETCH(QString, text);
        QFETCH(QStringList, elements);
        QFETCH(QStringList, notes);
        QFETCH(QStringList, warnings);
        const UmlDiagram d = readOne(text);
        QCOMPARE(d.level, UmlLevel::Acd);
        QCOMPARE(d.name, QStringLiteral("Talker"));
        QCOMPARE(describe(d), sorted(elements));
        QCOMPARE(d.notes, notes);
        QCOMPARE(d.warnings, warnings);
    }

    void blueprintExamplesVerbatim()
    {
        // The notation examples of blueprint §3, copied with their trailing ' comments.
        UmlModel acd, ccd;
        QString error;
        QVERIFY(UmlModel::load(test::dataDir(QStringLiteral("eval_blueprint/ClassName.puml")), &acd,
                               &error));
        QVERIFY(UmlModel::load(test::dataDir(QStringLiteral("eval_blueprint/launch_stem.puml")),
                               &ccd, &error));
        QCOMPARE(acd.diagrams.size(), 1);
        QCOMPARE(ccd.diagrams.size(), 1);
        const UmlDiagram &a = acd.diagrams.first();
        QCOMPARE(a.level, UmlLevel::Acd);
        QCOMPARE(a.name, QStringLiteral("ClassName"));
        QCOMPARE(describe(a), sorted({QStringLiteral("arc_name=ClassName"),
                                      QStringLiteral("arc_stereotype=AtomicRosNodeClassifier"),
                                      QStringLiteral("callback=callback_name"),
                                      QStringLiteral("message_type=pkg/msg/Type"),
                                      QStringLiteral("service_type=pkg/srv/Type"),
                                      QStringLiteral("service_type=pkg/srv/Type"),
                                      QStringLiteral("service_function=handler_name")}));
        QCOMPARE(a.notes, QStringList{QStringLiteral(
                              "line 1: no @startuml; read the whole text as one diagram")});
        QCOMPARE(a.warnings, QStringList());

        const UmlDiagram &c = ccd.diagrams.first();
        QCOMPARE(c.level, UmlLevel::Ccd);
        QCOMPARE(c.name, QStringLiteral("launch_stem"));
        QCOMPARE(
            describe(c),
            sorted(
                {QStringLiteral("part=node_name"), QStringLiteral("part=included_launch_stem"),
                 QStringLiteral("part_type=node_name:ClassName"),
                 QStringLiteral("part_type=:included_launch_stem"),
                 QStringLiteral("namespace=(left, node_name)"),
                 QStringLiteral("namespace=(left, included_launch_stem)"),
                 QStringLiteral("topic=topic"), QStringLiteral("service=service"),
                 QStringLiteral("boundary_port=(in, pkg/msg/Type)"),
                 QStringLiteral("boundary_port=(out, pkg/msg/Type)"),
                 QStringLiteral("connection=publish node_name -> topic"),
                 QStringLiteral("connection=delegation boundary:in/pkg/msg/Type -> node_name"),
                 QStringLiteral("connection=delegation node_name -> boundary:out/pkg/msg/Type")}));
        // The example's part2 { ... } declares no ports and part3/part4 are not declared at all.
        QCOMPARE(
            c.warnings,
            (QStringList{
                QStringLiteral("line 14: arrow end 'part2_s1' is not declared; arrow ignored"),
                QStringLiteral("line 15: arrow end 'part3_rs1' is not declared; arrow ignored"),
                QStringLiteral("line 16: arrow end 'part4_ps1' is not declared; arrow ignored")}));
    }

    void neitherAcdNorCcd()
    {
        const UmlDiagram d = readOne(QStringLiteral("@startuml\ncomponent A\nA --> B\n@enduml\n"));
        QCOMPARE(d.level, UmlLevel::Unknown);
        QVERIFY(d.elements.isEmpty());
        QCOMPARE(d.warnings, QStringList{QStringLiteral(
                                 "line 1: neither an ACD nor a CCD: no "
                                 "<<AtomicRosNodeClassifier>>, <<ComposedRosNodeClassifier>> "
                                 "or <<RosNodePart>> found")});
    }

    void severalBlocksInOneFile()
    {
        const QList<UmlDiagram> all = PlantUmlReader::read(
            QString::fromUtf8(kAcd) + QString::fromUtf8(kCcd), QStringLiteral("x.puml"));
        QCOMPARE(all.size(), 2);
        QCOMPARE(all.at(0).level, UmlLevel::Acd);
        QCOMPARE(all.at(1).level, UmlLevel::Ccd);
        QCOMPARE(describe(all.at(1)), sorted(kCcdElements));
    }

    void fuzzerFindingsReadWithoutCrashing()
    {
        // Inputs libFuzzer found crashing the reader (tests/fuzz/corpus/fuzz_plantuml/
        // regression-*): each must read, to whatever it says, without a crash.
        const QDir corpus(QStringLiteral(ROSARCH_SOURCE_DIR "/tests/fuzz/corpus/fuzz_plantuml"));
        const QStringList found = corpus.entryList({QStringLiteral("regression-*")}, QDir::Files);
        QVERIFY(!found.isEmpty());
        for (const QString &f : found) {
            QFile file(corpus.filePath(f));
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QList<UmlDiagram> diagrams =
                PlantUmlReader::read(QString::fromUtf8(file.readAll()));
            QVERIFY(!diagrams.isEmpty());
        }
    }

    void ourAcdWriterReadsBack()
    {
        AtomicNode n;
        n.id = QStringLiteral("arc_1");
        n.className = QStringLiteral("Talker");
        n.qualifiedName = QStringLiteral("demo::Talker");
        n.packageName = QStringLiteral("demo");
        Port pub = makePort(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("chatter"),
                            QStringLiteral("std_msgs/msg/String"), {});
        pub.guard = QStringLiteral("use_chatter"); // written as a comment line before the frame
        Port sub = makePort(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("~/cmd"),
                            QStringLiteral("geometry_msgs/msg/Twist"), QStringLiteral("on_cmd"));
        sub.nameOrigin = NameOrigin::Parameter;
        sub.parameter = QStringLiteral("cmd_topic");
        n.ports = {pub,
                   sub,
                   makePort(QStringLiteral("s2"), PortKind::Subscriber, QStringLiteral("odom"),
                            QStringLiteral("nav_msgs/msg/Odometry"), {}),
                   makePort(QStringLiteral("s3"), PortKind::Subscriber, QStringLiteral("raw"), {},
                            QStringLiteral("lambda")),
                   makePort(QStringLiteral("ps1"), PortKind::ServiceServer, QStringLiteral("reset"),
                            QStringLiteral("std_srvs/srv/Trigger"), QStringLiteral("on_reset")),
                   makePort(QStringLiteral("rs1"), PortKind::ServiceClient, QStringLiteral("map"),
                            QStringLiteral("nav_msgs/srv/GetMap"), {}),
                   makePort(QStringLiteral("pa1"), PortKind::ActionServer,
                            QStringLiteral("navigate"),
                            QStringLiteral("nav2_msgs/action/NavigateToPose"),
                            QStringLiteral("handle_goal")),
                   makePort(QStringLiteral("ra1"), PortKind::ActionClient, QStringLiteral("spin"),
                            QStringLiteral("nav2_msgs/action/Spin"), {})};
        const QString text = AcdWriter::write(n);
        const QList<UmlDiagram> all = PlantUmlReader::read(text, QStringLiteral("acd/Talker.puml"));
        QCOMPARE(all.size(), 1);
        const UmlDiagram &d = all.first();
        QCOMPARE(d.level, UmlLevel::Acd);
        QCOMPARE(d.name, QStringLiteral("Talker"));
        QCOMPARE(describe(d),
                 sorted({QStringLiteral("arc_name=Talker"),
                         QStringLiteral("arc_stereotype=AtomicRosNodeClassifier"),
                         QStringLiteral("callback=on_cmd"), QStringLiteral("callback=lambda"),
                         QStringLiteral("message_type=std_msgs/msg/String"),
                         QStringLiteral("message_type=geometry_msgs/msg/Twist"),
                         QStringLiteral("message_type=nav_msgs/msg/Odometry"),
                         QStringLiteral("message_type=?"),
                         QStringLiteral("service_type=std_srvs/srv/Trigger"),
                         QStringLiteral("service_function=on_reset"),
                         QStringLiteral("service_type=nav_msgs/srv/GetMap"),
                         QStringLiteral("action_type=nav2_msgs/action/NavigateToPose"),
                         QStringLiteral("action_function=handle_goal"),
                         QStringLiteral("action_type=nav2_msgs/action/Spin")}));
        QVERIFY2(d.notes.isEmpty(),
                 qPrintable(d.notes.join(QLatin1Char('\n')) + QLatin1Char('\n') + text));
        QVERIFY2(d.warnings.isEmpty(),
                 qPrintable(d.warnings.join(QLatin1Char('\n')) + QLatin1Char('\n') + text));
    }
};

QTEST_GUILESS_MAIN(TestPlantUmlReader)
#include "tst_plantumlreader.moc"
