// `rosarch check`'s report: which findings fail for a --fail-on level and a baseline, and the
// four formats (text, JSON that is also a baseline, SARIF 2.1.0, JUnit XML), read back here.
// The SARIF schema itself is checked in tst_checkcommand with a real validator.
#include "artifacts/checkreport.h"
#include "core/diagnostickind.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QXmlStreamReader>
#include <QtTest>

using namespace rosarch;

namespace {

Diagnostic finding(Diagnostic::Severity s, const QString &code, const QString &message,
                   const QString &file, int line, QList<Diagnostic::Related> related = {})
{
    Evidence e;
    e.file = file;
    e.line = line;
    e.column = line > 0 ? 5 : 0;
    e.endLine = line;
    e.endColumn = line > 0 ? 20 : 0;
    return {s, code, message, e, related};
}

QList<Diagnostic> sample()
{
    Evidence pub;
    pub.file = QStringLiteral("src/a/talker.py");
    pub.line = 12;
    return {
        finding(Diagnostic::Severity::Warning, QStringLiteral("type-mismatch"),
                QStringLiteral("The topic /t is used with different types."),
                QStringLiteral("src/b/listener.cpp"), 30,
                {{QStringLiteral("/talker provides /t (std_msgs/msg/String)"), pub}}),
        finding(Diagnostic::Severity::Error, QStringLiteral("malformed-xml"),
                QStringLiteral("Broken XML."), QStringLiteral("launch/x.launch.xml"), 3),
        finding(Diagnostic::Severity::Info, QStringLiteral("topic-unheard"),
                QStringLiteral("Nobody hears /u."), QStringLiteral("src/a/talker.py"), 14),
        finding(Diagnostic::Severity::Warning, QStringLiteral("no-workspace-like-code"),
                QStringLiteral("Something without a file."), QString(), 0),
    };
}

} // namespace

