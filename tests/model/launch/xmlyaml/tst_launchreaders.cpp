// The XML and YAML launch readers: constructs, evidence, equivalence and malformed input.
#include "launch/xmlyaml/xmllaunchreader.h"
#include "launch/xmlyaml/yamllaunchreader.h"
#include "support/launchsupport.h"
#include "support/testsupport.h"

#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::launch;
using Kind = LaunchAction::Kind;

namespace {

QString kindName(Kind k)
{
    static const char *const names[] = {"Node",
                                        "ComposableContainer",
                                        "ComposableNode",
                                        "LoadComposableNodes",
                                        "Include",
                                        "Group",
                                        "PushNamespace",
                                        "SetRemap",
                                        "DeclareArgument",
                                        "SetLaunchConfiguration",
                                        "SetParameter",
                                        "Unresolved"};
    static_assert(std::size(names) == int(Kind::Unresolved) + 1);
    return QLatin1String(names[int(k)]);
}

QByteArray fixture(const char *name)
{
    return test::readFile(test::dataDir(QStringLiteral("frontend_reader/") + QLatin1String(name)));
}

/// The action tree without evidence, one line per action, remap, parameter and argument, so that
/// two formats can be compared and a failure shows where they differ.
void describeTree(const QList<LaunchAction> &actions, QStringList *out, int depth = 0)
{
    const QString pad(depth * 2, QLatin1Char(' '));
    for (const LaunchAction &a : actions) {
        QStringList f{kindName(a.kind)};
        auto add = [&](const char *name, const Substitution &s) {
            if (!s.isEmpty())
                f << QStringLiteral("%1=%2").arg(QLatin1String(name), s.describe());
        };
        add("pkg", a.package);
        add("exec", a.executable);
        add("plugin", a.plugin);
        add("name", a.name);
        add("ns", a.nameSpace);
        add("target", a.target);
        add("path", a.path);
        if (a.hasValue)
            f << QStringLiteral("value=") + a.value.describe();
        if (!a.scoped)
            f << QStringLiteral("unscoped");
        if (a.lifecycle)
            f << QStringLiteral("lifecycle");
        if (!a.expression.isEmpty())
            f << QStringLiteral("expr=") + a.expression;
        if (a.condition.isSet())
            f << QStringLiteral("%1(%2)").arg(a.condition.unless ? QStringLiteral("unless")
                                                                 : QStringLiteral("if"),
                                              a.condition.expression.describe());
        *out << pad + f.join(QLatin1Char(' '));
        for (const LaunchRemap &r : a.remaps)
            *out << pad +
                        QStringLiteral("  remap %1 -> %2").arg(r.from.describe(), r.to.describe());
        for (const LaunchParameter &p : a.parameters)
            *out << pad + (p.isFile ? QStringLiteral("  param-file %1").arg(p.value.describe())
                                    : QStringLiteral("  param %1 = %2")
                                          .arg(p.name.describe(), p.value.describe()));
        for (const auto &arg : a.arguments)
            *out << pad + QStringLiteral("  arg %1 := %2")
                              .arg(arg.first.describe(), arg.second.describe());
        describeTree(a.children, out, depth + 1);
    }
}

QStringList tree(const QList<LaunchAction> &actions)
{
    QStringList out;
    describeTree(actions, &out);
    return out;
}

/// Every action, remap and parameter, depth first.
void collectEvidence(const QList<LaunchAction> &actions, QList<Evidence> *out)
{
    for (const LaunchAction &a : actions) {
        *out << a.evidence;
        for (const LaunchRemap &r : a.remaps)
            *out << r.evidence;
        for (const LaunchParameter &p : a.parameters)
            *out << p.evidence;
        collectEvidence(a.children, out);
    }
}

QStringList codes(const QList<Diagnostic> &diagnostics)
{
    QStringList out;
    for (const Diagnostic &d : diagnostics)
        out << d.code;
    return out;
}

} // namespace

class TestLaunchReaders : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void isLaunchFile_data();
    void isLaunchFile();
    void xmlConstructs();
    void xmlEvidence();
    void yamlConstructs();
    void yamlEvidence();
    void xmlYamlEquivalence();
    void inlineEquivalence_data();
    void inlineEquivalence();
    void rosArguments();
    void malformedXml();
    void malformedYaml();
    void badSubstitutionInAttribute();
    void notLaunchFiles();
    void deepNesting();
};

