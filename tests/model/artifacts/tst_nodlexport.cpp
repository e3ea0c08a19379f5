// NoDL export: the node classes of tests/data/params_checks become NoDL v2 documents that the
// NoDL schema (tests/data/nodl, validated as the NoDL project's own loader does it, by
// tests/support/validate-nodl.py) accepts, with the parameters, topics and QoS the code
// declares; what NoDL cannot express is left out and said. `rosarch export nodl` writes the
// same documents.
#include "artifacts/nodlwriter.h"
#include "pipeline/recovery.h"
#include "support/testsupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace rosarch;

namespace {

QString workspace()
{
    return test::dataDir(QStringLiteral("params_checks/ws"));
}

/// Runs the NoDL validator on `files`; its exit code (0: all valid, 1: some invalid) and output.
int validate(const QStringList &files, QString *output)
{
    QProcess python;
    python.start(QStringLiteral(ROSARCH_PYTHON3),
                 QStringList{QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                                 .filePath(QStringLiteral("tests/support/validate-nodl.py")),
                             test::dataDir(QStringLiteral("nodl"))} +
                     files);
    if (!python.waitForFinished(60000))
        return -1;
    *output = QString::fromUtf8(python.readAllStandardOutput() + python.readAllStandardError());
    return python.exitStatus() == QProcess::NormalExit ? python.exitCode() : -2;
}

/// Writes `files` below `dir`; their paths.
QStringList writeAll(const QString &dir, const QMap<QString, QByteArray> &files)
{
    QStringList paths;
    for (auto it = files.cbegin(); it != files.cend(); ++it) {
        paths << QDir(dir).filePath(it.key());
        test::writeFile(paths.last(), it.value());
    }
    return paths;
}

QJsonObject object(const QByteArray &json)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError)
        qWarning() << error.errorString();
    return doc.object();
}

/// The endpoint named `name` in the array `array` of `doc` (empty when there is none).
QJsonObject endpoint(const QJsonObject &doc, const QString &array, const QString &name)
{
    for (const QJsonValue &e : doc.value(array).toArray())
        if (e.toObject().value(QStringLiteral("name")).toString() == name)
            return e.toObject();
    return {};
}

} // namespace

class TestNodlExport : public QObject
{
    Q_OBJECT
private:
    NodlWriter::Documents m_nodl;

    QJsonObject document(const QString &path) const { return object(m_nodl.files.value(path)); }

private Q_SLOTS:
    void initTestCase()
    {
        QProcess python;
        python.start(QStringLiteral(ROSARCH_PYTHON3),
                     {QStringLiteral("-c"), QStringLiteral("import jsonschema, yaml")});
        QVERIFY2(python.waitForFinished(60000) && python.exitCode() == 0,
                 "python3 with jsonschema and yaml is missing (./setup.sh installs "
                 "python3-jsonschema and python3-yaml)");
        const Recovery r = recoverWorkspace(workspace());
        QVERIFY(!r.nodes.canceled);
        m_nodl = NodlWriter::write(r.nodes);
    }

    void oneDocumentPerNodeClass()
    {
        // The pluginlib plugin is loaded into follow_server, not run as a node of its own.
        QCOMPARE(m_nodl.files.keys(),
                 (QStringList{QStringLiteral("drive_py/battery_watch.nodl.json"),
                              QStringLiteral("drive_py/relay_any.nodl.json"),
                              QStringLiteral("drive_servers/follow_server.nodl.json"),
                              QStringLiteral("drive_servers/speed_limiter.nodl.json")}));
        QVERIFY(m_nodl.omitted.contains(
            QStringLiteral("drive_plugins/PurePursuit: a pluginlib plugin, not a node")));
    }

    void everyDocumentValidates()
    {
        QTemporaryDir dir;
        QString output;
        QCOMPARE(validate(writeAll(dir.path(), m_nodl.files), &output), 0);
        QVERIFY2(output.isEmpty(), qPrintable(output));
    }

