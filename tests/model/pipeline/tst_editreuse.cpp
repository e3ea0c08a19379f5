// After an edit that only moves lines, stages 2 and 3 reuse their earlier results with the
// moved locations brought up to date, and give exactly what a fresh run gives (in process, from
// the analysis cache, and in a long-lived worker); an edit that changes what the stages read
// (a topic's name) is analysed again. EvidenceShift refuses moves a stage could tell apart.
#include "cache/analysiscache.h"
#include "cache/evidenceshift.h"
#include "pipeline/recovery.h"
#include "pipeline/stagesession.h"
#include "support/cacherecovery.h"
#include "support/cachetestcase.h"
#include "support/testsupport.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

const QString kRectifier = QStringLiteral("src/vision/src/rectifier.cpp");

/// Prepends `lines` comment lines to `file`.
void prependLines(const QString &file, int lines)
{
    QByteArray source = test::readFile(file);
    for (int i = 0; i < lines; ++i)
        source.prepend("// moved\n");
    test::writeFile(file, source);
}

/// The line of the rectifier's parameter-named publisher in stage 1, of the declaration its
/// default comes from in stage 2, and of the publisher's port in stage 3 (0 when absent).
struct Lines
{
    int port = 0;
    int parameter = 0;
    int part = 0;
};

Lines linesOf(const Recovery &r)
{
    Lines out;
    for (const AtomicNode &n : r.nodes.nodes)
        for (const Port &p : n.ports)
            if (p.evidence.file == kRectifier && p.parameter == QLatin1String("output_topic"))
                out.port = p.evidence.line;
    for (const NodeInstance &n : r.launch.nodes)
        for (const ParameterSetting &p : n.effectiveParameters)
            if (p.evidence.file == kRectifier && p.name == QLatin1String("output_topic"))
                out.parameter = p.evidence.line;
    for (const Composite &c : r.architecture.composites)
        for (const RosNodePart &part : c.parts)
            for (const PartPort &p : part.ports)
                if (p.evidence.file == kRectifier && p.parameterDerived)
                    out.part = p.evidence.line;
    return out;
}

/// A marker that stage 3 never writes, at the place of a real input location: it survives
/// (moved) only when the earlier architecture is reused.
void mark(Recovery *r)
{
    Diagnostic d;
    d.code = QStringLiteral("test-marker");
    for (const AtomicNode &n : std::as_const(r->nodes.nodes))
        for (const Port &p : n.ports)
            if (p.evidence.file == kRectifier)
                d.evidence = p.evidence;
    QVERIFY(d.evidence.isValid());
    r->architecture.diagnostics.append(d);
}

const Diagnostic *marker(const Recovery &r)
{
    for (const Diagnostic &d : r.architecture.diagnostics)
        if (d.code == QLatin1String("test-marker"))
            return &d;
    return nullptr;
}

} // namespace

class TestEditReuse : public QObject
{
    Q_OBJECT

    QTemporaryDir m_temp;
    QString m_ws;
    QString m_cache;

private Q_SLOTS:
    void init()
    {
        QVERIFY(m_temp.isValid());
        test::freshCacheCase(m_temp, &m_ws, &m_cache);
    }