void TestLaunchReaders::isLaunchFile_data()
{
    QTest::addColumn<bool>("yaml");
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<bool>("expected");
    QTest::newRow("xml launch") << false << QByteArray("<launch><node pkg='a' exec='b'/></launch>")
                                << true;
    QTest::newRow("xml prolog and comment")
        << false << QByteArray("<?xml version='1.0'?>\n<!-- c -->\n<launch>") << true;
    QTest::newRow("xml broken after root") << false << QByteArray("<launch><node") << true;
    QTest::newRow("package.xml") << false
                                 << QByteArray("<package format='3'><name>x</name></package>")
                                 << false;
    QTest::newRow("launch not root") << false << QByteArray("<robot><launch/></robot>") << false;
    QTest::newRow("not xml") << false << QByteArray("launch = 1") << false;
    QTest::newRow("yaml launch") << true << QByteArray("launch:\n- node: {pkg: a, exec: b}\n")
                                 << true;
    QTest::newRow("yaml comments")
        << true << QByteArray("# header\n\nlaunch:   # entities\n\n  # first\n  - arg: {name: a}\n")
        << true;
    QTest::newRow("yaml flow") << true << QByteArray("launch: [{arg: {name: a}}]\n") << true;
    QTest::newRow("parameter file")
        << true << QByteArray("/**:\n  ros__parameters:\n    launch: true\n") << false;
    QTest::newRow("launch mapping (design file)")
        << true << QByteArray("name: x\nlaunch:\n  executable: y\n") << false;
    QTest::newRow("indented launch key")
        << true << QByteArray("a:\n  launch:\n  - node: {}\n") << false;
    QTest::newRow("launcher key") << true << QByteArray("launcher:\n- x\n") << false;
}

void TestLaunchReaders::isLaunchFile()
{
    QFETCH(bool, yaml);
    QFETCH(QByteArray, content);
    QFETCH(bool, expected);
    QCOMPARE(yaml ? YamlLaunchReader::isLaunchFile(content)
                  : XmlLaunchReader::isLaunchFile(content),
             expected);
}

void TestLaunchReaders::xmlConstructs()
{
    const auto d = XmlLaunchReader::read(fixture("constructs.launch.xml"),
                                         QStringLiteral("pkg/launch/a.launch.xml"));
    QCOMPARE(d.format, LaunchFileDescription::Format::Xml);
    QCOMPARE(d.file, QStringLiteral("pkg/launch/a.launch.xml"));
    QCOMPARE(d.diagnostics, QList<Diagnostic>());
    const QStringList expected{
        "DeclareArgument name=ns value=/robot",
        "DeclareArgument name=legacy value=1",
        "DeclareArgument name=required",
        "SetLaunchConfiguration name=cfg value=$(dirname)/cfg.yaml",
        "Group if($(var use_left))",
        "  PushNamespace ns=left",
        "  Node pkg=demo exec=talker name=t1 ns=chat",
        "    remap chatter -> /chat",
        "    param rate = 10",
        "    param limits.speed.max = 2.0",
        "    param-file $(var cfg)",
        "Node pkg=demo exec=lc name=lc lifecycle",
        "PushNamespace ns=outer",
        "SetRemap",
        "  remap a -> b",
        "SetParameter",
        "  param use_sim_time = true",
        "SetParameter",
        "  param use_sim_time = false",
        "SetParameter",
        "  param-file all.yaml",
        "Node pkg=demo exec=listener unless($(var quiet))",
        "Group unscoped",
        "  Node pkg=demo exec=late",
        "Unresolved expr=shutdown",
        "Unresolved expr=frobnicate",
    };
    QCOMPARE(tree(d.actions), expected);

    const LaunchAction &arg = d.actions[0];
    QCOMPARE(arg.description, QStringLiteral("Where it runs"));
    QVERIFY(arg.hasValue);
    QVERIFY(!d.actions[2].hasValue);
    const LaunchAction &group = d.actions[4];
    QVERIFY(group.scoped);
    QCOMPARE(group.condition.text, QStringLiteral("$(var use_left)"));
    QCOMPARE(group.condition.expression, var("use_left"));
    QVERIFY(!group.condition.unless);
    QCOMPARE(d.actions[11].condition.text, QStringLiteral("$(var quiet)"));
    QVERIFY(d.actions[11].condition.unless);
    QVERIFY(!d.actions[6].condition.isSet());

    // Evidence: start line, end line of each construct in the fixture.
    auto lines = [](const Evidence &e) { return qMakePair(e.line, e.endLine); };
    QCOMPARE(lines(group.evidence), qMakePair(6, 14));
    QCOMPARE(lines(group.children[0].evidence), qMakePair(6, 6)); // the pushed ns="left"
    const LaunchAction &talker = group.children[1];
    QCOMPARE(lines(talker.evidence), qMakePair(7, 13));
    QCOMPARE(lines(talker.parameters[0].evidence), qMakePair(8, 8));
    QCOMPARE(lines(talker.parameters[1].evidence), qMakePair(9, 9));
    QCOMPARE(lines(talker.parameters[2].evidence), qMakePair(10, 10));
    QCOMPARE(lines(talker.remaps[0].evidence), qMakePair(11, 11));
    QCOMPARE(lines(d.actions[5].evidence), qMakePair(15, 15));
    QCOMPARE(lines(d.actions[7].remaps[0].evidence), qMakePair(17, 17));
    QCOMPARE(lines(d.actions[12].children[0].evidence), qMakePair(22, 22));
    QCOMPARE(lines(d.actions.last().evidence), qMakePair(25, 25));
    QCOMPARE(d.actions[1].evidence.file, QStringLiteral("pkg/launch/a.launch.xml"));
}