    void theValidatorRefusesWhatNodlCannotTake()
    {
        // A placeholder in a topic's name, and rosarch's name of a type instead of NoDL's.
        QTemporaryDir dir;
        const QStringList files = writeAll(dir.path(), {{QStringLiteral("bad.nodl.json"),
                                                         R"({"nodl_version": 2,
                                       "parameters": {"p": {"type": "integer"}},
                                       "publishers": [{"name": "{plugin}/out",
                                                       "type": "std_msgs/msg/String",
                                                       "qos": {"history": "KEEP_LAST", "depth": 1,
                                                               "reliability": "RELIABLE"}}]})"}});
        QString output;
        QCOMPARE(validate(files, &output), 1);
        QVERIFY2(output.contains(QLatin1String("#/parameters/p/type")), qPrintable(output));
        QVERIFY2(output.contains(QLatin1String("#/publishers/0/name")), qPrintable(output));
    }

    void parametersWithTypesDefaultsAndRanges()
    {
        const QJsonObject doc = document(QStringLiteral("drive_servers/speed_limiter.nodl.json"));
        QCOMPARE(doc.value(QStringLiteral("nodl_version")).toInt(), 2);
        const QJsonObject parameters = doc.value(QStringLiteral("parameters")).toObject();
        const QJsonObject scale = parameters.value(QStringLiteral("scale_velocities")).toObject();
        QCOMPARE(scale.value(QStringLiteral("type")).toString(), QStringLiteral("double"));
        QCOMPARE(scale.value(QStringLiteral("default_value")).toDouble(), 1.0);
        QCOMPARE(scale.value(QStringLiteral("description")).toString(),
                 QStringLiteral("Factor applied to every command"));
        QCOMPARE(scale.value(QStringLiteral("validation")).toObject(),
                 (QJsonObject{{QStringLiteral("bounds"), QJsonArray{0.0, 2.0}}}));
        const QJsonObject frame = parameters.value(QStringLiteral("command_frame")).toObject();
        QCOMPARE(frame.value(QStringLiteral("type")).toString(), QStringLiteral("string"));
        QCOMPARE(frame.value(QStringLiteral("default_value")).toString(),
                 QStringLiteral("base_link"));
        QCOMPARE(frame.value(QStringLiteral("read_only")).toBool(), true);
        const QJsonObject window = parameters.value(QStringLiteral("window")).toObject();
        QCOMPARE(window.value(QStringLiteral("type")).toString(), QStringLiteral("int"));
        QVERIFY(window.value(QStringLiteral("default_value")).isDouble());
        QCOMPARE(window.value(QStringLiteral("default_value")).toInt(), 5);
        QCOMPARE(parameters.value(QStringLiteral("max_velocity")).toObject(),
                 (QJsonObject{{QStringLiteral("type"), QStringLiteral("double_array")},
                              {QStringLiteral("default_value"), QJsonArray{0.5, 0.0, 2.5}}}));
        // declared with a type and no default: NoDL's "required at start-up"
        QCOMPARE(parameters.value(QStringLiteral("wheel_base")).toObject(),
                 (QJsonObject{{QStringLiteral("type"), QStringLiteral("double")}}));
        QVERIFY(!parameters.contains(QStringLiteral("legacy_mode"))); // undeclared again
        // sorted by name, as written
        const QStringList names = parameters.keys(); // QJsonObject sorts them
        const QByteArray text =
            m_nodl.files.value(QStringLiteral("drive_servers/speed_limiter.nodl.json"));
        QStringList inTextOrder = names;
        std::sort(inTextOrder.begin(), inTextOrder.end(), [&](const QString &a, const QString &b) {
            return text.indexOf('"' + a.toUtf8() + "\": {") <
                   text.indexOf('"' + b.toUtf8() + "\": {");
        });
        QCOMPARE(inTextOrder, names);

        const QJsonObject battery = document(QStringLiteral("drive_py/battery_watch.nodl.json"))
                                        .value(QStringLiteral("parameters"))
                                        .toObject();
        QCOMPARE(battery.value(QStringLiteral("thresholds")).toObject(),
                 (QJsonObject{{QStringLiteral("type"), QStringLiteral("double_array")},
                              {QStringLiteral("default_value"), QJsonArray{0.1, 0.3}},
                              {QStringLiteral("read_only"), true}}));
        QCOMPARE(battery.value(QStringLiteral("frame_id")).toObject(),
                 (QJsonObject{{QStringLiteral("type"), QStringLiteral("string")},
                              {QStringLiteral("default_value"), QStringLiteral("battery")}}));
        QCOMPARE(battery.value(QStringLiteral("low_level"))
                     .toObject()
                     .value(QStringLiteral("validation"))
                     .toObject(),
                 (QJsonObject{{QStringLiteral("bounds"), QJsonArray{0.0, 1.0}}}));
    }

    void topicsWithTypeAndQos()
    {
        const QJsonObject doc = document(QStringLiteral("drive_servers/speed_limiter.nodl.json"));
        QCOMPARE(endpoint(doc, QStringLiteral("publishers"), QStringLiteral("cmd_vel_smoothed")),
                 (QJsonObject{
                     {QStringLiteral("name"), QStringLiteral("cmd_vel_smoothed")},
                     {QStringLiteral("type"), QStringLiteral("geometry_msgs/msg/Twist")},
                     {QStringLiteral("qos"),
                      QJsonObject{{QStringLiteral("history"), QStringLiteral("KEEP_LAST")},
                                  {QStringLiteral("depth"), 10},
                                  {QStringLiteral("reliability"), QStringLiteral("RELIABLE")},
                                  {QStringLiteral("durability"), QStringLiteral("VOLATILE")}}}}));
        QVERIFY(!doc.contains(QStringLiteral("service_servers"))); // empty: left out
        // The class and where it is, for whoever traces a document back to the code.
        const QJsonObject rosarch = doc.value(QStringLiteral("codegen"))
                                        .toObject()
                                        .value(QStringLiteral("rosarch"))
                                        .toObject();
        QCOMPARE(rosarch.value(QStringLiteral("class")).toString(),
                 QStringLiteral("drive_servers::SpeedLimiter"));
        QCOMPARE(rosarch.value(QStringLiteral("node_name")).toString(),
                 QStringLiteral("speed_limiter"));
    }

    void whatNodlCannotExpressIsSaid()
    {
        // The subscription's name is the value of a parameter without a default.
        const QJsonObject battery = document(QStringLiteral("drive_py/battery_watch.nodl.json"));
        QVERIFY(!battery.contains(QStringLiteral("subscriptions")));
        QStringList aboutBattery;
        for (const QString &line : m_nodl.omitted)
            if (line.startsWith(QLatin1String("drive_py/battery_watch: subscriber ")))
                aboutBattery << line;
        QCOMPARE(aboutBattery.size(), 1);
        QVERIFY2(aboutBattery.first().endsWith(QLatin1String(": name decided at run time")),
                 qPrintable(aboutBattery.first()));
    }

    void theCommandWritesTheDocuments()
    {
        QTemporaryDir out;
        const test::Run r = test::runRosarch({QStringLiteral("export"), QStringLiteral("nodl"),
                                              workspace(), QStringLiteral("--out"), out.path()});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.startsWith(
                     QStringLiteral("Wrote %1 NoDL documents to ").arg(m_nodl.files.size())),
                 qPrintable(r.out));
        QVERIFY(
            r.err.contains(QLatin1String("note: drive_plugins/PurePursuit: a pluginlib plugin")));
        for (auto it = m_nodl.files.cbegin(); it != m_nodl.files.cend(); ++it)
            QCOMPARE(test::readFile(QDir(out.path()).filePath(it.key())), it.value());
    }

    void theCommandRefusesBadArguments_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        const QString ws = workspace();
        QTest::newRow("no format") << QStringList{QStringLiteral("export")}
                                   << QStringLiteral("export needs a format: nodl.");
        QTest::newRow("unknown format")
            << QStringList{QStringLiteral("export"), QStringLiteral("xml"), ws,
                           QStringLiteral("--out"), QStringLiteral("x")}
            << QStringLiteral("Unknown export format 'xml'");
        QTest::newRow("no --out") << QStringList{QStringLiteral("export"), QStringLiteral("nodl"),
                                                 ws}
                                  << QStringLiteral("export needs --out <dir>.");
        QTest::newRow("no workspace")
            << QStringList{QStringLiteral("export"), QStringLiteral("nodl"),
                           QStringLiteral("--out"), QStringLiteral("x")}
            << QStringLiteral("export nodl needs one workspace folder.");
    }

    void theCommandRefusesBadArguments()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const test::Run r = test::runRosarch(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(r.err.contains(QLatin1String("Usage: rosarch export nodl")));
    }
};

QTEST_GUILESS_MAIN(TestNodlExport)
#include "tst_nodlexport.moc"