    void movedLinesGiveWhatAFreshRunGives()
    {
        AnalysisCache first(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        Recovery before = test::recoverWith(m_ws, &first, nullptr);
        const Lines old = linesOf(before);
        QVERIFY(old.port > 0 && old.parameter > 0 && old.part > 0);
        mark(&before);
        prependLines(m_ws + QLatin1Char('/') + kRectifier, 3);

        AnalysisCache second(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        Recovery after = test::recoverWith(m_ws, &second, &before);
        // Stage 2 came from its memo (written for the old lines), stage 3 from `before` (a run
        // with an earlier result stores no memo of stage 3).
        QCOMPARE(second.statistics().stores, 3); // stage 1's memo, rectifier.cpp, its manifest
        const Diagnostic *kept = marker(after);
        QVERIFY2(kept, "stage 3 was composed again instead of reused");
        QCOMPARE(kept->evidence.line, marker(before)->evidence.line + 3);
        after.architecture.diagnostics.removeOne(*kept);

        const Recovery fresh = test::recoverUncached(m_ws);
        const Lines moved = linesOf(fresh);
        QCOMPARE(moved.port, old.port + 3);
        QCOMPARE(moved.parameter, old.parameter + 3);
        QCOMPARE(moved.part, old.part + 3);
        QCOMPARE(linesOf(after).port, moved.port);
        QCOMPARE(linesOf(after).parameter, moved.parameter);
        QCOMPARE(linesOf(after).part, moved.part);
        QVERIFY(after.nodes == fresh.nodes);
        QVERIFY(after.launch == fresh.launch);
        QVERIFY(after.architecture == fresh.architecture);
    }

    void aRenamedTopicIsComposedAgain()
    {
        AnalysisCache first(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        Recovery before = test::recoverWith(m_ws, &first, nullptr);
        mark(&before);
        const QString file = m_ws + QLatin1Char('/') + kRectifier;
        QByteArray source = test::readFile(file);
        QVERIFY(source.contains("\"image_raw\""));
        source.replace("\"image_raw\"", "\"image_other\"");
        test::writeFile(file, source);
        prependLines(file, 2);

        AnalysisCache second(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const Recovery after = test::recoverWith(m_ws, &second, &before);
        QVERIFY2(!marker(after), "stage 3 reused a result composed from another topic");
        const Recovery fresh = test::recoverUncached(m_ws);
        QVERIFY(after == fresh);
        bool renamed = false;
        for (const Composite &c : after.architecture.composites)
            for (const RosNodePart &part : c.parts)
                for (const PartPort &p : part.ports)
                    renamed = renamed || p.name.endsWith(QLatin1String("image_other"));
        QVERIFY(renamed);
    }

    void aLongLivedWorkerGivesWhatAFreshRunGives()
    {
        StageSession session;
        const StageProcess::Result first = session.recover(m_ws, {}, {});
        QVERIFY2(first.error.isEmpty(), qPrintable(first.error));
        prependLines(m_ws + QLatin1Char('/') + kRectifier, 4);
        const StageProcess::Result moved = session.recover(m_ws, {}, {});
        QVERIFY2(moved.error.isEmpty(), qPrintable(moved.error));
        QCOMPARE(linesOf(moved.recovery).part, linesOf(first.recovery).part + 4);
        QVERIFY(moved.recovery == test::recoverUncached(m_ws));
    }

    void theShiftRefusesWhatAStageCouldTell()
    {
        const QString f = QStringLiteral("a.cpp");
        const Evidence a{f, 3, 1, 3, 9}, b{f, 7, 1, 7, 9}, c{f, 7, 12, 7, 20};
        const auto moved = [](const Evidence &e, int by) {
            return Evidence{e.file, e.line + by, e.column, e.endLine + by, e.endColumn};
        };
        { // every location after an inserted line moves down: accepted
            EvidenceShift s;
            QVERIFY(s.compare(QList<Evidence>{a, b, c}, {a, moved(b, 1), moved(c, 1)}));
            s.compareUnmoved(QList<Evidence>{a, b, c}, {a, moved(b, 1), moved(c, 1)});
            QVERIFY(s.settle());
            QCOMPARE(s.files(), QList<QString>{f});
            QList<Evidence> result{c, a};
            QVERIFY(s.apply(result));
            QCOMPARE(result, (QList<Evidence>{moved(c, 1), a}));
            QList<Evidence> unknown{Evidence{f, 5, 1, 5, 2}};
            QVERIFY(!s.apply(unknown)); // not an input's: the stage made it, it cannot be moved
        }
        { // two locations swap their order
            EvidenceShift s;
            QVERIFY(s.compare(QList<Evidence>{a, b}, {moved(a, 10), b}));
            s.compareUnmoved(QList<Evidence>{a, b}, {moved(a, 10), b});
            QVERIFY(!s.settle());
        }
        { // two on one line end up on two lines (a check merges findings by line)
            EvidenceShift s;
            QVERIFY(s.compare(QList<Evidence>{b, c}, {b, moved(c, 1)}));
            s.compareUnmoved(QList<Evidence>{b, c}, {b, moved(c, 1)});
            QVERIFY(!s.settle());
        }
        { // one old location, two new ones
            EvidenceShift s;
            QVERIFY(s.compare(QList<Evidence>{a, a}, {moved(a, 1), moved(a, 2)}));
            QVERIFY(!s.settle());
        }
        { // another file
            EvidenceShift s;
            QVERIFY(s.compare(QList<Evidence>{a}, {Evidence{QStringLiteral("b.cpp"), 3, 1, 3, 9}}));
            QVERIFY(!s.settle());
        }
        { // a difference besides locations
            EvidenceShift s;
            QVERIFY(!s.compare(QList<Evidence>{a}, {a, b}));
        }
    }
};

QTEST_GUILESS_MAIN(TestEditReuse)
#include "tst_editreuse.moc"