void TestLaunchReaders::xmlEvidence()
{
    const QByteArray xml = "<launch>\n"
                           "  <node pkg=\"a\" exec=\"b\">\n"
                           "    <remap from=\"x\" to=\"y\"/>\n"
                           "    <param name=\"p\" value=\"1\"/>\n"
                           "  </node>\n"
                           "  <!-- é --><arg name=\"é\" default=\"$(var x\"/>\n"
                           "</launch>\n";
    const auto d = XmlLaunchReader::read(xml, QStringLiteral("f.xml"));
    QCOMPARE(d.actions.size(), 2);
    const LaunchAction &node = d.actions[0];
    QCOMPARE(node.evidence, (Evidence{"f.xml", 2, 3, 5, 10}));
    QCOMPARE(node.remaps[0].evidence, (Evidence{"f.xml", 3, 5, 3, 29}));
    QCOMPARE(node.parameters[0].evidence, (Evidence{"f.xml", 4, 5, 4, 32}));
    // Columns count UTF-8 bytes: "  <!-- é -->" is 13 bytes.
    QCOMPARE(d.actions[1].evidence, (Evidence{"f.xml", 6, 14, 6, 48}));
    // The bad default is reported at its attribute.
    QCOMPARE(codes(d.diagnostics), QStringList{"malformed-substitution"});
    QCOMPARE(d.diagnostics[0].evidence, (Evidence{"f.xml", 6, 29, 6, 46}));
    QList<Evidence> all;
    collectEvidence(d.actions, &all);
    for (const Evidence &e : all)
        QVERIFY(e.isValid() && e.endLine >= e.line);
}

void TestLaunchReaders::yamlConstructs()
{
    const auto d =
        YamlLaunchReader::read(fixture("constructs.launch.yaml"), QStringLiteral("a.launch.yaml"));
    QCOMPARE(d.format, LaunchFileDescription::Format::Yaml);
    QCOMPARE(d.diagnostics, QList<Diagnostic>());
    const QStringList expected{
        "DeclareArgument name=ns value=/robot",
        "DeclareArgument name=required",
        "SetLaunchConfiguration name=cfg value=$(dirname)/cfg.yaml",
        "Group if($(var use_left))",
        "  PushNamespace ns=left",
        "  Node pkg=demo exec=talker name=t1 ns=chat",
        "    remap chatter -> /chat",
        "    param rate = 10",
        "    param limits.speed.max = 2.0",
        "    param list = [1, 2, 3]",
        "    param-file $(var cfg)",
        "Group unscoped",
        "  Node pkg=demo exec=quiet",
        "PushNamespace ns=outer",
        "SetRemap",
        "  remap a -> b",
        "SetParameter",
        "  param use_sim_time = true",
        "Node pkg=demo exec=listener unless($(var quiet))",
        "Unresolved expr=executable",
    };
    QCOMPARE(tree(d.actions), expected);
    QCOMPARE(d.actions[0].description, QStringLiteral("Where it runs"));
    QCOMPARE(d.actions[3].condition.text, QStringLiteral("$(var use_left)"));

    auto lines = [](const Evidence &e) { return qMakePair(e.line, e.endLine); };
    const LaunchAction &talker = d.actions[3].children[1];
    QCOMPARE(lines(d.actions[3].evidence), qMakePair(5, 22));
    QCOMPARE(lines(talker.evidence), qMakePair(9, 22));
    QCOMPARE(lines(talker.parameters[0].evidence), qMakePair(15, 15));
    QCOMPARE(lines(talker.parameters[1].evidence), qMakePair(19, 19)); // the nested leaf
    QCOMPARE(lines(talker.parameters[3].evidence), qMakePair(21, 21));
    QCOMPARE(lines(talker.remaps[0].evidence), qMakePair(22, 22));
    QCOMPARE(lines(d.actions[4].children[0].evidence), qMakePair(23, 23));
    QCOMPARE(lines(d.actions.last().evidence), qMakePair(28, 28));
}