class TestCheckReport : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void failOnLevels()
    {
        QCOMPARE(CheckReport(sample(), {}, Diagnostic::Severity::Error).failing(), 1);
        QCOMPARE(CheckReport(sample(), {}, Diagnostic::Severity::Warning).failing(), 3);
        QCOMPARE(CheckReport(sample(), {}, Diagnostic::Severity::Info).failing(), 4);
        QCOMPARE(CheckReport(sample(), {}, Diagnostic::Severity::Info, true).failing(), 0);
    }

    void aBaselineKeepsOldFindingsFromFailing()
    {
        const CheckReport first(sample(), {}, Diagnostic::Severity::Warning);
        QSet<QString> keys;
        QString error;
        QVERIFY(CheckReport::readBaseline(first.json(QStringLiteral("1")), &keys, &error));
        QCOMPARE(keys.size(), 4);
        // The same findings on other lines (an edit above them) are still in the baseline.
        QList<Diagnostic> later = sample();
        for (Diagnostic &d : later)
            d.evidence.line += 10;
        later << finding(Diagnostic::Severity::Warning, QStringLiteral("duplicate-node-name"),
                         QStringLiteral("2 nodes are named /x."), QStringLiteral("l.py"), 4);
        const CheckReport second(later, keys, Diagnostic::Severity::Warning);
        QCOMPARE(second.baselined(), 4);
        QCOMPARE(second.failing(), 1);
        QVERIFY(second.findings().last().failing);
        QVERIFY(second.text().contains(QLatin1String("[type-mismatch, baseline]")));
    }

    // A finding is its diagnostic as diagnostics.json writes it, with its key and its verdict;
    // `related` is there even when empty.
    void jsonFindings()
    {
        QList<Diagnostic> diagnostics = sample();
        diagnostics[1].contexts = {QStringLiteral("a.launch.py"), QStringLiteral("b.launch.xml")};
        const CheckReport report(diagnostics, {}, Diagnostic::Severity::Error);
        const QJsonObject root = QJsonDocument::fromJson(report.json(QStringLiteral("1"))).object();
        const QJsonArray findings = root[QLatin1String("findings")].toArray();
        QCOMPARE(findings.size(), 4);
        QJsonObject mismatch, broken;
        for (const QJsonValue &f : findings) {
            if (f[QLatin1String("code")] == QLatin1String("type-mismatch"))
                mismatch = f.toObject();
            if (f[QLatin1String("code")] == QLatin1String("malformed-xml"))
                broken = f.toObject();
        }
        QCOMPARE(mismatch.keys(), (QStringList{"baselined", "code", "evidence", "failing", "key",
                                               "message", "related", "severity"}));
        QCOMPARE(mismatch[QLatin1String("severity")].toString(), QStringLiteral("warning"));
        QCOMPARE(
            mismatch[QLatin1String("related")][0][QLatin1String("evidence")][QLatin1String("line")]
                .toInt(),
            12);
        QVERIFY(broken[QLatin1String("related")].isArray());
        QCOMPARE(broken[QLatin1String("related")].toArray().size(), 0);
        QCOMPARE(broken[QLatin1String("contexts")].toArray().size(), 2);
        QCOMPARE(broken[QLatin1String("failing")].toBool(), true);
        QCOMPARE(broken[QLatin1String("key")].toString(), diagnostics[1].key());
    }

    void baselineAsKeyLines()
    {
        QSet<QString> keys;
        QString error;
        QVERIFY(CheckReport::readBaseline("# accepted\ntopic-unheard:0123456789abcdef\n\n", &keys,
                                          &error));
        QCOMPARE(keys, QSet<QString>{QStringLiteral("topic-unheard:0123456789abcdef")});
        QVERIFY(!CheckReport::readBaseline("this is not a baseline\n", &keys, &error));
        QVERIFY(error.contains(QLatin1String("not a finding key")));
        QVERIFY(!CheckReport::readBaseline("{\"version\": 1}", &keys, &error));
        QVERIFY(error.contains(QLatin1String("findings")));
    }

    void sameFindingTwiceIsOne()
    {
        QList<Diagnostic> twice = sample();
        twice << sample().first();
        QCOMPARE(CheckReport(twice, {}, Diagnostic::Severity::Error).findings().size(), 4);
    }

    void text()
    {
        const QString t = CheckReport(sample(), {}, Diagnostic::Severity::Error).text();
        QVERIFY(t.contains(QLatin1String("src/b/listener.cpp:30:5: warning: The topic /t is used "
                                         "with different types. [type-mismatch]\n"
                                         "  src/a/talker.py:12: note: /talker provides /t")));
        QVERIFY(t.contains(QLatin1String("warning: Something without a file.")));
        QVERIFY(t.endsWith(QLatin1String("4 findings (1 errors, 2 warnings, 1 notes); 0 in the "
                                         "baseline; 1 fail the check.\n")));
    }

    void sarif()
    {
        QSet<QString> baseline{sample().at(2).key()};
        const QByteArray data = CheckReport(sample(), baseline, Diagnostic::Severity::Warning)
                                    .sarif(QStringLiteral("/tmp/ws"), QStringLiteral("0.1.0"));
        const QJsonObject log = QJsonDocument::fromJson(data).object();
        QCOMPARE(log.value(QStringLiteral("version")).toString(), QStringLiteral("2.1.0"));
        const QJsonObject run = log.value(QStringLiteral("runs")).toArray().at(0).toObject();
        QCOMPARE(run.value(QStringLiteral("originalUriBaseIds"))
                     .toObject()
                     .value(QStringLiteral("%SRCROOT%"))
                     .toObject()
                     .value(QStringLiteral("uri"))
                     .toString(),
                 QStringLiteral("file:///tmp/ws/"));
        const QJsonArray rules = run.value(QStringLiteral("tool"))
                                     .toObject()
                                     .value(QStringLiteral("driver"))
                                     .toObject()
                                     .value(QStringLiteral("rules"))
                                     .toArray();
        const QJsonArray results = run.value(QStringLiteral("results")).toArray();
        QCOMPARE(results.size(), 4);
        QCOMPARE(rules.size(), 4);
        for (const auto &r : results) {
            const QJsonObject o = r.toObject();
            // Every result points at its rule, and every rule has help a person can act on.
            const QJsonObject rule =
                rules.at(o.value(QStringLiteral("ruleIndex")).toInt()).toObject();
            QCOMPARE(rule.value(QStringLiteral("id")), o.value(QStringLiteral("ruleId")));
            QVERIFY(!rule.value(QStringLiteral("help"))
                         .toObject()
                         .value(QStringLiteral("text"))
                         .toString()
                         .isEmpty());
            QVERIFY(o.value(QStringLiteral("partialFingerprints"))
                        .toObject()
                        .contains(QStringLiteral("rosarchKey/v1")));
        }
        const QJsonObject mismatch = results.at(0).toObject();
        QCOMPARE(mismatch.value(QStringLiteral("ruleId")).toString(),
                 QStringLiteral("type-mismatch"));
        QCOMPARE(mismatch.value(QStringLiteral("level")).toString(), QStringLiteral("warning"));
        const QJsonObject location = mismatch.value(QStringLiteral("locations"))
                                         .toArray()
                                         .at(0)
                                         .toObject()
                                         .value(QStringLiteral("physicalLocation"))
                                         .toObject();
        QCOMPARE(location.value(QStringLiteral("artifactLocation"))
                     .toObject()
                     .value(QStringLiteral("uri"))
                     .toString(),
                 QStringLiteral("src/b/listener.cpp"));
        QCOMPARE(location.value(QStringLiteral("region"))
                     .toObject()
                     .value(QStringLiteral("startLine"))
                     .toInt(),
                 30);
        const QJsonObject related =
            mismatch.value(QStringLiteral("relatedLocations")).toArray().at(0).toObject();
        QCOMPARE(related.value(QStringLiteral("physicalLocation"))
                     .toObject()
                     .value(QStringLiteral("artifactLocation"))
                     .toObject()
                     .value(QStringLiteral("uri"))
                     .toString(),
                 QStringLiteral("src/a/talker.py"));
        QVERIFY(related.value(QStringLiteral("message"))
                    .toObject()
                    .value(QStringLiteral("text"))
                    .toString()
                    .contains(QLatin1String("/talker provides")));
        QCOMPARE(results.at(1).toObject().value(QStringLiteral("level")).toString(),
                 QStringLiteral("error"));
        // The baselined note is suppressed, so code scanning shows it as dismissed.
        const QJsonObject note = results.at(2).toObject();
        QCOMPARE(note.value(QStringLiteral("level")).toString(), QStringLiteral("note"));
        QCOMPARE(note.value(QStringLiteral("suppressions"))
                     .toArray()
                     .at(0)
                     .toObject()
                     .value(QStringLiteral("kind"))
                     .toString(),
                 QStringLiteral("external"));
        // A finding without a file has no location rather than a made-up one.
        QVERIFY(results.at(3).toObject().value(QStringLiteral("locations")).toArray().isEmpty());
        // Only a merged finding carries its systems, in the property bag.
        QVERIFY(!mismatch.contains(QStringLiteral("properties")));
    }

    void sarifContexts()
    {
        QList<Diagnostic> merged = sample();
        merged.first().contexts = {QStringLiteral("a/launch/robot.launch.py"),
                                   QStringLiteral("b/launch/sim.launch.xml")};
        const QByteArray data = CheckReport(merged, {}, Diagnostic::Severity::Warning)
                                    .sarif(QStringLiteral("/tmp/ws"), QStringLiteral("0.1.0"));
        const QJsonObject result = QJsonDocument::fromJson(data)
                                       .object()
                                       .value(QStringLiteral("runs"))
                                       .toArray()
                                       .at(0)
                                       .toObject()
                                       .value(QStringLiteral("results"))
                                       .toArray()
                                       .at(0)
                                       .toObject();
        const QJsonArray contexts = result.value(QStringLiteral("properties"))
                                        .toObject()
                                        .value(QStringLiteral("contexts"))
                                        .toArray();
        QCOMPARE(contexts.size(), 2);
        QCOMPARE(contexts.at(1).toString(), QStringLiteral("b/launch/sim.launch.xml"));
        // The catalogue's help, and a generic one for an unknown code.
        QVERIFY(DiagnosticKind::of(QStringLiteral("qos-incompatible"))
                    .help.contains(QLatin1String("best-effort")));
        QVERIFY(DiagnosticKind::of(QStringLiteral("no-workspace-like-code"))
                    .help.contains(QLatin1String("no-workspace-like-code")));
    }

    void junit()
    {
        QSet<QString> baseline{sample().at(2).key()};
        const QByteArray xml =
            CheckReport(sample(), baseline, Diagnostic::Severity::Warning).junit();
        QXmlStreamReader r(xml);
        int cases = 0, failures = 0, skipped = 0, suites = 0;
        while (!r.atEnd()) {
            if (r.readNext() != QXmlStreamReader::StartElement)
                continue;
            if (r.name() == QLatin1String("testsuite"))
                ++suites;
            else if (r.name() == QLatin1String("testcase"))
                ++cases;
            else if (r.name() == QLatin1String("failure"))
                ++failures;
            else if (r.name() == QLatin1String("skipped"))
                ++skipped;
        }
        QVERIFY2(!r.hasError(), qPrintable(r.errorString()));
        QCOMPARE(suites, 4);
        QCOMPARE(cases, 4);
        QCOMPARE(failures, 3);
        QCOMPARE(skipped, 1);
        // No finding: one passing case, so CI shows the check ran.
        QVERIFY(CheckReport({}, {}, Diagnostic::Severity::Error)
                    .junit()
                    .contains("<testcase classname=\"rosarch\" name=\"architecture checks\"/>"));
    }
};

QTEST_GUILESS_MAIN(TestCheckReport)
#include "tst_checkreport.moc"
