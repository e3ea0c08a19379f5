// Corrections in the Document (blueprint §5): each one of the fixture project, made one by one,
// gives the same model as the corrected-model function; every one undoes and redoes; removing
// one reverts it; and re-running the stages on the same workspace keeps them, by key.
#include "document/document.h"
#include "project/correctedmodel.h"
#include "support/acceptedwait.h"
#include "support/documentchanges.h"
#include "support/testsupport.h"

#include <QDirIterator>
#include <QSignalSpy>
#include <QtTest>

#include <pwd.h>
#include <unistd.h>

using namespace rosarch;

namespace {

QString caseDir()
{
    return test::dataDir(QStringLiteral("project_corrections"));
}

Project fixtureCorrections()
{
    Project p;
    QString error;
    if (!ProjectFile::read(QDir(caseDir()).filePath(QStringLiteral("rosarch.project.json")), &p,
                           &error))
        qWarning("%s", qPrintable(error));
    p.decisions.clear(); // corrections only: there are no suggestions here
    return p;
}

/// What the composites say, without the positional ids that a code change shifts.
QStringList shape(const Architecture &arch)
{
    QStringList out;
    for (const Composite &c : arch.composites) {
        for (const RosNodePart &part : c.parts) {
            out << QStringLiteral("%1 %2 %3 %4 %5")
                       .arg(c.file, part.name, part.typeName, part.subsystem)
                       .arg(int(part.marks.provenance));
            for (const PartPort &p : part.ports)
                out << QStringLiteral("  %1 %2 %3 %4")
                           .arg(p.id, p.name, p.type)
                           .arg(int(p.marks.provenance));
        }
        for (const Channel &ch : c.channels)
            out << QStringLiteral("channel %1 %2 %3").arg(ch.name, ch.type).arg(ch.marks.reviewed);
    }
    return out;
}

} // namespace

