// A person's decisions on disk: kept per workspace, written by the autosave (not on every undo
// and redo), before another workspace replaces them and when the document goes, and kept in
// memory when the disk refuses them.
#include "document.h"
#include "project.h"
#include "suggestionfixture.h"
#include "testsupport.h"

#include <QCryptographicHash>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QtTest>

using namespace rosarch;

namespace {

/// How many decisions the project file at `path` holds (-1 when it cannot be read).
qsizetype storedDecisions(const QString &path)
{
    if (!QFileInfo::exists(path))
        return 0;
    Project p;
    QString error;
    return ProjectFile::read(path, &p, &error) ? p.decisions.size() : -1;
}

} // namespace
using rosarch::test::exampleWorkspace;
using rosarch::test::kSecret;

class TestDecisionStorage : public QObject
{
    Q_OBJECT
private:
    test::SuggestionFixture m_fixture;
    const Recovery &m_recovery = m_fixture.recovery;
    const SuggestionReport &m_deterministic = m_fixture.deterministic;

    void load(Document &doc) { m_fixture.load(doc); }
    const Suggestion &first(const Document &doc, Suggestion::Kind kind)
    {
        return test::firstOf(doc, kind);
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_fixture.setUp()); }
    void init() { QFile::remove(ProjectFile::locate(exampleWorkspace())); }

    void decisionsAreKeptWithTheProject()
    {
        const QString path = ProjectFile::locate(exampleWorkspace());
        const QByteArray sha1 =
            QCryptographicHash::hash(exampleWorkspace().toUtf8(), QCryptographicHash::Sha1).toHex();
        QCOMPARE(path, QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                           .filePath(QStringLiteral("projects/%1/rosarch.project.json")
                                         .arg(QString::fromLatin1(sha1))));
        QVERIFY(path.startsWith(m_fixture.home.path()));
        QString acceptedValue;
        {
            Document doc;
            load(doc);
            QCOMPARE(doc.decisionsPath(), path);
            const Suggestion d = first(doc, Suggestion::Kind::NodeDescription);
            acceptedValue = d.value;
            QVERIFY(doc.acceptSuggestion(d.id));
            QVERIFY(doc.rejectSuggestion(first(doc, Suggestion::Kind::SubsystemGrouping).id));
        }
        const QByteArray stored = test::readFile(path);
        QVERIFY(stored.contains("\"accepted\""));
        QVERIFY(stored.contains("\"rejected\""));
        QVERIFY(stored.contains(acceptedValue.toUtf8()));
        QVERIFY(!stored.contains(kSecret.toUtf8())); // never the API key

        // Running the stages again re-applies the accepted description at once; running the
        // suggestions again does not ask about what was decided.
        Document again;
        again.setRecovery(m_recovery);
        QCOMPARE(again.atomicNodes().node(QStringLiteral("arc_1"))->description, acceptedValue);
        QCOMPARE(again.undoStack()->count(), 0);
        QCOMPARE(again.setSuggestions(m_deterministic), 2);
        int pending = 0;
        for (const Suggestion &s : again.suggestions())
            pending += s.status == Suggestion::Status::Pending ? 1 : 0;
        QCOMPARE(pending, 7);
        QCOMPARE(first(again, Suggestion::Kind::NodeDescription).status,
                 Suggestion::Status::Accepted);
        QCOMPARE(first(again, Suggestion::Kind::SubsystemGrouping).status,
                 Suggestion::Status::Rejected);

        // Undoing a decision forgets it on disk as well.
        Document third;
        load(third);
        QVERIFY(third.acceptSuggestion(first(third, Suggestion::Kind::SubsystemGrouping).id));
        third.undoStack()->undo();
        QVERIFY(third.saveDecisions());
        QVERIFY(test::readFile(path).contains("\"rejected\""));
        QCOMPARE(storedDecisions(path), 2);
    }

    void aDecisionStaysWithItsClassWhenTheIdsShift()
    {
        // Decided on arc_1, the project names the class by key: a class inserted before it
        // shifts every id, and the description stays with its class (blueprint §5).
        QString target, value;
        {
            Document doc;
            load(doc);
            const Suggestion d = first(doc, Suggestion::Kind::NodeDescription);
            target = doc.atomicNodes().node(d.targetId)->qualifiedName;
            value = d.value;
            QVERIFY(doc.acceptSuggestion(d.id));
        }
        Recovery shifted = m_recovery;
        AtomicNode inserted;
        inserted.className = QStringLiteral("Aardvark");
        inserted.qualifiedName = QStringLiteral("aardvark.Aardvark");
        inserted.packageName = shifted.nodes.nodes.first().packageName;
        shifted.nodes.nodes.prepend(inserted);
        QHash<QString, QString> renamed;
        for (int i = 0; i < shifted.nodes.nodes.size(); ++i) {
            AtomicNode &n = shifted.nodes.nodes[i];
            const QString id = QStringLiteral("arc_%1").arg(i + 1);
            renamed.insert(n.id, id);
            n.id = id;
        }
        for (NodeInstance &n : shifted.launch.nodes)
            n.classId = renamed.value(n.classId, n.classId);
        Document doc;
        doc.setRecovery(shifted);
        QVERIFY(doc.orphans().isEmpty());
        for (const AtomicNode &n : doc.atomicNodes().nodes)
            QCOMPARE(n.description == value, n.qualifiedName == target);
        for (const AtomicNode &n : doc.accepted().nodes.nodes)
            QCOMPARE(n.marks.provenance == Provenance::Suggested, n.qualifiedName == target);
    }

    void undoAndRedoDoNotWriteTheAutosaveDoes()
    {
        const QString path = ProjectFile::locate(exampleWorkspace());
        Document doc;
        load(doc);
        const Suggestion d = first(doc, Suggestion::Kind::NodeDescription);
        QVERIFY(doc.acceptSuggestion(d.id));
        QVERIFY(doc.hasUnsavedDecisions());
        for (int i = 0; i < 5; ++i) {
            doc.undoStack()->undo();
            doc.undoStack()->redo();
        }
        QVERIFY(!QFileInfo::exists(path)); // nothing written yet
        QVERIFY(doc.saveDecisions());
        QVERIFY(!doc.hasUnsavedDecisions());
        QCOMPARE(storedDecisions(path), 1);

        // The autosave writes a burst of changes once, an interval after the first one.
        doc.setAutosaveInterval(100);
        doc.undoStack()->undo();
        QCOMPARE(storedDecisions(path), 1);
        QTRY_COMPARE(storedDecisions(path), 0);
        QVERIFY(!doc.hasUnsavedDecisions());

        // Replacing the workspace writes what is pending first; so does closing the document.
        doc.setAutosaveInterval(60000);
        doc.undoStack()->redo();
        QVERIFY(doc.hasUnsavedDecisions());
        doc.setRecovery({});
        QCOMPARE(storedDecisions(path), 1);
        {
            Document other;
            load(other);
            other.setAutosaveInterval(60000);
            QVERIFY(other.rejectSuggestion(first(other, Suggestion::Kind::SubsystemGrouping).id));
            QCOMPARE(storedDecisions(path), 1);
        }
        QCOMPARE(storedDecisions(path), 2);
    }

    void aBurstOfChangesDoesNotPostponeTheAutosave()
    {
        // A crash loses at most one interval of decisions, even while a person keeps deciding,
        // undoing and redoing faster than the interval: later changes do not restart it.
        const QString path = ProjectFile::locate(exampleWorkspace());
        Document doc;
        load(doc);
        doc.setAutosaveInterval(300);
        QVERIFY(doc.acceptSuggestion(first(doc, Suggestion::Kind::NodeDescription).id));
        QElapsedTimer burst;
        burst.start();
        while (!QFileInfo::exists(path) && burst.elapsed() < 3000) {
            QTest::qWait(50);
            doc.undoStack()->undo();
            doc.undoStack()->redo();
        }
        QVERIFY2(QFileInfo::exists(path), "nothing written during three seconds of changes");
        QCOMPARE(storedDecisions(path), 1); // written between a redo and an undo
    }

    void aDecisionThatCannotBeSavedIsKeptForTheSameWorkspace()
    {
        // The project folder cannot be created (a file stands where it would go).
        const QString path = ProjectFile::locate(exampleWorkspace());
        const QString folder = QFileInfo(path).path();
        QDir(folder).removeRecursively();
        QDir().mkpath(QFileInfo(folder).path());
        {
            QFile blocker(folder);
            QVERIFY(blocker.open(QIODevice::WriteOnly));
        }
        Document doc;
        QSignalSpy failed(&doc, &Document::decisionsSaveFailed);
        load(doc);
        const Suggestion d = first(doc, Suggestion::Kind::NodeDescription);
        QVERIFY(doc.acceptSuggestion(d.id));
        QVERIFY(!doc.saveDecisions());
        QCOMPARE(failed.size(), 1);
        // Running the stages again on the same workspace keeps the decision in memory.
        doc.setRecovery(m_recovery);
        QCOMPARE(doc.decisions().size(), 1);
        QCOMPARE(doc.atomicNodes().node(d.targetId)->description, d.value);
        QVERIFY(doc.hasUnsavedDecisions());
        QFile::remove(folder);
        QVERIFY(doc.saveDecisions());
        QCOMPARE(storedDecisions(path), 1);
    }
};

QTEST_GUILESS_MAIN(TestDecisionStorage)
#include "tst_decisionstorage.moc"
