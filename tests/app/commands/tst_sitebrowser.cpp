// The architecture site in a real browser: Debian's chromium, driven by puppeteer-core
// (tests/support/site/check-site.mjs), opens the site `rosarch site` writes for the example
// workspace (and for each workspace in $ROSARCH_SITE_WORKSPACES, colon-separated, such as
// navigation2) and checks that every link resolves, that the search finds a node, a topic and
// a launch file and leads to their pages, and that a click on a part of a system diagram lands
// on its node page. The Nu HTML Checker validates every page, axe-core finds no serious or
// critical violation. Screenshots go to <build>/site-screenshots/<workspace>/.
#include "support/testsupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

QString exampleWorkspace()
{
    return QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
        .filePath(QStringLiteral("resources/example_ws"));
}

/// Search terms for a workspace the test knows nothing about: a node, a topic and a launch
/// file whose names are unique in the site's search index, each with its page.
QStringList termsFromIndex(const QByteArray &script)
{
    const qsizetype start = script.indexOf('[');
    const QJsonArray entries =
        QJsonDocument::fromJson(script.mid(start, script.lastIndexOf(']') - start + 1)).array();
    QMap<QString, int> names;
    for (const QJsonValue &e : entries)
        names[e.toArray().at(0).toString()] += 1;
    QStringList terms;
    for (const QString &kind :
         {QStringLiteral("node"), QStringLiteral("topic"), QStringLiteral("launch file")})
        for (const QJsonValue &e : entries) {
            const QJsonArray a = e.toArray();
            if (a.at(1).toString() == kind && names.value(a.at(0).toString()) == 1) {
                terms << a.at(0).toString() + u'=' + a.at(2).toString();
                break;
            }
        }
    return terms;
}

} // namespace

