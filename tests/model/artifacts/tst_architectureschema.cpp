// schemas/architecture.schema.json describes architecture.json as ArchitectureJson::write writes
// it: every fixture's expected architecture validates against it with a real JSON-schema
// validator (scripts/fetch-sarif-schema.sh puts it in the build tree, node runs it), and so
// does an architecture that sets every optional field; a missing or mistyped field is refused.
#include "artifacts/architecturejson.h"
#include "support/jsonschemacheck.h"
#include "support/testsupport.h"

#include <QtTest>

using namespace rosarch;

namespace {

/// Runs the schema validator on `file`; its exit code (0: valid, 1: invalid) and output.
int validate(const QString &file, QString *output)
{
    return test::validateJsonSchema(
        test::sourceFile(QStringLiteral("schemas/architecture.schema.json")), {file}, output);
}

Evidence at(int line)
{
    return {QStringLiteral("src/pkg/launch/a.launch.py"), line, 1, line, 20};
}

/// An architecture, with its node list and launch dependencies, in which every optional
/// field of the format is set at least once.
struct EveryField
{
    Architecture arch;
    AtomicNodeList nodes;
    LaunchDependencies launch;
};

EveryField everyField()
{
    EveryField e;
    ParameterDeclaration rate;
    rate.name = QStringLiteral("rate");
    rate.type = QStringLiteral("double");
    rate.defaultValue = QStringLiteral("2.0");
    rate.hasDefault = true;
    rate.description = QStringLiteral("How often");
    rate.via = QStringLiteral("declare_parameter");
    rate.evidence = at(1);
    ParameterDeclaration frame;
    frame.name = QStringLiteral("frame");
    frame.type = QStringLiteral("string");
    frame.via = QStringLiteral("declare_parameter");
    frame.evidence = at(2);
    AtomicNode cls;
    cls.id = QStringLiteral("arc_1");
    cls.className = QStringLiteral("A");
    cls.packageName = QStringLiteral("pkg");
    cls.parameters = {rate, frame};
    e.nodes.nodes = {cls};

    NodeInstance n;
    n.id = QStringLiteral("n1");
    n.launchFileId = QStringLiteral("lf1");
    n.className = QStringLiteral("A");
    n.classId = QStringLiteral("arc_1");
    n.nodeName = QStringLiteral("a");
    n.nameSpace = QStringLiteral("/");
    n.effectiveParameters = {{QStringLiteral("rate"),
                              QStringLiteral("5.0"),
                              QStringLiteral("file"),
                              QStringLiteral("src/pkg/config/a.yaml"),
                              {QStringLiteral("src/pkg/config/a.yaml"), 4, 5, 4, 14}},
                             {QStringLiteral("rtae"), QStringLiteral("1.0"),
                              QStringLiteral("launch"), QString(), at(3)}};
    e.launch.nodes = {n};

    PartPort pub;
    pub.id = QStringLiteral("p1");
    pub.nameAsWritten = QStringLiteral("out");
    pub.name = QStringLiteral("/out");
    pub.type = QStringLiteral("type_");
    pub.resolved = false;
    pub.parameterDerived = true;
    pub.remapped = true;
    pub.guard = QStringLiteral("enabled_");
    pub.active = false;
    pub.evidence = at(5);
    pub.marks = {Provenance::Corrected, true};
    pub.model = QStringLiteral("tf2_ros");
    PartPort sub;
    sub.id = QStringLiteral("s1");
    sub.kind = PortKind::Subscriber;
    sub.name = QStringLiteral("/in");
    sub.type = QStringLiteral("std_msgs/msg/Empty");

    RosNodePart node;
    node.id = QStringLiteral("part1");
    node.instanceId = QStringLiteral("n1");
    node.name = QStringLiteral("a");
    node.typeName = QStringLiteral("A");
    node.typeId = QStringLiteral("arc_1");
    node.nameSpace = QStringLiteral("/");
    node.typed = false;
    node.ports = {pub, sub};
    node.evidence = at(6);
    node.subsystem = QStringLiteral("perception");
    node.marks = {Provenance::Suggested, false};
    RosNodePart include;
    include.id = QStringLiteral("part2");
    include.kind = RosNodePart::Kind::Launch;
    include.instanceId = QStringLiteral("lf2");
    include.typeName = QStringLiteral("outside");
    include.typeId = QStringLiteral("lf2");
    include.nameSpace = QStringLiteral("/ns");
    include.active = false;
    include.external = true;
    include.ports = {sub};

    Composite root;
    root.instanceId = QStringLiteral("lf1");
    root.stem = QStringLiteral("a");
    root.file = QStringLiteral("src/pkg/launch/a.launch.py");
    root.package = QStringLiteral("pkg");
    root.parts = {node, include};
    Channel topic;
    topic.id = QStringLiteral("q_in");
    topic.name = QStringLiteral("/in");
    topic.type = QStringLiteral("std_msgs/msg/Empty");
    topic.marks = {Provenance::Recovered, true};
    root.channels = {topic};
    root.boundary = {{QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("/out"),
                      QStringLiteral("type_"), true}};
    root.connections = {{Connection::Kind::Subscribe, QStringLiteral("part1"), QStringLiteral("s1"),
                         QStringLiteral("q_in")},
                        {Connection::Kind::Subscribe, QStringLiteral("part2"), QStringLiteral("s1"),
                         QStringLiteral("q_in")},
                        {Connection::Kind::DelegationOut, QStringLiteral("part1"),
                         QStringLiteral("p1"), QStringLiteral("p1")}};
    Composite exe; // an executable's own system
    exe.instanceId = QStringLiteral("lf3");
    exe.stem = QStringLiteral("a_main");
    exe.file = QStringLiteral("src/pkg/src/main.cpp");
    exe.package = QStringLiteral("pkg");
    exe.executable = QStringLiteral("a_main");
    e.arch.composites = {root, exe};
    return e;
}

} // namespace

