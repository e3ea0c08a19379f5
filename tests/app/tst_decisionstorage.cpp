// A person's decisions on disk: kept per workspace in the project file when a person saves;
// until then in the autosave side file, written by the autosave (not on every undo and redo),
// before another workspace replaces them and when the document goes; kept in memory when the
// disk refuses them.
#include "document/document.h"
#include "project/project.h"
#include "support/acceptedwait.h"
#include "support/suggestionfixture.h"
#include "support/testsupport.h"

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
    void init()
    {
        QFile::remove(ProjectFile::locate(exampleWorkspace()));
        QFile::remove(ProjectFile::autosavePath(ProjectFile::locate(exampleWorkspace())));
    }

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
            QCOMPARE(doc.session()->projectPath(), path);
            const Suggestion d = first(doc, Suggestion::Kind::NodeDescription);
            acceptedValue = d.value;
            QVERIFY(doc.session()->acceptSuggestion(d.id));
            QVERIFY(doc.session()->rejectSuggestion(
                first(doc, Suggestion::Kind::SubsystemGrouping).id));
            QVERIFY(doc.session()->isModified());
            QVERIFY(!QFileInfo::exists(path)); // written when a person saves
            QVERIFY(doc.session()->save());
            QVERIFY(!doc.session()->isModified());
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
        QCOMPARE(again.session()->setSuggestions(m_deterministic), 2);
        int pending = 0;
        for (const Suggestion &s : again.session()->suggestions())
            pending += s.status == Suggestion::Status::Pending ? 1 : 0;
        QCOMPARE(pending, 7);
        QCOMPARE(first(again, Suggestion::Kind::NodeDescription).status,
                 Suggestion::Status::Accepted);
        QCOMPARE(first(again, Suggestion::Kind::SubsystemGrouping).status,
                 Suggestion::Status::Rejected);

        // Undoing a decision forgets it on disk as well.
        Document third;
        load(third);
        QVERIFY(third.session()->acceptSuggestion(
            first(third, Suggestion::Kind::SubsystemGrouping).id));
        third.undoStack()->undo();
        QVERIFY(third.session()->save());
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
            QVERIFY(doc.session()->acceptSuggestion(d.id));
            QVERIFY(doc.session()->save());
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
        QVERIFY(doc.session()->orphans().isEmpty());
        for (const AtomicNode &n : doc.atomicNodes().nodes)
            QCOMPARE(n.description == value, n.qualifiedName == target);
        for (const AtomicNode &n : test::acceptedNow(doc).nodes.nodes)
            QCOMPARE(n.marks.provenance == Provenance::Suggested, n.qualifiedName == target);
    }

    void undoAndRedoDoNotWriteTheAutosaveDoes()
    {
        const QString path = ProjectFile::locate(exampleWorkspace());
        const QString side = ProjectFile::autosavePath(path);
        QFile::remove(side);
        Document doc;
        load(doc);
        QCOMPARE(doc.session()->autosaveFile(), side);
        const Suggestion d = first(doc, Suggestion::Kind::NodeDescription);
        QVERIFY(doc.session()->acceptSuggestion(d.id));
        QVERIFY(doc.session()->hasAutosavePending());
        for (int i = 0; i < 5; ++i) {
            doc.undoStack()->undo();
            doc.undoStack()->redo();
        }
        QVERIFY(!QFileInfo::exists(path)); // nothing written yet
        QVERIFY(!QFileInfo::exists(side));
        QVERIFY(doc.session()->writeAutosave());
        QVERIFY(!doc.session()->hasAutosavePending());
        QCOMPARE(storedDecisions(side), 1);
        QVERIFY(!QFileInfo::exists(path)); // the autosave never writes the project itself
        QVERIFY(doc.session()->save());
        QCOMPARE(storedDecisions(path), 1);
        QVERIFY(!QFileInfo::exists(side)); // a save takes the side file's place

        // The autosave writes a burst of changes once, an interval after the first one.
        doc.session()->setAutosaveInterval(100);
        doc.undoStack()->undo();
        QVERIFY(doc.session()->isModified());
        QVERIFY(!QFileInfo::exists(side));
        QTRY_VERIFY(QFileInfo::exists(side));
        QCOMPARE(storedDecisions(side), 0);
        QCOMPARE(storedDecisions(path), 1);
        QVERIFY(!doc.session()->hasAutosavePending());
        // Back at the saved state, the side file goes.
        doc.undoStack()->redo();
        QVERIFY(!doc.session()->isModified());
        QTRY_VERIFY(!QFileInfo::exists(side));

        // Replacing the workspace keeps what is pending in the side file first; so does closing
        // the document. The project file stays as saved.
        doc.session()->setAutosaveInterval(60000);
        doc.undoStack()->undo();
        QVERIFY(doc.session()->hasAutosavePending());
        doc.setRecovery({});
        QCOMPARE(storedDecisions(side), 0);
        QVERIFY(QFileInfo::exists(side));
        QCOMPARE(storedDecisions(path), 1);
        QFile::remove(side);
        {
            Document other;
            load(other);
            other.session()->setAutosaveInterval(60000);
            QVERIFY(other.session()->rejectSuggestion(
                first(other, Suggestion::Kind::SubsystemGrouping).id));
            QVERIFY(!QFileInfo::exists(side));
        }
        QCOMPARE(storedDecisions(side), 2);
        QCOMPARE(storedDecisions(path), 1);

        // What the side file holds comes back as modified state; discarding removes it.
        Document recovered;
        load(recovered);
        QCOMPARE(recovered.session()->decisions().size(), 1);
        QString error;
        QVERIFY2(recovered.session()->recoverAutosave(&error), qPrintable(error));
        QCOMPARE(recovered.session()->decisions().size(), 2);
        QVERIFY(recovered.session()->isModified());
        QCOMPARE(first(recovered, Suggestion::Kind::SubsystemGrouping).status,
                 Suggestion::Status::Rejected);
        recovered.session()->discardChanges();
        QVERIFY(!recovered.session()->isModified());
        QVERIFY(!QFileInfo::exists(side));
        QCOMPARE(storedDecisions(path), 1);
    }

    void aBurstOfChangesDoesNotPostponeTheAutosave()
    {
        // A crash loses at most one interval of decisions, even while a person keeps deciding,
        // undoing and redoing faster than the interval: later changes do not restart it.
        const QString side = ProjectFile::autosavePath(ProjectFile::locate(exampleWorkspace()));
        QFile::remove(side);
        Document doc;
        load(doc);
        doc.session()->setAutosaveInterval(300);
        QVERIFY(doc.session()->acceptSuggestion(first(doc, Suggestion::Kind::NodeDescription).id));
        QElapsedTimer burst;
        burst.start();
        while (!QFileInfo::exists(side) && burst.elapsed() < 3000) {
            QTest::qWait(50);
            doc.undoStack()->undo();
            doc.undoStack()->redo();
        }
        QVERIFY2(QFileInfo::exists(side), "nothing written during three seconds of changes");
        QCOMPARE(storedDecisions(side), 1); // written between a redo and an undo
        doc.session()->discardChanges();
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
        QSignalSpy failed(doc.session(), &ProjectSession::saveFailed);
        load(doc);
        const Suggestion d = first(doc, Suggestion::Kind::NodeDescription);
        QVERIFY(doc.session()->acceptSuggestion(d.id));
        QVERIFY(!doc.session()->save());
        QCOMPARE(failed.size(), 1);
        QVERIFY(!doc.session()->writeAutosave()); // the side file would go next to it
        QCOMPARE(failed.size(), 2);
        QVERIFY(doc.session()->isModified());
        // Running the stages again on the same workspace keeps the decision in memory.
        doc.setRecovery(m_recovery);
        QCOMPARE(doc.session()->decisions().size(), 1);
        QCOMPARE(doc.atomicNodes().node(d.targetId)->description, d.value);
        QVERIFY(doc.session()->hasAutosavePending());
        QFile::remove(folder);
        QVERIFY(doc.session()->save());
        QCOMPARE(storedDecisions(path), 1);
        QVERIFY(!doc.session()->isModified());
    }
};

QTEST_GUILESS_MAIN(TestDecisionStorage)
#include "tst_decisionstorage.moc"
