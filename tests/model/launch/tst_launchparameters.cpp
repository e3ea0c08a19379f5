// Stage 2's parameters as ROS 2 applies them: parameter files by node keys and wildcards,
// RewrittenYaml, plugin names from parameters, and what is said about bad parameter files.
#include "executorfixture.h"
#include "support/testsupport.h"

#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::executor;
using rosarch::test::launch::var;

class TestLaunchParameters : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parameterFilesApplyAsRos2Does()
    {
        // Node keys by namespace and name, the /** wildcard before the node's own entry, later
        // sources over earlier ones, nested keys dotted, code defaults last (blueprint §1).
        Fixture fx;
        fx.nodes.nodes[0].ports << Port{};
        Port &named = fx.nodes.nodes[0].ports.last();
        named.id = QStringLiteral("p1");
        named.name = QStringLiteral("chatter");
        named.nameOrigin = NameOrigin::Parameter;
        named.parameter = QStringLiteral("topic_default_only");
        QDir(fx.dir.path()).mkpath(QStringLiteral("bringup/config"));
        QFile yaml(fx.dir.filePath(QStringLiteral("bringup/config/p.yaml")));
        QVERIFY(yaml.open(QIODevice::WriteOnly));
        yaml.write("/**:\n"                 // 1
                   "  ros__parameters:\n"   // 2
                   "    rate: 1\n"          // 3
                   "    topic: all\n"       // 4
                   "ns1:\n"                 // 5
                   "  talker:\n"            // 6
                   "    ros__parameters:\n" // 7
                   "      topic: mine\n"    // 8
                   "      nested:\n"        // 9
                   "        deep: [1, 2]\n" // 10
                   "/other:\n"              // 11
                   "  ros__parameters:\n"   // 12
                   "    topic: nope\n");    // 13
        yaml.close();
        const Substitution file = share(QStringLiteral("bringup"), QStringLiteral("config/p.yaml"));
        LaunchAction inNs =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("talker"), 3);
        inNs.nameSpace = lit(QStringLiteral("ns1"));
        inNs.parameters = {parameterFile(file), value(QStringLiteral("rate"), QStringLiteral("5"))};
        LaunchAction atRoot =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("talker"), 4);
        atRoot.parameters = {value(QStringLiteral("rate"), QStringLiteral("7")),
                             parameterFile(file)};
        fx.add(QStringLiteral("bringup/launch/p.launch.py"), {inNs, atRoot});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/p.launch.py"));
        QCOMPARE(d.nodes.size(), 2);
        QCOMPARE(
            effective(d.nodes[0]),
            (QStringList{QStringLiteral("nested.deep=[1, 2] (file 10)"),
                         QStringLiteral("rate=5 (launch 8)"), QStringLiteral("topic=mine (file 8)"),
                         QStringLiteral("topic_default_only=chatter (default 0)")}));
        QCOMPARE(
            effective(d.nodes[1]),
            (QStringList{QStringLiteral("rate=1 (file 3)"), QStringLiteral("topic=all (file 4)"),
                         QStringLiteral("topic_default_only=chatter (default 0)")}));
        QCOMPARE(d.nodes[0].effectiveParameters.first().file,
                 QStringLiteral("bringup/config/p.yaml"));
        QVERIFY(d.diagnostics.isEmpty());
    }

    void rewrittenYamlRewritesAndMovesUnderTheRootKey()
    {
        Fixture fx;
        QDir(fx.dir.path()).mkpath(QStringLiteral("bringup/config"));
        QFile yaml(fx.dir.filePath(QStringLiteral("bringup/config/base.yaml")));
        QVERIFY(yaml.open(QIODevice::WriteOnly));
        yaml.write("talker:\n  ros__parameters:\n    topic: base\n    use_sim_time: false\n"
                   "    other: kept\n    zone:\n      enabled: ZONE_ON\n");
        yaml.close();
        Substitution rewritten;
        rewritten.kind = Substitution::Kind::RewrittenYaml;
        rewritten.parts << share(QStringLiteral("bringup"), QStringLiteral("config/base.yaml"))
                        << var(QStringLiteral("namespace")) << lit(QStringLiteral("topic"))
                        << lit(QStringLiteral("rewritten")) << lit(QStringLiteral("missing"))
                        << lit(QStringLiteral("not added")) // value_rewrites: by value
                        << lit(QStringLiteral("=ZONE_ON")) << lit(QStringLiteral("true"));
        const QString robot = QStringLiteral("robot");
        LaunchAction talker =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("talker"), 3);
        talker.nameSpace = var(QStringLiteral("namespace"));
        talker.parameters = {parameterFile(rewritten)};
        LaunchAction plain = node(QStringLiteral("demo"), QStringLiteral("talker"),
                                  QStringLiteral("talker"), 4); // at the root: the key moved
        plain.parameters = {parameterFile(rewritten)};
        fx.add(QStringLiteral("bringup/launch/r.launch.py"),
               {declare(QStringLiteral("namespace"), &robot), talker, plain});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/r.launch.py"));
        QCOMPARE(d.nodes.size(), 2);
        QCOMPARE(d.nodes[0].nameSpace, QStringLiteral("/robot"));
        QCOMPARE(effective(d.nodes[0]),
                 (QStringList{QStringLiteral("other=kept (file 5)"),
                              QStringLiteral("topic=rewritten (launch 9)"),
                              QStringLiteral("use_sim_time=false (file 4)"),
                              QStringLiteral("zone.enabled=true (launch 9)")}));
        QCOMPARE(effective(d.nodes[1]), QStringList());
    }

    void pluginsAreNamedByParameters()
    {
        // pluginlib's convention: `<name>.plugin: "pkg::Class"` loads plugin <name> when a
        // list (or a single name) of the node's parameters names it; `Spare` is configured
        // but no parameter loads it.
        Fixture fx;
        QDir(fx.dir.path()).mkpath(QStringLiteral("bringup/config"));
        QFile yaml(fx.dir.filePath(QStringLiteral("bringup/config/server.yaml")));
        QVERIFY(yaml.open(QIODevice::WriteOnly));
        yaml.write("talker:\n  ros__parameters:\n    controller_plugins: [\"Follow\"]\n"
                   "    Follow:\n      plugin: \"ctrl_pkg::Follower\"\n      speed: 0.5\n"
                   "    Checker:\n      plugin: ctrl_pkg/Checker\n"
                   "    NotAClass:\n      plugin: \"just words\"\n"
                   "    checker_plugin: Checker\n"
                   "    Spare:\n      plugin: \"ctrl_pkg::Follower\"\n");
        yaml.close();
        LaunchAction a =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("talker"), 3);
        a.parameters = {
            parameterFile(share(QStringLiteral("bringup"), QStringLiteral("config/server.yaml")))};
        fx.add(QStringLiteral("bringup/launch/s.launch.py"), {a});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/s.launch.py"));
        QCOMPARE(d.nodes.size(), 1);
        QStringList plugins;
        for (const ParameterSetting &p : d.nodes[0].plugins)
            plugins << QStringLiteral("%1=%2 @%3").arg(p.name, p.value).arg(p.evidence.line);
        QCOMPARE(plugins, (QStringList{QStringLiteral("Checker=ctrl_pkg/Checker @8"),
                                       QStringLiteral("Follow=ctrl_pkg::Follower @5")}));
    }

    void parameterFileProblemsAreSaid()
    {
        Fixture fx;
        QDir(fx.dir.path()).mkpath(QStringLiteral("bringup/config"));
        QFile broken(fx.dir.filePath(QStringLiteral("bringup/config/broken.yaml")));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("talker:\n  ros__parameters:\n    rate: [1, 2\n");
        broken.close();
        QFile flat(fx.dir.filePath(QStringLiteral("bringup/config/flat.yaml")));
        QVERIFY(flat.open(QIODevice::WriteOnly));
        flat.write("rate: 3\n");
        flat.close();
        LaunchAction a =
            node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("talker"), 3);
        a.parameters = {
            parameterFile(share(QStringLiteral("bringup"), QStringLiteral("config/missing.yaml"))),
            parameterFile(share(QStringLiteral("bringup"), QStringLiteral("config/broken.yaml"))),
            parameterFile(share(QStringLiteral("bringup"), QStringLiteral("config/flat.yaml"))),
            parameterFile(share(QStringLiteral("elsewhere"), QStringLiteral("p.yaml")))};
        fx.add(QStringLiteral("bringup/launch/b.launch.py"), {a});
        const LaunchDependencies d = fx.run(QStringLiteral("bringup/launch/b.launch.py"));
        QStringList codes;
        for (const Diagnostic &diag : d.diagnostics)
            codes << diag.code + QLatin1Char(' ') + diag.evidence.file;
        QCOMPARE(codes,
                 (QStringList{QStringLiteral("no-such-parameter-file x"),
                              QStringLiteral("malformed-yaml bringup/config/broken.yaml"),
                              QStringLiteral("parameter-file-unused bringup/config/flat.yaml"),
                              QStringLiteral("no-such-parameter-file x")}));
        QVERIFY(d.diagnostics.last().message.contains(QLatin1String("elsewhere")));
        QCOMPARE(d.nodes.size(), 1);
    }

    void parameterFileNodeKeys_data()
    {
        QTest::addColumn<QString>("pattern");
        QTest::addColumn<QString>("fqn");
        QTest::addColumn<bool>("matches");
        QTest::newRow("exact") << "/ns/talker"
                               << "/ns/talker" << true;
        QTest::newRow("other namespace") << "/ns/talker"
                                         << "/talker" << false;
        QTest::newRow("everything") << "/**"
                                    << "/a/b/c" << true;
        QTest::newRow("one segment") << "/*/talker"
                                     << "/ns/talker" << true;
        QTest::newRow("one segment, not none") << "/*/talker"
                                               << "/talker" << false;
        QTest::newRow("any depth") << "/**/talker"
                                   << "/a/b/talker" << true;
        QTest::newRow("any depth, also none") << "/**/talker"
                                              << "/talker" << true;
        QTest::newRow("prefix") << "/robot/**"
                                << "/robot/x/y" << true;
        QTest::newRow("prefix, other") << "/robot/**"
                                       << "/rover/x" << false;
    }

    void parameterFileNodeKeys()
    {
        QFETCH(QString, pattern);
        QFETCH(QString, fqn);
        QFETCH(bool, matches);
        QCOMPARE(ParameterFile::matches(pattern, fqn), matches);
    }

    void aParameterFileBombIsCut()
    {
        // Aliases that double at every level stand for 2^40 nodes in a few hundred bytes.
        QByteArray yaml = "a0: &a0 [x, x]\n";
        for (int i = 1; i < 40; ++i)
            yaml += QStringLiteral("a%1: &a%1 [*a%2, *a%2]\n").arg(i).arg(i - 1).toUtf8();
        yaml += "talker:\n  ros__parameters:\n    big: *a39\n";
        const ParameterFile f = ParameterFile::read(yaml, QStringLiteral("bomb.yaml"));
        QStringList codes;
        for (const Diagnostic &d : f.diagnostics)
            codes << d.code;
        QCOMPARE(codes, QStringList{QStringLiteral("launch-evaluation-limit")});
    }
};

QTEST_GUILESS_MAIN(TestLaunchParameters)
#include "tst_launchparameters.moc"