class TestSiteBrowser : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void siteWorksInABrowser_data()
    {
        QTest::addColumn<QString>("workspace");
        QTest::addColumn<QStringList>("terms");
        QTest::newRow("example_ws")
            << exampleWorkspace()
            << QStringList{
                   QStringLiteral("LidarFilter=nodes/robot_sensing.LidarFilter.html"),
                   QStringLiteral("/robot1/scan_filtered=topics/robot1.scan_filtered.html"),
                   QStringLiteral(
                       "navigation.launch.xml=launch/robot_bringup.navigation.launch.xml.html")};
        const QString more = qEnvironmentVariable("ROSARCH_SITE_WORKSPACES");
        for (const QString &ws : more.split(u':', Qt::SkipEmptyParts))
            QTest::newRow(qPrintable(QDir(ws).dirName())) << ws << QStringList();
    }

    void siteWorksInABrowser()
    {
        QFETCH(QString, workspace);
        QFETCH(QStringList, terms);
        const QString tools = QStringLiteral(ROSARCH_SITE_TOOLS_DIR);
        QVERIFY2(
            QFileInfo::exists(tools + QStringLiteral("/node_modules/puppeteer-core/package.json")),
            "puppeteer-core, vnu-jar and axe-core are missing: run scripts/fetch-site-tools.sh "
            "build/_sitetools (./setup.sh does)");
        QVERIFY2(QFileInfo(QStringLiteral(ROSARCH_CHROMIUM)).isExecutable(),
                 "Debian's chromium is missing: apt-get install chromium (./setup.sh does)");
        QVERIFY2(QFileInfo(QStringLiteral(ROSARCH_JAVA)).isExecutable(), "java is missing");
        QVERIFY2(QFileInfo(QStringLiteral(ROSARCH_NODE)).isExecutable(), "node is missing");

        QTemporaryDir dir;
        const QString site = dir.filePath(QStringLiteral("site"));
        const test::Run run =
            test::runRosarch({QStringLiteral("site"), workspace, QStringLiteral("--out"), site});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        if (terms.isEmpty())
            terms =
                termsFromIndex(test::readFile(site + QStringLiteral("/assets/search-index.js")));
        QCOMPARE(terms.size(), 3);

        const QString shots = QStringLiteral(ROSARCH_SCREENSHOT_DIR) + u'/' +
                              QString::fromLatin1(QTest::currentDataTag());
        QProcess check;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("ROSARCH_SITE_TOOLS"), tools);
        check.setProcessEnvironment(env);
        check.start(QStringLiteral(ROSARCH_NODE),
                    QStringList{QStringLiteral(ROSARCH_SOURCE_DIR) +
                                    QStringLiteral("/tests/support/site/check-site.mjs"),
                                site, shots, QStringLiteral(ROSARCH_CHROMIUM),
                                tools + QStringLiteral("/node_modules/vnu-jar/build/dist/vnu.jar"),
                                QStringLiteral(ROSARCH_JAVA)} +
                        terms);
        QVERIFY(check.waitForStarted(10000));
        QVERIFY2(QTest::qWaitFor([&] { return check.state() == QProcess::NotRunning; }, 540000),
                 "the browser check did not finish");
        const QByteArray stderrText = check.readAllStandardError();
        QVERIFY2(check.exitStatus() == QProcess::NormalExit && check.exitCode() == 0,
                 stderrText.constData());
        QJsonParseError error;
        const QJsonObject report =
            QJsonDocument::fromJson(check.readAllStandardOutput(), &error).object();
        QVERIFY2(!report.isEmpty(), qPrintable(error.errorString()));

        // Links: between pages (with their fragments) and to the source files.
        QVERIFY(report.value(QLatin1String("pages")).toInt() > 20);
        QVERIFY(report.value(QLatin1String("links")).toInt() > 100);
        QVERIFY(report.value(QLatin1String("sourceLinks")).toInt() > 10);
        const auto none = [](const QJsonValue &list) {
            QStringList items;
            for (const QJsonValue &v : list.toArray())
                items << v.toString();
            return items.mid(0, 10).join(u'\n');
        };
        QVERIFY2(report.value(QLatin1String("brokenLinks")).toArray().isEmpty(),
                 qPrintable(none(report.value(QLatin1String("brokenLinks")))));
        QVERIFY2(report.value(QLatin1String("brokenSourceLinks")).toArray().isEmpty(),
                 qPrintable(none(report.value(QLatin1String("brokenSourceLinks")))));
        // Search: each name's first result leads to its page.
        const QJsonArray search = report.value(QLatin1String("search")).toArray();
        QCOMPARE(search.size(), terms.size());
        for (const QJsonValue &v : search) {
            const QJsonObject s = v.toObject();
            QVERIFY2(s.value(QLatin1String("results")).toInt() > 0,
                     qPrintable(s.value(QLatin1String("text")).toString()));
            QCOMPARE(s.value(QLatin1String("landed")).toString(),
                     s.value(QLatin1String("expected")).toString());
        }
        // A part of a system diagram leads to its node class's page.
        const QJsonObject click = report.value(QLatin1String("diagramClick")).toObject();
        QVERIFY2(
            click.value(QLatin1String("landed")).toString().startsWith(QLatin1String("nodes/")),
            qPrintable(QJsonDocument(click).toJson()));
        QVERIFY(!click.value(QLatin1String("heading")).toString().isEmpty());
        // The keyboard reaches the diagram's links, and Enter follows one off the page.
        const QJsonObject keyboard = report.value(QLatin1String("keyboard")).toObject();
        QVERIFY2(keyboard.value(QLatin1String("reached")).toBool(),
                 qPrintable(QJsonDocument(keyboard).toJson()));
        QVERIFY2(keyboard.value(QLatin1String("landed")).toString() !=
                     click.value(QLatin1String("from")).toString(),
                 qPrintable(QJsonDocument(keyboard).toJson()));
        // Validity and accessibility.
        QVERIFY(report.value(QLatin1String("vnuChecked")).toInt() ==
                report.value(QLatin1String("pages")).toInt());
        QVERIFY2(report.value(QLatin1String("vnu")).toArray().isEmpty(),
                 qPrintable(none(report.value(QLatin1String("vnu")))));
        const QJsonArray axe = report.value(QLatin1String("axe")).toArray();
        QVERIFY(axe.size() >= 8);
        QStringList serious;
        for (const QJsonValue &p : axe)
            for (const QJsonValue &v : p.toObject().value(QLatin1String("violations")).toArray()) {
                const QString impact = v.toObject().value(QLatin1String("impact")).toString();
                if (impact == QLatin1String("serious") || impact == QLatin1String("critical"))
                    serious << QStringLiteral("%1 (%2): %3 %4")
                                   .arg(
                                       p.toObject().value(QLatin1String("page")).toString(),
                                       p.toObject().value(QLatin1String("scheme")).toString(),
                                       v.toObject().value(QLatin1String("id")).toString(),
                                       QString::fromUtf8(
                                           QJsonDocument(
                                               v.toObject().value(QLatin1String("nodes")).toArray())
                                               .toJson(QJsonDocument::Compact)));
            }
        QVERIFY2(serious.isEmpty(), qPrintable(serious.mid(0, 10).join(u'\n')));
        QVERIFY(report.value(QLatin1String("screenshots")).toArray().size() >= 8);
    }
};

QTEST_GUILESS_MAIN(TestSiteBrowser)
#include "tst_sitebrowser.moc"
