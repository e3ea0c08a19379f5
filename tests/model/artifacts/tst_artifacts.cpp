#include "artifacts/artifactcommit.h"
#include "artifacts/artifactwriter.h"
#include "artifacts/atomicnodesjson.h"
#include "plantuml/acdwriter.h"
#include "support/testsupport.h"

#include <QTemporaryDir>

#include <QtTest>
#include <sys/stat.h>
#include <unistd.h>

using namespace rosarch;

namespace {
Evidence at(const QString &file, int line)
{
    return Evidence{file, line, 5, line, 40};
}

AtomicNodeList sampleList()
{
    AtomicNodeList list;
    list.workspaceRoot = QStringLiteral("/ws");
    RosPackage pkg;
    pkg.name = QStringLiteral("demo");
    pkg.buildType = QStringLiteral("ament_cmake");
    pkg.path = QStringLiteral("src/demo");
    list.packages << pkg;

    AtomicNode n;
    n.id = QStringLiteral("arc_1");
    n.className = QStringLiteral("Talker");
    n.qualifiedName = QStringLiteral("demo::Talker");
    n.nodeName = QStringLiteral("talker");
    n.packageName = QStringLiteral("demo");
    n.headerFiles << QStringLiteral("src/demo/include/talker.hpp");
    n.sourceFiles << QStringLiteral("src/demo/src/talker.cpp");
    n.compileType = AtomicNode::CompileType::Cpp;
    n.executables << QStringLiteral("talker");
    n.plugins << QStringLiteral("demo::Talker");
    n.baseClasses << QStringLiteral("rclcpp::Node");
    n.evidence = at(QStringLiteral("src/demo/include/talker.hpp"), 3);

    Port pub;
    pub.id = QStringLiteral("p1");
    pub.kind = PortKind::Publisher;
    pub.name = QStringLiteral("chatter");
    pub.type = QStringLiteral("std_msgs/msg/String");
    pub.nameOrigin = NameOrigin::Parameter;
    pub.parameter = QStringLiteral("topic");
    pub.nameExpression = QStringLiteral("topic_");
    pub.evidence = at(QStringLiteral("src/demo/src/talker.cpp"), 10);
    Port sub;
    sub.id = QStringLiteral("s1");
    sub.kind = PortKind::Subscriber;
    sub.name = QStringLiteral("~/in");
    sub.type = QStringLiteral("std_msgs/msg/String");
    sub.callback = QStringLiteral("on_in");
    sub.evidence = at(QStringLiteral("src/demo/src/talker.cpp"), 11);
    Port srv;
    srv.id = QStringLiteral("ps1");
    srv.kind = PortKind::ServiceServer;
    srv.name = QStringLiteral("reset");
    srv.type = QStringLiteral("std_srvs/srv/Empty");
    srv.callback = QStringLiteral("handle_reset");
    srv.guard = QStringLiteral("use_reset");
    srv.guardParameter = QStringLiteral("use_reset");
    srv.evidence = at(QStringLiteral("src/demo/src/talker.cpp"), 13);
    Port cli;
    cli.id = QStringLiteral("ra1");
    cli.kind = PortKind::ActionClient;
    cli.name = QStringLiteral("fibonacci");
    cli.type = QStringLiteral("demo/action/Fibonacci");
    cli.via = QStringLiteral("Helper");
    cli.inherited = true;
    cli.evidence = at(QStringLiteral("src/demo/src/talker.cpp"), 15);
    cli.viaEvidence = {at(QStringLiteral("src/demo/src/talker.cpp"), 30),
                       at(QStringLiteral("src/demo/src/helper.cpp"), 7)};
    n.ports << pub << sub << srv << cli;
    list.nodes << n;

    AtomicNode twin = n;
    twin.id = QStringLiteral("arc_2");
    twin.packageName = QString();
    twin.ports.clear();
    list.nodes << twin;
    return list;
}
} // namespace