class TestDocumentCorrections : public QObject
{
    Q_OBJECT
    QTemporaryDir m_home;
    QTemporaryDir m_ws;
    Recovery m_recovered;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_home.isValid());
        qputenv("XDG_DATA_HOME", m_home.filePath(QStringLiteral("data")).toUtf8());
        qputenv("XDG_CONFIG_HOME", m_home.filePath(QStringLiteral("config")).toUtf8());
        test::copyTree(QDir(caseDir()).filePath(QStringLiteral("ws")), m_ws.path());
        m_recovered = recoverWorkspace(m_ws.path(), fixtureCorrections().launch);
    }

    void init()
    {
        // a document keeps its project on disk; every test starts from none
        const QString project = ProjectFile::locate(m_ws.path());
        QFile::remove(project);
        QFile::remove(ProjectFile::autosavePath(project));
    }

    void theAuthorIsTheAccountWithoutUserInTheEnvironment()
    {
        // Before: a session without USER (a desktop launcher) recorded "unknown" as who
        // accepted a finding or made a correction.
        const QByteArray saved[] = {qgetenv("USER"), qgetenv("USERNAME"),
                                    qgetenv("ROSARCH_AUTHOR")};
        const char *names[] = {"USER", "USERNAME", "ROSARCH_AUTHOR"};
        for (const char *name : names)
            qunsetenv(name);
        const passwd *account = ::getpwuid(::getuid());
        QVERIFY(account && account->pw_name);
        QCOMPARE(ProjectSession::author(), QString::fromLocal8Bit(account->pw_name));
        qputenv("ROSARCH_AUTHOR", "Ada");
        QCOMPARE(ProjectSession::author(), QStringLiteral("Ada"));
        for (int i = 0; i < 3; ++i) {
            if (saved[i].isEmpty())
                qunsetenv(names[i]);
            else
                qputenv(names[i], saved[i]);
        }
    }

    void eachCorrectionUndoesAndRedoes()
    {
        const Project project = fixtureCorrections();
        Document doc;
        doc.session()->setAutosaveInterval(60000);
        doc.session()->setLaunchOptions(project.launch);
        doc.setRecovery(m_recovered);
        QSignalSpy changes(&doc, &Document::changed);
        QList<Recovery> steps{test::acceptedNow(doc)};
        for (const Correction &c : project.corrections) {
            Correction fresh = c;
            fresh.id.clear(); // the document numbers them
            const QString id = doc.session()->addCorrection(fresh);
            QCOMPARE(id, c.id);
            QCOMPARE(doc.session()->correction(id)->target, c.target);
            QVERIFY(doc.session()->correction(id)->time.isValid());
            QVERIFY(!doc.session()->correction(id)->author.isEmpty());
            steps << test::acceptedNow(doc);
            QVERIFY2(steps.last() != steps.at(steps.size() - 2) ||
                         c.kind == Correction::Kind::Review,
                     qPrintable(c.id)); // each one changes the model (a review marks it)
        }
        int corrections = 0;
        for (const QList<QVariant> &args : std::as_const(changes))
            corrections += args.at(0).value<DocumentChange>().has(DocumentChange::Corrections);
        QCOMPARE(corrections, project.corrections.size());
        QCOMPARE(doc.session()->orphans(), QList<Orphan>());
        // the same model the pure function gives for the project (ids and times aside)
        Project made = project;
        made.corrections = doc.session()->corrections();
        QCOMPARE(test::acceptedNow(doc), CorrectedModel::apply(m_recovered, made).recovery);
        QCOMPARE(test::acceptedNow(doc), CorrectedModel::apply(m_recovered, project).recovery);

        for (int i = int(steps.size()) - 2; i >= 0; --i) {
            doc.undoStack()->undo();
            QVERIFY2(test::acceptedNow(doc) == steps.at(i), qPrintable(QString::number(i)));
        }
        QVERIFY(doc.session()->corrections().isEmpty());
        QCOMPARE(test::acceptedNow(doc), m_recovered);
        for (int i = 1; i < steps.size(); ++i) {
            doc.undoStack()->redo();
            QVERIFY2(test::acceptedNow(doc) == steps.at(i), qPrintable(QString::number(i)));
        }
    }

    void removingACorrectionRevertsIt()
    {
        const Project project = fixtureCorrections();
        Document doc;
        doc.session()->setAutosaveInterval(60000);
        doc.setRecovery(m_recovered);
        for (const Correction &c : project.corrections)
            doc.session()->addCorrection(c);
        const Recovery all = test::acceptedNow(doc);
        QVERIFY(doc.session()->removeCorrection(QStringLiteral("c3"))); // the topic rename
        QVERIFY(!doc.session()->correction(QStringLiteral("c3")));
        Project without = project;
        without.corrections.removeAt(2);
        const Recovery expected = CorrectedModel::apply(m_recovered, without).recovery;
        QCOMPARE(test::acceptedNow(doc), expected);
        doc.undoStack()->undo();
        QCOMPARE(doc.session()->corrections().at(2).id, QStringLiteral("c3")); // back where it was
        QCOMPARE(test::acceptedNow(doc), all);
        QVERIFY(!doc.session()->removeCorrection(QStringLiteral("c99")));
        QVERIFY(doc.session()->addCorrection(Correction{}).isEmpty()); // no target: nothing pushed
    }

    void theModelAsAcceptedIsMadeInTheBackground()
    {
        const Project project = fixtureCorrections();
        QVERIFY(project.corrections.size() >= 3);
        Document doc;
        doc.session()->setAutosaveInterval(60000);
        doc.setRecovery(m_recovered);
        // A new model with an empty project: the model as recovered, at once.
        QVERIFY(!doc.isAcceptedPending());
        QCOMPARE(doc.accepted(), doc.recovered());

        // A correction: until the job is done the views see the model before and are told
        // when it is there; applying it never runs in the call that made it.
        QSignalSpy changes(&doc, &Document::changed);
        QVERIFY(!doc.session()->addCorrection(project.corrections.at(0)).isEmpty());
        QVERIFY(doc.isAcceptedPending());
        QCOMPARE(doc.accepted(), doc.recovered());
        QVERIFY(test::acceptedSettled(doc));
        QCOMPARE(test::changesOf(changes, DocumentChange::Accepted).size(), 1);
        Project first = project;
        first.corrections = {project.corrections.at(0)};
        QCOMPARE(doc.accepted(), CorrectedModel::apply(m_recovered, first).recovery);

        // Several changes before the event loop runs: one job, for all of them.
        changes.clear();
        doc.session()->addCorrection(project.corrections.at(1));
        doc.session()->addCorrection(project.corrections.at(2));
        QVERIFY(test::acceptedSettled(doc));
        QCOMPARE(test::changesOf(changes, DocumentChange::Accepted).size(), 1);
        Project three = project;
        three.corrections = project.corrections.mid(0, 3);
        QCOMPARE(doc.accepted(), CorrectedModel::apply(m_recovered, three).recovery);

        // What must write what a person reviewed waits for it (an export right after an undo).
        doc.undoStack()->undo();
        QVERIFY(doc.isAcceptedPending());
        doc.settleAccepted();
        QVERIFY(!doc.isAcceptedPending());
        Project two = project;
        two.corrections = project.corrections.mid(0, 2);
        QCOMPARE(doc.accepted(), CorrectedModel::apply(m_recovered, two).recovery);

        // A re-run of the same workspace: the model as recovered stands for it until the job
        // applies the project to the new model.
        doc.setRecovery(m_recovered);
        QVERIFY(doc.isAcceptedPending());
        QCOMPARE(doc.accepted(), doc.recovered());
        QVERIFY(test::acceptedSettled(doc));
        QCOMPARE(doc.accepted(), CorrectedModel::apply(m_recovered, two).recovery);
    }

    void pendingSuggestionsSurviveARerunUnlessTheirTargetIsGone()
    {
        Document doc;
        doc.session()->setAutosaveInterval(60000);
        doc.setRecovery(m_recovered);
        SuggestionReport report;
        for (const AtomicNode &n : m_recovered.nodes.nodes) {
            Suggestion s;
            s.id = QStringLiteral("s%1").arg(report.suggestions.size() + 1);
            s.kind = Suggestion::Kind::NodeDescription;
            s.targetId = n.id;
            s.value = QStringLiteral("About ") + n.className;
            report.suggestions.append(s);
        }
        doc.session()->setSuggestions(report);
        QVERIFY(doc.session()->acceptSuggestion(QStringLiteral("s2")));
        // a class inserted before all others (every id shifts) and one deleted
        const QString arbiter = m_ws.filePath(QStringLiteral("src/cart_base/cart_base/arbiter.py"));
        const QString recorder =
            m_ws.filePath(QStringLiteral("src/cart_base/cart_base/recorder.py"));
        const QByteArray recorderSource = test::readFile(recorder);
        test::writeFile(arbiter, "from rclpy.node import Node\n\n\nclass Arbiter(Node):\n"
                                 "    def __init__(self):\n        super().__init__('arbiter')\n");
        QVERIFY(QFile::remove(recorder));
        doc.setRecovery(recoverWorkspace(m_ws.path()));
        QFile::remove(arbiter);
        test::writeFile(recorder, recorderSource);
        QCOMPARE(doc.session()->suggestions().size(),
                 report.suggestions.size() - 1); // Recorder's went
        for (const Suggestion &s : doc.session()->suggestions()) {
            const AtomicNode *n = doc.atomicNodes().node(s.targetId);
            QVERIFY(n);
            QCOMPARE(s.value, QStringLiteral("About ") + n->className); // on its own class
            QCOMPARE(s.status == Suggestion::Status::Accepted, s.id == QLatin1String("s2"));
        }
    }

    void reRunningTheStagesKeepsTheCorrections()
    {
        const Project project = fixtureCorrections();
        Document doc;
        doc.session()->setAutosaveInterval(60000);
        doc.setRecovery(m_recovered);
        const QStringList ids =
            doc.session()->addCorrections(project.corrections, QStringLiteral("all of them"));
        QCOMPARE(ids.size(), project.corrections.size());
        QCOMPARE(doc.undoStack()->count(), 1); // one step
        const Recovery before = test::acceptedNow(doc);
        // F5: the stages run again on the same workspace
        doc.setRecovery(recoverWorkspace(m_ws.path(), project.launch));
        QCOMPARE(doc.session()->corrections().size(), project.corrections.size());
        QCOMPARE(test::acceptedNow(doc), before);
        // a description a person wrote (F2) is a correction too: the node list keeps it
        for (const AtomicNode &n : doc.atomicNodes().nodes)
            QCOMPARE(n.description.startsWith(QLatin1String("Reports contact of one bumper")),
                     n.className == QLatin1String("BumperNode"));
        QVERIFY(doc.session()->orphans().isEmpty());
        // a code change that shifts ids: still applied to the same elements
        test::writeFile(m_ws.filePath(QStringLiteral("src/cart_base/cart_base/arbiter.py")),
                        "from rclpy.node import Node\n\n\nclass Arbiter(Node):\n"
                        "    def __init__(self):\n        super().__init__('arbiter')\n");
        doc.setRecovery(recoverWorkspace(m_ws.path(), project.launch));
        QVERIFY(doc.session()->orphans().isEmpty());
        QCOMPARE(shape(test::acceptedNow(doc).architecture), shape(before.architecture));
        QFile::remove(m_ws.filePath(QStringLiteral("src/cart_base/cart_base/arbiter.py")));
    }
};

QTEST_GUILESS_MAIN(TestDocumentCorrections)
#include "tst_documentcorrections.moc"
