// schemas/atomic-nodes.schema.json describes atomic_nodes.json as AtomicNodesJson::write writes
// it: every fixture's expected List of Atomic ROS Nodes validates against it with a real
// JSON-schema validator (scripts/fetch-sarif-schema.sh puts it in the build tree, node runs
// it), and so does a list that sets every optional field; a wrong field type is refused.
#include "artifacts/atomicnodesjson.h"
#include "support/jsonschemacheck.h"
#include "support/testsupport.h"

#include <QtTest>

using namespace rosarch;

namespace {

/// Runs the schema validator on `file`; its exit code (0: valid, 1: invalid) and output.
int validate(const QString &file, QString *output)
{
    return test::validateJsonSchema(
        test::sourceFile(QStringLiteral("schemas/atomic-nodes.schema.json")), {file}, output);
}

Evidence at(int line)
{
    return {QStringLiteral("src/pkg/src/a.cpp"), line, 1, line, 20};
}

/// A list in which every optional field of the format is set at least once.
AtomicNodeList everyField()
{
    ParameterDeclaration rate;
    rate.name = QStringLiteral("{prefix}.rate");
    rate.nameExpression = QStringLiteral("prefix_ + \".rate\"");
    rate.type = QStringLiteral("double");
    rate.defaultValue = QStringLiteral("2.0");
    rate.hasDefault = true;
    rate.readOnly = true;
    rate.description = QStringLiteral("How often");
    rate.range = QStringLiteral("[0.0, 10.0] step 0.5");
    rate.guard = QStringLiteral("use_rate_");
    rate.via = QStringLiteral("declare_parameter");
    rate.inherited = true;
    rate.evidence = at(3);
    ParameterDeclaration any;
    any.name = QStringLiteral("any");
    any.dynamicTyping = true;
    any.range = QStringLiteral("one of [a, b]");
    any.via = QStringLiteral("declare_parameter");
    any.evidence = at(4);

    Port pub;
    pub.id = QStringLiteral("p1");
    pub.name = QStringLiteral("out");
    pub.type = QStringLiteral("topic_type_");
    pub.nameOrigin = NameOrigin::Parameter;
    pub.nameExpression = QStringLiteral("prefix_ + \"/out\"");
    pub.parameter = QStringLiteral("prefix");
    pub.parameterPrefix = QStringLiteral("/");
    pub.parameterSuffix = QStringLiteral("/out");
    pub.guard = QStringLiteral("enabled_");
    pub.guardParameter = QStringLiteral("enabled");
    pub.guardDefault = QStringLiteral("true");
    pub.via = QStringLiteral("Helper");
    pub.qos = QStringLiteral("10");
    pub.inherited = true;
    pub.evidence = at(5);
    pub.viaEvidence = {at(6)};
    pub.marks = {Provenance::Corrected, true};
    Port client;
    client.id = QStringLiteral("rs1");
    client.kind = PortKind::ServiceClient;
    client.name = QStringLiteral("get");
    client.type = QStringLiteral("pkg/srv/Get");
    client.evidence = at(7);

    AtomicNode node;
    node.id = QStringLiteral("arc_1");
    node.className = QStringLiteral("A");
    node.qualifiedName = QStringLiteral("pkg::A");
    node.nodeName = QStringLiteral("a");
    node.packageName = QStringLiteral("pkg");
    node.sourceFiles = {QStringLiteral("src/pkg/src/a.cpp")};
    node.executables = {QStringLiteral("a")};
    node.lifecycle = true;
    node.evidence = at(1);
    node.ports = {pub, client};
    node.children = {
        {QStringLiteral("pkg::Child"), QStringLiteral("child"), QStringLiteral("ns"), at(8)}};
    node.constructions = {{QStringLiteral("A"),
                           QStringLiteral("a"),
                           QStringLiteral("a"),
                           QStringLiteral("argc > 1"),
                           {client},
                           at(9)}};
    node.parameters = {rate, any};
    node.acceptsUndeclared = true;
    node.marks = {Provenance::Suggested, false};
    AtomicNode plugin;
    plugin.id = QStringLiteral("arc_2");
    plugin.className = QStringLiteral("Plugin");
    plugin.packageName = QStringLiteral("pkg");
    plugin.plugins = {QStringLiteral("pkg::Plugin")};
    plugin.pluginInterface = QStringLiteral("base::Interface");
    plugin.evidence = at(10);
    AtomicNode outside = plugin; // in no package
    outside.id = QStringLiteral("arc_3");
    outside.packageName.clear();
    outside.pluginInterface.clear();
    outside.compileType = AtomicNode::CompileType::Python;
    outside.procedural = true;

    RosPackage pkg;
    pkg.name = QStringLiteral("pkg");
    pkg.buildType = QStringLiteral("ament_cmake");
    pkg.path = QStringLiteral("src/pkg");
    AtomicNodeList list;
    list.packages = {pkg};
    list.nodes = {node, plugin, outside};
    list.helperParameters = {any};
    return list;
}

} // namespace

class TestAtomicNodesSchema : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY2(QFileInfo::exists(QStringLiteral(ROSARCH_SARIF_DIR "/json-schema")),
                 "the JSON-schema validator is missing: run scripts/fetch-sarif-schema.sh "
                 "build/_sarif (./setup.sh does)");
        QVERIFY2(QFileInfo(QStringLiteral(ROSARCH_NODE)).isExecutable(),
                 "nodejs is missing (./setup.sh installs it)");
        QVERIFY(m_dir.isValid());
        const QByteArray every = AtomicNodesJson::write(everyField());
        test::writeFile(m_dir.filePath(QStringLiteral("every.json")), every);
        // the same with a boolean written as a string
        QByteArray wrong = every;
        QVERIFY(wrong.contains("\"read_only\": true"));
        wrong.replace("\"read_only\": true", "\"read_only\": \"true\"");
        test::writeFile(m_dir.filePath(QStringLiteral("wrong.json")), wrong);
    }

    void documentValidates_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("expected");
        QTest::addColumn<QString>("complaint"); ///< in the validator's output when invalid
        const QDir data(test::dataDir());
        int fixtures = 0;
        for (const QString &c : data.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
            const QString file = data.filePath(c + QStringLiteral("/expected/atomic_nodes.json"));
            if (!QFileInfo::exists(file))
                continue;
            QTest::newRow(qPrintable(c)) << file << 0 << QString();
            ++fixtures;
        }
        QVERIFY2(fixtures >= 30, "the fixtures' expected atomic_nodes.json are missing");
        QTest::newRow("every optional field")
            << m_dir.filePath(QStringLiteral("every.json")) << 0 << QString();
        QTest::newRow("wrong field type") << m_dir.filePath(QStringLiteral("wrong.json")) << 1
                                          << QStringLiteral("/parameters/0/read_only");
    }

    void documentValidates()
    {
        QFETCH(QString, file);
        QFETCH(int, expected);
        QFETCH(QString, complaint);
        QString output;
        const int code = validate(file, &output);
        QVERIFY2(code == expected, qPrintable(output));
        QVERIFY2(output.contains(complaint), qPrintable(output));
    }
};

QTEST_GUILESS_MAIN(TestAtomicNodesSchema)
#include "tst_atomicnodesschema.moc"