class TestArtifacts : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void jsonHasBlueprintFieldsAndRoundTrips()
    {
        const AtomicNodeList list = sampleList();
        const QByteArray json = AtomicNodesJson::write(list);
        for (const char *field :
             {"\"list_packages\"", "\"package_name\"", "\"list_atomic_ros_node_classifiers\"",
              "\"id\": \"arc_1\"", "\"class_name\": \"Talker\"", "\"node_name\": \"talker\"",
              "\"header_file_paths\"", "\"source_file_paths\"", "\"description\"",
              "\"compile_type\": \"cpp\"", "\"execution\": \"talker\"", "\"end_column\": 40",
              "\"via_evidence\""})
            QVERIFY2(json.contains(field), field);

        AtomicNodeList back;
        QString error;
        QVERIFY2(AtomicNodesJson::read(json, &back, &error), qPrintable(error));
        QCOMPARE(back.nodes.size(), 2);
        QCOMPARE(back.nodes[0].ports, list.nodes[0].ports);
        QCOMPARE(back.nodes[0].plugins, list.nodes[0].plugins);
        QCOMPARE(back.nodes[0].evidence, list.nodes[0].evidence);
        QCOMPARE(back.nodes[1].packageName, QString());
        QCOMPARE(AtomicNodesJson::write(back).size() > 0, true);
    }

    void jsonReadRejectsMalformedInput()
    {
        AtomicNodeList list;
        QString error;
        QVERIFY(!AtomicNodesJson::read("{not json", &list, &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(!AtomicNodesJson::read("{\"x\": 1}", &list, &error));
        QCOMPARE(error, QStringLiteral("missing list_packages"));
        QVERIFY(!AtomicNodesJson::read(
            R"({"list_packages":[{"package_name":"p","list_atomic_ros_node_classifiers":[{"ports":[{"kind":"timer"}]}]}]})",
            &list, &error));
        QVERIFY(error.contains(QStringLiteral("timer")));
    }

    void acdFollowsBlueprintNotation()
    {
        const QString acd = AcdWriter::write(sampleList().nodes[0]);
        const QString expected =
            QStringLiteral("@startuml\n"
                           "' demo::Talker (cpp) in package demo\n"
                           "component \"<<AtomicRosNodeClassifier>>\\nTalker\" as node {\n"
                           "  portout \" \" as p1\n"
                           "  portin \"on_in\" as s1\n"
                           "}\n"
                           "  ' name from parameter 'topic'\n"
                           "frame \"p1\\nchatter\" as topic_p1 {\n"
                           "  rectangle \"**std_msgs::msg::String**\" as t_p1\n"
                           "}\n"
                           "frame \"s1\\n~/in\" as topic_s1 {\n"
                           "  rectangle \"**std_msgs::msg::String**\" as t_s1\n"
                           "}\n"
                           "  ' guard: use_reset\n"
                           "folder \"ps1\\nreset\" as srv_ps1 {\n"
                           "  rectangle \"**std_srvs::srv::Empty**\" as st_ps1\n"
                           "  rectangle \"handle_reset(...)\" as sf_ps1\n"
                           "}\n"
                           "  ' via Helper; inherited\n"
                           "folder \"ra1\\nfibonacci\" as act_ra1 {\n"
                           "  rectangle \"**demo::action::Fibonacci**\" as at_ra1\n"
                           "}\n"
                           "p1 -[#green,bold]-> topic_p1\n"
                           "topic_s1 -[#blue,bold]-> s1\n"
                           "node --0 srv_ps1\n"
                           "node --( act_ra1\n"
                           "@enduml\n");
        QCOMPARE(acd, expected);
    }

    void fileStemsDisambiguateSharedClassNames()
    {
        const auto stems = AcdWriter::fileStems(sampleList());
        QCOMPARE(stems.value(QStringLiteral("arc_1")), QStringLiteral("demo.Talker"));
        QCOMPARE(stems.value(QStringLiteral("arc_2")), QStringLiteral("Talker"));
    }

    void writerProducesFixedLayoutAndDropsStaleDiagrams()
    {
        QTemporaryDir dir;
        QDir(dir.path()).mkpath(QStringLiteral("acd"));
        QFile stale(dir.filePath(QStringLiteral("acd/Old.puml")));
        QVERIFY(stale.open(QIODevice::WriteOnly));
        stale.close();
        AtomicNodeList list = sampleList();
        Diagnostic d;
        d.code = QStringLiteral("syntax-error");
        d.message = QStringLiteral("broken");
        d.evidence = at(QStringLiteral("x.py"), 2);
        list.diagnostics << d;
        QStringList written;
        QString error;
        QVERIFY2(ArtifactWriter::writeAll(list, dir.path(), &written, &error), qPrintable(error));
        QCOMPARE(written.size(), 4);
        QVERIFY(QFile::exists(dir.filePath(QStringLiteral("atomic_nodes.json"))));
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("acd/Old.puml"))));
        QVERIFY(QFile::exists(dir.filePath(QStringLiteral("acd/demo.Talker.puml"))));
        QVERIFY(QFile::exists(dir.filePath(QStringLiteral("acd/Talker.puml"))));
        const QByteArray diag = test::readFile(dir.filePath(QStringLiteral("diagnostics.json")));
        QVERIFY(diag.contains("\"code\": \"syntax-error\""));
        QVERIFY(diag.contains("\"line\": 2"));
    }

    void theFolderIsSwappedWholeAndUnchangedFilesStay()
    {
        // The artifacts go into a fresh folder beside the output folder, swapped in
        // with one rename; a file equal to its previous version is linked, not written again;
        // what is not an artifact stays; staging folders of dead runs are removed.
        QTemporaryDir parent;
        const QString out = parent.filePath(QStringLiteral("out"));
        auto inode = [](const QString &path) {
            struct stat st = {};
            return ::stat(QFile::encodeName(path).constData(), &st) == 0 ? st.st_ino : ino_t(0);
        };
        auto write = [&](const QByteArray &a, const QByteArray &b) {
            ArtifactCommit commit(out);
            QString error;
            QStringList written;
            QVERIFY2(commit.begin(&error) &&
                         commit.add(QStringLiteral("atomic_nodes.json"), a, &error) &&
                         commit.add(QStringLiteral("acd/A.puml"), b, &error) &&
                         commit.commit(&written, &error),
                     qPrintable(error));
            QCOMPARE(written.size(), 2);
        };
        write("{}", "@startuml\n@enduml\n");
        test::writeFile(out + QStringLiteral("/notes.txt"), "mine\n");
        test::writeFile(out + QStringLiteral("/acd/A.svg"), "<svg/>");
        test::writeFile(out + QStringLiteral("/render/x.png"), "png");
        // A staging folder of a killed run (no such process) and one of a live process.
        const QString dead = parent.filePath(QStringLiteral(".out.rosarch-writing-999999999-x"));
        const QString live =
            parent.filePath(QStringLiteral(".out.rosarch-writing-%1-y").arg(getppid()));
        QVERIFY(QDir().mkpath(dead) && QDir().mkpath(live));
        const ino_t json = inode(out + QStringLiteral("/atomic_nodes.json"));
        const ino_t acd = inode(out + QStringLiteral("/acd/A.puml"));
        write("{}", "@startuml\nchanged\n@enduml\n");
        QCOMPARE(inode(out + QStringLiteral("/atomic_nodes.json")), json); // unchanged: linked
        QVERIFY(inode(out + QStringLiteral("/acd/A.puml")) != acd);
        QCOMPARE(test::readFile(out + QStringLiteral("/acd/A.puml")),
                 QByteArray("@startuml\nchanged\n@enduml\n"));
        QCOMPARE(test::readFile(out + QStringLiteral("/notes.txt")), QByteArray("mine\n"));
        QCOMPARE(test::readFile(out + QStringLiteral("/render/x.png")), QByteArray("png"));
        QVERIFY(!QFile::exists(out + QStringLiteral("/acd/A.svg"))); // a picture of the old ACD
        QVERIFY(!QFileInfo::exists(dead));
        QVERIFY(QFileInfo::exists(live));
        QDir(live).removeRecursively();
        QCOMPARE(
            QDir(parent.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
            QStringList{QStringLiteral("out")});
    }

    void aFolderThatCannotBeSwappedIsSaid()
    {
        // A FIFO in the output folder cannot be carried into the fresh one: the artifacts are
        // moved in one by one, the FIFO stays, and the writer says why instead of staying
        // silent about the weaker guarantee. A folder that can be swapped says nothing.
        QTemporaryDir parent;
        const QString out = parent.filePath(QStringLiteral("out"));
        QStringList written;
        QString error, notice = QStringLiteral("unset");
        Recovery r;
        QVERIFY2(ArtifactWriter::writeAll(r, out, &written, &error, {}, &notice),
                 qPrintable(error));
        QCOMPARE(notice, QString());
        QVERIFY(::mkfifo(QFile::encodeName(out + QStringLiteral("/pipe")).constData(), 0600) == 0);
        r.nodes.diagnostics.append({Diagnostic::Severity::Info,
                                    QStringLiteral("x"),
                                    QStringLiteral("changed"),
                                    {},
                                    {},
                                    {},
                                    {}});
        QVERIFY2(ArtifactWriter::writeAll(r, out, &written, &error, {}, &notice),
                 qPrintable(error));
        QCOMPARE(notice, QStringLiteral("The artifacts in %1 were replaced file by file, not in "
                                        "one step, because its entry pipe cannot be carried "
                                        "over (a special file, or another file system): a run "
                                        "killed meanwhile could have left old and new files "
                                        "mixed.")
                             .arg(out));
        QVERIFY(test::readFile(out + QStringLiteral("/diagnostics.json")).contains("changed"));
        QVERIFY(QFileInfo(out + QStringLiteral("/pipe")).exists());
    }

    void anUnchangedResultIsNotWrittenAgain()
    {
        // Unchanged artifacts are not written again: a stamp of what they were made from,
        // with each file's size and time, lets the next run skip the writing.
        QTemporaryDir dir;
        auto inode = [&](const QString &relative) {
            struct stat st = {};
            return ::stat(QFile::encodeName(dir.filePath(relative)).constData(), &st) == 0
                       ? st.st_ino
                       : ino_t(0);
        };
        QStringList written;
        QString error;
        QVERIFY2(ArtifactWriter::writeAll(sampleList(), dir.path(), &written, &error),
                 qPrintable(error));
        const QString stamp = QString::fromLatin1(ArtifactCommit::kStampFile);
        const ino_t first = inode(stamp);
        QVERIFY(first != 0);
        written.clear();
        QVERIFY(ArtifactWriter::writeAll(sampleList(), dir.path(), &written, &error));
        QCOMPARE(written.size(), 4);
        QCOMPARE(inode(stamp), first); // nothing written
        // An artifact edited since is noticed: everything is written again.
        const QString acd = dir.filePath(QStringLiteral("acd/Talker.puml"));
        const QByteArray original = test::readFile(acd);
        test::writeFile(acd, original + "' edited\n");
        QVERIFY(ArtifactWriter::writeAll(sampleList(), dir.path(), &written, &error));
        QVERIFY(inode(stamp) != first);
        QCOMPARE(test::readFile(acd), original);
        // Another result: written again.
        AtomicNodeList other = sampleList();
        other.nodes.removeLast();
        const ino_t second = inode(stamp);
        QVERIFY(ArtifactWriter::writeAll(other, dir.path(), &written, &error));
        QVERIFY(inode(stamp) != second);

        // A run killed while writing left its staging folder; the next run finds the result
        // unchanged and writes nothing, but removes that folder all the same.
        QTemporaryDir parent;
        const QString out = parent.filePath(QStringLiteral("out"));
        QVERIFY(ArtifactWriter::writeAll(sampleList(), out, &written, &error));
        const QString dead = parent.filePath(QStringLiteral(".out.rosarch-writing-999999999-x"));
        QVERIFY(QDir().mkpath(dead + QStringLiteral("/acd")));
        QVERIFY(ArtifactWriter::writeAll(sampleList(), out, &written, &error));
        QVERIFY(!QFileInfo::exists(dead));
    }

    void writerReportsUnwritableFolder()
    {
        QTemporaryDir dir;
        QFile blocker(dir.filePath(QStringLiteral("file")));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        QStringList written;
        QString error;
        QVERIFY(!ArtifactWriter::writeAll(sampleList(), dir.filePath(QStringLiteral("file/sub")),
                                          &written, &error));
        QVERIFY(error.contains(QStringLiteral("Cannot create")));
    }
};

QTEST_GUILESS_MAIN(TestArtifacts)
#include "tst_artifacts.moc"