void TestLaunchReaders::yamlEvidence()
{
    const QByteArray yaml = "launch:\n"                                 // 1
                            "  - node:\n"                               // 2
                            "      pkg: a\n"                            // 3
                            "      exec: b\n"                           // 4
                            "      remap:\n"                            // 5
                            "        - from: x\n"                       // 6
                            "          to: \"y\"\n"                     // 7
                            "  - arg: {name: n, default: \"$(var\"}\n"; // 8
    const auto d = YamlLaunchReader::read(yaml, QStringLiteral("f.yaml"));
    QCOMPARE(d.actions.size(), 2);
    QCOMPARE(d.actions[0].evidence, (Evidence{"f.yaml", 2, 5, 7, 18}));
    QCOMPARE(d.actions[0].remaps[0].evidence, (Evidence{"f.yaml", 6, 11, 7, 18}));
    QCOMPARE(d.actions[1].evidence.line, 8);
    QCOMPARE(codes(d.diagnostics), QStringList{"malformed-substitution"});
    QCOMPARE(d.diagnostics[0].evidence.line, 8);
    QCOMPARE(d.diagnostics[0].evidence.column, 29);
}

void TestLaunchReaders::xmlYamlEquivalence()
{
    const auto x =
        XmlLaunchReader::read(fixture("patrol.launch.xml"), QStringLiteral("patrol.launch.xml"));
    const auto y =
        YamlLaunchReader::read(fixture("patrol.launch.yaml"), QStringLiteral("patrol.launch.yaml"));
    QCOMPARE(x.diagnostics, QList<Diagnostic>());
    QCOMPARE(y.diagnostics, QList<Diagnostic>());
    const QStringList xt = tree(x.actions);
    QCOMPARE(tree(y.actions), xt);
    // Spot checks, so that equal but empty trees cannot pass.
    QCOMPARE(xt.size(), 37);
    QVERIFY(xt.contains("  Node pkg=patrol_mapping exec=mapper "
                        "unless($(eval '$(var robot)' == 'sim'))"));
    QVERIFY(xt.contains("    param filter.max_range = 30.0"));
    QVERIFY(xt.contains("  Node pkg=patrol_sim exec=world name=world_$(env USER)"));
    QVERIFY(xt.contains("ComposableContainer pkg=rclcpp_components exec=component_container "
                        "name=vision_container"));
    QVERIFY(xt.contains("  ComposableNode pkg=patrol_vision plugin=patrol_vision::Detector "
                        "name=detector ns=vision"));
    QVERIFY(xt.contains("  arg map := $(var map_file)"));
    QCOMPARE(x.actions.last().kind, Kind::Unresolved);
    QCOMPARE(y.actions.last().expression, QStringLiteral("executable"));
    QList<Evidence> evidence;
    collectEvidence(x.actions, &evidence);
    collectEvidence(y.actions, &evidence);
    for (const Evidence &e : evidence)
        QVERIFY(e.isValid() && e.endLine >= e.line);
}

void TestLaunchReaders::inlineEquivalence_data()
{
    QTest::addColumn<QByteArray>("xml");
    QTest::addColumn<QByteArray>("yaml");
    QTest::newRow("two nodes")
        << QByteArray("<launch>\n<node pkg=\"p\" exec=\"talker\" output=\"screen\"/>\n"
                      "<node pkg=\"p\" exec=\"listener\" output=\"screen\"/>\n</launch>")
        << QByteArray("launch:\n- node: {pkg: \"p\", exec: \"talker\", output: \"screen\"}\n"
                      "- node:\n    pkg: p\n    exec: listener\n    output: screen\n");
    QTest::newRow("include and group")
        << QByteArray("<launch><group scoped=\"False\"><include file=\"$(var f)\">"
                      "<arg name=\"a\" value=\"$(env A x)\"/></include></group></launch>")
        << QByteArray("launch:\n- group:\n    scoped: False\n    children:\n"
                      "    - include: {file: $(var f), arg: [{name: a, value: $(env A x)}]}\n");
}

