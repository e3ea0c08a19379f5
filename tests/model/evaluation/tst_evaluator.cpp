// The evaluator: multiset comparison per kind and diagram, the §4 conventions, macro vs micro.
// tests/data/eval_models holds a reference and a recovered model broken on purpose.
#include "evaluation/evaluator.h"
#include "plantuml/umlmodel.h"
#include "support/testsupport.h"

#include <QtTest>

using namespace rosarch;

namespace {

UmlModel load(const QString &sub)
{
    UmlModel m;
    QString error;
    if (!UmlModel::load(test::dataDir(sub), &m, &error))
        qWarning("%s", qPrintable(error));
    return m;
}

QStringList values(const QList<UmlElement> &elements)
{
    QStringList out;
    for (const UmlElement &e : elements)
        out << e.value;
    return out;
}

UmlElement element(const QString &kind, const QString &value)
{
    return UmlElement{kind, value, 0, {}};
}

UmlDiagram diagram(UmlLevel level, const QString &name, const QString &file,
                   const QList<UmlElement> &elements)
{
    UmlDiagram d;
    d.level = level;
    d.name = name;
    d.file = file;
    d.elements = elements;
    return d;
}

bool near(double a, double b)
{
    return std::abs(a - b) < 1e-9;
}

#define COMPARE_RATIOS(score, p, r, f)                                                             \
    do {                                                                                           \
        QVERIFY2(near((score).precision, (p)), qPrintable(QString::number((score).precision)));    \
        QVERIFY2(near((score).recall, (r)), qPrintable(QString::number((score).recall)));          \
        QVERIFY2(near((score).f1, (f)), qPrintable(QString::number((score).f1)));                  \
    } while (false)

} // namespace