class TestArchitectureSchema : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;

    /// Writes `every` with `from` replaced by `to` (which must be there) as `name`.
    bool writeVariant(const QByteArray &every, const char *name, const QByteArray &from,
                      const QByteArray &to)
    {
        if (!every.contains(from))
            return false;
        QByteArray variant = every;
        variant.replace(from, to);
        test::writeFile(m_dir.filePath(QString::fromLatin1(name)), variant);
        return true;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY2(QFileInfo::exists(QStringLiteral(ROSARCH_SARIF_DIR "/json-schema")),
                 "the JSON-schema validator is missing: run scripts/fetch-sarif-schema.sh "
                 "build/_sarif (./setup.sh does)");
        QVERIFY2(QFileInfo(QStringLiteral(ROSARCH_NODE)).isExecutable(),
                 "nodejs is missing (./setup.sh installs it)");
        QVERIFY(m_dir.isValid());
        const EveryField e = everyField();
        const QByteArray every = ArchitectureJson::write(
            e.arch, {{QStringLiteral("lf1"), QStringLiteral("a")}}, &e.nodes, &e.launch);
        test::writeFile(m_dir.filePath(QStringLiteral("every.json")), every);
        // each optional field the format has is in it
        for (const char *field :
             {"\"name_as_written\"", "\"type_resolved\"", "\"unresolved\"", "\"parameter_derived\"",
              "\"remapped\"", "\"interface_model\"", "\"guard\"", "\"provenance\"", "\"reviewed\"",
              "\"external\"", "\"typed\"", "\"subsystem\"", "\"parameters\"", "\"declared\"",
              "\"description\"", "\"executable\"", "\"ccd\""})
            QVERIFY2(every.contains(field), field);
        // a boolean written as a string, a required field left out, a field of our own
        // misspelt, a value's source in no known form
        QVERIFY(writeVariant(every, "string.json", "\"active\": false", "\"active\": \"false\""));
        QVERIFY(writeVariant(every, "missing.json", "\"namespace\": \"/ns\",", ""));
        QVERIFY(writeVariant(every, "misspelt.json", "\"boundary_ports\"", "\"boundary\""));
        QVERIFY(
            writeVariant(every, "source.json", "\"source\": \"launch\"", "\"source\": \"yaml\""));
    }

    void documentValidates_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("expected");
        QTest::addColumn<QString>("complaint"); ///< in the validator's output when invalid
        const QDir data(test::dataDir());
        int fixtures = 0;
        for (const QString &c : data.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
            const QString file = data.filePath(c + QStringLiteral("/expected/architecture.json"));
            if (!QFileInfo::exists(file))
                continue;
            QTest::newRow(qPrintable(c)) << file << 0 << QString();
            ++fixtures;
        }
        QVERIFY2(fixtures >= 10, "the fixtures' expected architecture.json are missing");
        const auto row = [this](const char *name, int expected, const QString &complaint) {
            QTest::newRow(name) << m_dir.filePath(QString::fromLatin1(name)) << expected
                                << complaint;
        };
        row("every.json", 0, {});
        row("string.json", 1, QStringLiteral("/ports/0/active"));
        row("missing.json", 1, QStringLiteral("/parts/1"));
        row("misspelt.json", 1, QStringLiteral("/list_composed_ros_node_classifiers/0"));
        row("source.json", 1, QStringLiteral("/parameters/2/source")); // sorted by name
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

QTEST_GUILESS_MAIN(TestArchitectureSchema)
#include "tst_architectureschema.moc"