void TestLaunchReaders::inlineEquivalence()
{
    QFETCH(QByteArray, xml);
    QFETCH(QByteArray, yaml);
    const QStringList xt = tree(XmlLaunchReader::read(xml, QStringLiteral("a.xml")).actions);
    QVERIFY(!xt.isEmpty());
    QCOMPARE(tree(YamlLaunchReader::read(yaml, QStringLiteral("a.yaml")).actions), xt);
}

void TestLaunchReaders::rosArguments()
{
    const QByteArray xml =
        R"X(<launch>
  <node pkg="p" exec="e" args="input.txt --ros-args -r scan:=$(var ns)/scan --remap __ns:=/robot -p rate:=5 --params-file 'my params.yaml' -- -r not:=this"/>
  <node pkg="p" exec="e" name="kept" ros_args="-r __node:=renamed -r a:=b"/>
</launch>)X";
    const auto d = XmlLaunchReader::read(xml, QStringLiteral("a.xml"));
    const QStringList expected{
        "Node pkg=p exec=e ns=/robot", "  remap scan -> $(var ns)/scan", "  param rate = 5",
        "  param-file my params.yaml", "Node pkg=p exec=e name=kept",    "  remap a -> b",
    };
    QCOMPARE(tree(d.actions), expected);
    QCOMPARE(d.actions[0].remaps[0].evidence.line, 2);
}

void TestLaunchReaders::malformedXml()
{
    const QByteArray xml = "<launch>\n"
                           "  <arg name=\"a\" default=\"1\"/>\n"
                           "  <group>\n"
                           "    <node pkg=\"p\" exec=\"e\"/>\n"
                           "    <node pkg=\"p\" exec=\"f\">\n"
                           "  </group>\n"
                           "  <node pkg=\"p\" exec=\"never\"/>\n"
                           "</launch>\n";
    const auto d = XmlLaunchReader::read(xml, QStringLiteral("bad.xml"));
    QCOMPARE(codes(d.diagnostics), QStringList{"malformed-xml"});
    const Diagnostic &error = d.diagnostics[0];
    QCOMPARE(error.severity, Diagnostic::Severity::Error);
    QCOMPARE(error.evidence.file, QStringLiteral("bad.xml"));
    QCOMPARE(error.evidence.line, 6);
    QVERIFY2(error.message.contains(QStringLiteral("line 6")), qPrintable(error.message));
    // What was read before the error is kept, open elements included.
    const QStringList expected{
        "DeclareArgument name=a value=1",
        "Group",
        "  Node pkg=p exec=e",
        "  Node pkg=p exec=f",
    };
    QCOMPARE(tree(d.actions), expected);
    QCOMPARE(d.actions[1].evidence.endLine, 6);

    const auto empty = XmlLaunchReader::read(QByteArray(), QStringLiteral("empty.xml"));
    QCOMPARE(codes(empty.diagnostics), QStringList{"malformed-xml"});
    QVERIFY(empty.actions.isEmpty());
    const auto garbage = XmlLaunchReader::read("<launch><node pkg='a' exec='b'/>\x01</launch>",
                                               QStringLiteral("g.xml"));
    QCOMPARE(codes(garbage.diagnostics), QStringList{"malformed-xml"});
    QCOMPARE(tree(garbage.actions), QStringList{"Node pkg=a exec=b"});
}