class TestEvaluator : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void identicalModelsScoreOne()
    {
        const UmlModel reference = load(QStringLiteral("eval_models/reference"));
        QCOMPARE(reference.ofLevel(UmlLevel::Acd).size(), 3);
        QCOMPARE(reference.ofLevel(UmlLevel::Ccd).size(), 1);
        const Evaluation e = Evaluator::evaluate(reference.diagrams, reference.diagrams,
                                                 {UmlLevel::Acd, UmlLevel::Ccd});
        QCOMPARE(e.levels.size(), 2);
        for (const LevelEvaluation &l : e.levels) {
            QVERIFY(l.extra.isEmpty());
            COMPARE_RATIOS(l.micro, 1, 1, 1);
            COMPARE_RATIOS(l.macro, 1, 1, 1);
            QCOMPARE(l.micro.fp + l.micro.fn, 0);
            QVERIFY(l.micro.tp > 0);
            QCOMPARE(l.kinds.size(), umlKinds(l.level).size());
            for (const KindSummary &k : l.kinds) {
                COMPARE_RATIOS(k.micro, 1, 1, 1);
                COMPARE_RATIOS(k.macro, 1, 1, 1);
            }
            for (const DiagramEvaluation &d : l.diagrams) {
                QVERIFY(!d.missing);
                QCOMPARE(d.recoveredFile, d.referenceFile);
                for (const KindEvaluation &k : d.kinds)
                    QVERIFY(k.falsePositives.isEmpty() && k.falseNegatives.isEmpty());
            }
        }
        QCOMPARE(e.level(UmlLevel::Ccd)->micro.tp, 16);
    }

    void brokenCcdListsExactlyTheBrokenElements()
    {
        // Recovered demo: part monitor missing, listener typed Talker, an extra topic, and the
        // listener's server arrow drawn red (client).
        const Evaluation e = Evaluator::evaluate(
            load(QStringLiteral("eval_models/reference")).diagrams,
            load(QStringLiteral("eval_models/recovered")).diagrams, {UmlLevel::Ccd});
        QCOMPARE(e.levels.size(), 1);
        const LevelEvaluation &l = e.levels.first();
        QCOMPARE(l.diagrams.size(), 1);
        const DiagramEvaluation &d = l.diagrams.first();
        QCOMPARE(d.name, QStringLiteral("demo"));
        QVERIFY(d.recoveredFile.endsWith(QLatin1String("recovered/ccd/demo.puml")));
        const QHash<QString, QPair<QStringList, QStringList>> expected = {
            {UmlKind::Part, {{}, {QStringLiteral("monitor")}}},
            {UmlKind::PartType,
             {{QStringLiteral("listener:Talker")},
              {QStringLiteral("listener:Listener"), QStringLiteral("monitor:Monitor")}}},
            {UmlKind::Namespace, {{}, {QStringLiteral("(/, monitor)")}}},
            {UmlKind::Topic, {{QStringLiteral("robot1/debug")}, {}}},
            {UmlKind::Connection,
             {{QStringLiteral("client listener -> robot1/reset")},
              {QStringLiteral("server listener -> robot1/reset"),
               QStringLiteral("subscribe robot1/chatter -> monitor")}}}};
        for (const KindEvaluation &k : d.kinds) {
            const auto want = expected.value(k.kind);
            QCOMPARE(values(k.falsePositives), want.first);
            QCOMPARE(values(k.falseNegatives), want.second);
        }
        QCOMPARE(d.kind(UmlKind::Connection)->score.tp, 3);
        QCOMPARE(d.kind(UmlKind::Connection)->falsePositives.first().line,
                 21); // line in the recovered file
        QCOMPARE(d.total.tp, 10);
        QCOMPARE(d.total.fp, 3);
        QCOMPARE(d.total.fn, 6);
        COMPARE_RATIOS(d.total, 10.0 / 13, 10.0 / 16, 20.0 / 29);
        QVERIFY(d.total.f1 < 1.0);
        // One diagram: macro and micro agree.
        COMPARE_RATIOS(l.macro, 10.0 / 13, 10.0 / 16, 20.0 / 29);
        COMPARE_RATIOS(l.micro, 10.0 / 13, 10.0 / 16, 20.0 / 29);
        COMPARE_RATIOS(l.kind(UmlKind::Topic)->micro, 0.5, 1, 2.0 / 3);
    }

    void acdMacroAndMicroByHand()
    {
        // Talker: 5/5 right. Listener: 6 elements, one wrong message type. Planner: 3
        // elements, not recovered. Extra: recovered only.
        const Evaluation e = Evaluator::evaluate(
            load(QStringLiteral("eval_models/reference")).diagrams,
            load(QStringLiteral("eval_models/recovered")).diagrams, {UmlLevel::Acd});
        const LevelEvaluation &l = e.levels.first();
        QCOMPARE(l.diagrams.size(), 3);
        const DiagramEvaluation *talker = l.diagram(QStringLiteral("Talker"));
        const DiagramEvaluation *listener = l.diagram(QStringLiteral("Listener"));
        const DiagramEvaluation *planner = l.diagram(QStringLiteral("Planner"));
        QVERIFY(talker && listener && planner);
        COMPARE_RATIOS(talker->total, 1, 1, 1);
        QCOMPARE(talker->total.tp, 5);
        COMPARE_RATIOS(listener->total, 5.0 / 6, 5.0 / 6, 5.0 / 6);
        QCOMPARE(values(listener->kind(UmlKind::MessageType)->falsePositives),
                 QStringList{QStringLiteral("std_msgs/msg/Int32")});
        QCOMPARE(values(listener->kind(UmlKind::MessageType)->falseNegatives),
                 QStringList{QStringLiteral("std_msgs/msg/String")});
        // A missing diagram scores 0/0/0 in every kind, even those empty in the reference.
        QVERIFY(planner->missing);
        QVERIFY(planner->recoveredFile.isEmpty());
        COMPARE_RATIOS(planner->total, 0, 0, 0);
        QCOMPARE(planner->total.fn, 3);
        COMPARE_RATIOS(planner->kind(UmlKind::ActionType)->score, 0, 0, 0);
        QCOMPARE(values(planner->kind(UmlKind::ArcName)->falseNegatives),
                 QStringList{QStringLiteral("Planner")});
        // Extra recovered diagrams are listed and not scored.
        QCOMPARE(l.extra.size(), 1);
        QCOMPARE(l.extra.first().name, QStringLiteral("Extra"));

        // Micro: TP 10, FP 1, FN 4. Macro: the mean of 1, 5/6 and 0.
        QCOMPARE(l.micro.tp, 10);
        QCOMPARE(l.micro.fp, 1);
        QCOMPARE(l.micro.fn, 4);
        COMPARE_RATIOS(l.micro, 10.0 / 11, 10.0 / 14, 0.8);
        COMPARE_RATIOS(l.macro, 11.0 / 18, 11.0 / 18, 11.0 / 18);
        // message type: per diagram 1, 0, 0 -> macro 1/3; counts 2/1/2 -> micro 2/3, 1/2, 4/7.
        COMPARE_RATIOS(l.kind(UmlKind::MessageType)->macro, 1.0 / 3, 1.0 / 3, 1.0 / 3);
        COMPARE_RATIOS(l.kind(UmlKind::MessageType)->micro, 2.0 / 3, 0.5, 4.0 / 7);
        // service type: Talker has none on both sides (1), Listener right (1), Planner missing (0).
        COMPARE_RATIOS(l.kind(UmlKind::ServiceType)->macro, 2.0 / 3, 2.0 / 3, 2.0 / 3);
        COMPARE_RATIOS(l.kind(UmlKind::ServiceType)->micro, 1, 1, 1);
    }

    void conventions()
    {
        const KindEvaluation empty = Evaluator::compare(UmlKind::Topic, {}, {});
        QCOMPARE(empty.score.tp + empty.score.fp + empty.score.fn, 0);
        COMPARE_RATIOS(empty.score, 1, 1, 1);

        const KindEvaluation onlyRecovered =
            Evaluator::compare(UmlKind::Topic, {}, {element(UmlKind::Topic, QStringLiteral("a"))});
        QCOMPARE(onlyRecovered.score.fp, 1);
        COMPARE_RATIOS(onlyRecovered.score, 0, 0, 0);
        const KindEvaluation onlyReference =
            Evaluator::compare(UmlKind::Topic, {element(UmlKind::Topic, QStringLiteral("a"))}, {});
        QCOMPARE(onlyReference.score.fn, 1);
        COMPARE_RATIOS(onlyReference.score, 0, 0, 0);

        // Two empty diagrams: every kind and the total are 1/1/1.
        const UmlDiagram nothing = diagram(UmlLevel::Ccd, QStringLiteral("x"), {}, {});
        const DiagramEvaluation d = Evaluator::evaluateDiagram(nothing, &nothing);
        COMPARE_RATIOS(d.total, 1, 1, 1);
        for (const KindEvaluation &k : d.kinds)
            COMPARE_RATIOS(k.score, 1, 1, 1);
        // A missing empty diagram still scores 0.
        const DiagramEvaluation missing = Evaluator::evaluateDiagram(nothing, nullptr);
        COMPARE_RATIOS(missing.total, 0, 0, 0);
    }

    void multisetsCountRepeats()
    {
        const auto t = [](const QString &v) { return element(UmlKind::MessageType, v); };
        const KindEvaluation k = Evaluator::compare(
            UmlKind::MessageType,
            {t(QStringLiteral("a")), t(QStringLiteral("a")), t(QStringLiteral("b"))},
            {t(QStringLiteral("a")), t(QStringLiteral("b")), t(QStringLiteral("b"))});
        QCOMPARE(k.score.tp, 2);
        QCOMPARE(values(k.falsePositives), QStringList{QStringLiteral("b")});
        QCOMPARE(values(k.falseNegatives), QStringList{QStringLiteral("a")});
        COMPARE_RATIOS(k.score, 2.0 / 3, 2.0 / 3, 2.0 / 3);
    }

    void sameNameDiagramsAreMatchedByFileStem()
    {
        const UmlElement a = element(UmlKind::ArcName, QStringLiteral("Talker"));
        const UmlElement one = element(UmlKind::MessageType, QStringLiteral("p/msg/One"));
        const UmlElement two = element(UmlKind::MessageType, QStringLiteral("p/msg/Two"));
        const QList<UmlDiagram> reference = {
            diagram(UmlLevel::Acd, QStringLiteral("Talker"), QStringLiteral("ref/pkg1.Talker.puml"),
                    {a, one}),
            diagram(UmlLevel::Acd, QStringLiteral("Talker"), QStringLiteral("ref/pkg2.Talker.puml"),
                    {a, two})};
        const QList<UmlDiagram> recovered = {
            diagram(UmlLevel::Acd, QStringLiteral("Talker"), QStringLiteral("rec/pkg2.Talker.puml"),
                    {a, two}),
            diagram(UmlLevel::Acd, QStringLiteral("Talker"), QStringLiteral("rec/pkg1.Talker.puml"),
                    {a, one})};
        const LevelEvaluation l = Evaluator::evaluateLevel(reference, recovered, UmlLevel::Acd);
        QCOMPARE(l.diagrams.size(), 2);
        QCOMPARE(l.diagrams.at(0).recoveredFile, QStringLiteral("rec/pkg1.Talker.puml"));
        QCOMPARE(l.diagrams.at(1).recoveredFile, QStringLiteral("rec/pkg2.Talker.puml"));
        COMPARE_RATIOS(l.micro, 1, 1, 1);
        QVERIFY(l.extra.isEmpty());
    }

    void onlyTheAskedLevels()
    {
        const UmlModel reference = load(QStringLiteral("eval_models/reference"));
        const Evaluation e = Evaluator::evaluate(reference.diagrams, {}, {UmlLevel::Ccd});
        QCOMPARE(e.levels.size(), 1);
        QVERIFY(e.level(UmlLevel::Acd) == nullptr);
        QVERIFY(e.level(UmlLevel::Ccd)->diagrams.first().missing);
        COMPARE_RATIOS(e.level(UmlLevel::Ccd)->micro, 0, 0, 0);
        QCOMPARE(e.level(UmlLevel::Ccd)->micro.fn, 16);
    }
};

QTEST_GUILESS_MAIN(TestEvaluator)
#include "tst_evaluator.moc"