void TestLaunchReaders::malformedYaml()
{
    const QByteArray yaml = "launch:\n"
                            "- arg: {name: a, default: '1'}\n"
                            "- node: {pkg: p, exec: e}\n"
                            "- node: {pkg: p, exec: [unclosed}\n"
                            "- node: {pkg: p, exec: never}\n";
    const auto d = YamlLaunchReader::read(yaml, QStringLiteral("bad.yaml"));
    QCOMPARE(codes(d.diagnostics), QStringList{"malformed-yaml"});
    const Diagnostic &error = d.diagnostics[0];
    QCOMPARE(error.severity, Diagnostic::Severity::Error);
    QCOMPARE(error.evidence.line, 4);
    QVERIFY2(error.message.contains(QStringLiteral("line 4")), qPrintable(error.message));
    const QStringList expected{"DeclareArgument name=a value=1", "Node pkg=p exec=e"};
    QCOMPARE(tree(d.actions), expected);

    const auto tabs = YamlLaunchReader::read("launch:\n\t- node: {}\n", QStringLiteral("t.yaml"));
    QCOMPARE(codes(tabs.diagnostics), QStringList{"malformed-yaml"});
    QVERIFY(tabs.actions.isEmpty());

    // Well-formed YAML that is not a launch description in the expected shape.
    const auto shapes = YamlLaunchReader::read("launch:\n- node: {pkg: p, exec: e}\n- [1, 2]\n"
                                               "- {a: 1, b: 2}\n",
                                               QStringLiteral("s.yaml"));
    QCOMPARE(codes(shapes.diagnostics), (QStringList{"invalid-entity", "invalid-entity"}));
    QCOMPARE(shapes.diagnostics[1].evidence.line, 4);
    QCOMPARE(tree(shapes.actions), QStringList{"Node pkg=p exec=e"});
}

void TestLaunchReaders::badSubstitutionInAttribute()
{
    const QByteArray xml = "<launch>\n"
                           "  <node pkg=\"p\" exec=\"$(var exe\" if=\"$(eval '$(var a)\"/>\n"
                           "  <node pkg=\"p\"/>\n"
                           "</launch>";
    const auto d = XmlLaunchReader::read(xml, QStringLiteral("a.xml"));
    QCOMPARE(d.actions.size(), 2);
    const LaunchAction &node = d.actions[0];
    QCOMPARE(node.executable, Substitution::unknown(QStringLiteral("$(var exe")));
    QCOMPARE(node.condition.expression, Substitution::unknown(QStringLiteral("$(eval '$(var a)")));
    QCOMPARE(node.condition.text, QStringLiteral("$(eval '$(var a)"));
    QCOMPARE(codes(d.diagnostics), (QStringList{"malformed-substitution", "malformed-substitution",
                                                "missing-attribute"}));
    QVERIFY2(d.diagnostics[0].message.contains(QStringLiteral("'if'")),
             qPrintable(d.diagnostics[0].message));
    QCOMPARE(d.diagnostics[0].evidence.line, 2);
    QCOMPARE(d.diagnostics[0].evidence.column, 34);
    QVERIFY2(d.diagnostics[1].message.contains(QStringLiteral("'exec'")),
             qPrintable(d.diagnostics[1].message));
    QCOMPARE(d.diagnostics[2].evidence.line, 3);
}

void TestLaunchReaders::notLaunchFiles()
{
    const auto x =
        XmlLaunchReader::read("<package><name>x</name></package>", QStringLiteral("p.xml"));
    QVERIFY(x.actions.isEmpty());
    QCOMPARE(codes(x.diagnostics), QStringList{"not-a-launch-file"});
    QCOMPARE(x.diagnostics[0].severity, Diagnostic::Severity::Warning);
    const auto y =
        YamlLaunchReader::read("/**:\n  ros__parameters:\n    a: 1\n", QStringLiteral("p.yaml"));
    QVERIFY(y.actions.isEmpty());
    QCOMPARE(codes(y.diagnostics), QStringList{"not-a-launch-file"});
}

void TestLaunchReaders::deepNesting()
{
    QByteArray xml = "<launch>";
    QByteArray yaml = "launch:\n";
    QByteArray flow = "launch: [";
    for (int i = 0; i < 1000; ++i) {
        xml += "<group>";
        yaml += QByteArray(2 * i, ' ') + "- group:\n" + QByteArray(2 * i + 4, ' ') + "children:\n";
        flow += "{group: [";
    }
    xml += "<node pkg='p' exec='e'/>";
    const auto x = XmlLaunchReader::read(xml, QStringLiteral("deep.xml"));
    QVERIFY(codes(x.diagnostics).contains(QStringLiteral("nesting-too-deep")));
    QVERIFY(codes(x.diagnostics).contains(QStringLiteral("malformed-xml")));
    QCOMPARE(x.actions.size(), 1);
    QCOMPARE(x.actions[0].kind, Kind::Group);
    const auto y = YamlLaunchReader::read(yaml, QStringLiteral("deep.yaml"));
    QVERIFY(!y.diagnostics.isEmpty());
    const auto f = YamlLaunchReader::read(flow, QStringLiteral("flow.yaml"));
    QVERIFY(!f.diagnostics.isEmpty());
}

QTEST_GUILESS_MAIN(TestLaunchReaders)
#include "tst_launchreaders.moc"
