// The $(...) substitution parser shared by the XML and YAML launch readers.
#include "launch/substitutionevaluator.h"
#include "launch/xmlyaml/frontendsubstitution.h"
#include "support/launchsupport.h"
#include "support/testsupport.h"

#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::launch;
using SKind = Substitution::Kind;

namespace {

Substitution text(const QString &t)
{
    return Substitution::literal(t);
}

} // namespace

class TestLaunchSubstitutions : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void substitutionDescribe_data();
    void substitutionDescribe();
    void substitutionStructure();
    void substitutionErrors_data();
    void substitutionErrors();
    void launchFunctions_data();
    void launchFunctions();
};

void TestLaunchSubstitutions::substitutionDescribe_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("described");

    auto row = [](const char *name, const QString &in, SKind k, const QString &out) {
        QTest::newRow(name) << in << int(k) << out;
    };
    row("empty", "", SKind::Text, "");
    row("text", "plain text", SKind::Text, "plain text");
    row("dollar without paren", "costs $5 (approx)", SKind::Text, "costs $5 (approx)");
    row("var", "$(var robot)", SKind::LaunchConfiguration, "$(var robot)");
    row("var with slash", "$(var output/objects)", SKind::LaunchConfiguration,
        "$(var output/objects)");
    row("env", "$(env HOME)", SKind::EnvironmentVariable, "$(env HOME)");
    row("optenv", "$(optenv ROBOT_ID 0)", SKind::EnvironmentVariable, "$(env ROBOT_ID)");
    row("find-pkg-share", "$(find-pkg-share nav)", SKind::FindPackageShare,
        "$(find-pkg-share nav)");
    row("find-pkg-prefix", "$(find-pkg-prefix nav)", SKind::FindPackagePrefix,
        "$(find-pkg-prefix nav)");
    row("dirname", "$(dirname)", SKind::ThisLaunchFileDir, "$(dirname)");
    row("filename", "$(filename)", SKind::ThisLaunchFile, "$(filename)");
    row("concat", "$(find-pkg-share nav)/launch/$(var robot).launch.xml", SKind::Concat,
        "$(find-pkg-share nav)/launch/$(var robot).launch.xml");
    row("nested", "$(find-pkg-share $(var pkg)_description)", SKind::FindPackageShare,
        "$(find-pkg-share $(var pkg)_description)");
    row("eval double quoted", "$(eval \"'$(var mode)' == 'fast'\")", SKind::Eval,
        "$(eval '$(var mode)' == 'fast')");
    row("eval single quoted", "$(eval '\"$(var cfg)\" != \"\"')", SKind::Eval,
        "$(eval \"$(var cfg)\" != \"\")");
    row("eval unquoted words", "$(eval 1 + $(var n))", SKind::Eval, "$(eval 1 + $(var n))");
    row("anon", "$(anon talker)", SKind::Unknown, "$(anon talker)");
    row("command", "$(command 'xacro $(var model)' warn)", SKind::Unknown,
        "$(command 'xacro $(var model)' warn)");
    row("escaped dollar", "\\$(var x)", SKind::Text, "$(var x)");
    row("escaped backslash", "a\\\\b", SKind::Text, "a\\b");
    row("extra spaces", "$(var  robot )", SKind::LaunchConfiguration, "$(var robot)");
    row("parens inside quotes", "$(eval 'max(1, $(var n))')", SKind::Eval,
        "$(eval max(1, $(var n)))");
}

void TestLaunchSubstitutions::substitutionDescribe()
{
    QFETCH(QString, input);
    QFETCH(int, kind);
    QFETCH(QString, described);
    QString error;
    const Substitution s = FrontendSubstitution::parse(input, &error);
    QCOMPARE(error, QString());
    QCOMPARE(int(s.kind), kind);
    QCOMPARE(s.describe(), described);
}

void TestLaunchSubstitutions::substitutionStructure()
{
    // Defaults live in parts[0].
    Substitution s = FrontendSubstitution::parse(QStringLiteral("$(var ns /robot)"));
    QCOMPARE(s.text, QStringLiteral("ns"));
    QCOMPARE(s.parts, QList<Substitution>{text("/robot")});
    s = FrontendSubstitution::parse(QStringLiteral("$(env ROBOT $(var fallback))"));
    QCOMPARE(s.kind, SKind::EnvironmentVariable);
    QCOMPARE(s.text, QStringLiteral("ROBOT"));
    QCOMPARE(s.parts, QList<Substitution>{var("fallback")});
    s = FrontendSubstitution::parse(QStringLiteral("$(env ROBOT)"));
    QVERIFY(s.parts.isEmpty());
    s = FrontendSubstitution::parse(QStringLiteral("$(optenv ROBOT)"));
    QCOMPARE(s.parts, QList<Substitution>{text(QString())});

    // An eval keeps the pieces of its expression, with the nested substitutions parsed.
    s = FrontendSubstitution::parse(QStringLiteral("$(eval \"'$(var a)' == 'true'\")"));
    QCOMPARE(s.kind, SKind::Eval);
    QCOMPARE(s.parts, (QList<Substitution>{text("'"), var("a"), text("' == 'true'")}));

    // Nested package name; concatenation merges adjacent text.
    s = FrontendSubstitution::parse(QStringLiteral("$(find-pkg-share $(var p))/x/$(var f)"));
    QCOMPARE(s.kind, SKind::Concat);
    QCOMPARE(s.parts.size(), 3);
    QCOMPARE(s.parts[0].kind, SKind::FindPackageShare);
    QCOMPARE(s.parts[0].parts, QList<Substitution>{var("p")});
    QCOMPARE(s.parts[1], text("/x/"));
    QCOMPARE(s.parts[2], var("f"));

    // Launch functions keep their name and their parsed arguments.
    s = FrontendSubstitution::parse(QStringLiteral("$(if $(var fast) mt st)"));
    QCOMPARE(s.kind, SKind::Function);
    QCOMPARE(s.text, QStringLiteral("if"));
    QCOMPARE(s.parts, (QList<Substitution>{var("fast"), text("mt"), text("st")}));
    QCOMPARE(s.describe(), QStringLiteral("$(if $(var fast) mt st)"));
    // Unknown substitutions keep the expression as written, and their parsed arguments.
    s = FrontendSubstitution::parse(QStringLiteral("$(command ls $(var dir))"));
    QCOMPARE(s.kind, SKind::Unknown);
    QCOMPARE(s.text, QStringLiteral("$(command ls $(var dir))"));
    QCOMPARE(s.parts, (QList<Substitution>{text("ls"), var("dir")}));
    s = FrontendSubstitution::parse(QStringLiteral("a$(anon n)b"));
    QCOMPARE(s.kind, SKind::Concat);
    QCOMPARE(s.parts.size(), 3);
    QCOMPARE(s.parts[1].kind, SKind::Unknown);
    QCOMPARE(s.parts[1].text, QStringLiteral("$(anon n)"));
    QCOMPARE(s.parts[1].parts, QList<Substitution>{text("n")});
}

void TestLaunchSubstitutions::substitutionErrors_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("message");
    QTest::newRow("unclosed") << "$(var x"
                              << "'$(var' is not closed at column 1";
    QTest::newRow("unclosed nested") << "a $(find-pkg-share $(var p)"
                                     << "not closed at column 3";
    QTest::newRow("no name") << "$()"
                             << "name is expected";
    QTest::newRow("unterminated quote") << "$(eval 'x == 1)"
                                        << "unterminated quote";
    QTest::newRow("junk after name") << "$(var:x)"
                                     << "not closed";
    QString deep;
    for (int i = 0; i < 500; ++i)
        deep += QStringLiteral("$(var ");
    QTest::newRow("too deep") << deep << "nested too deeply";
}

void TestLaunchSubstitutions::substitutionErrors()
{
    QFETCH(QString, input);
    QFETCH(QString, message);
    QString error;
    const Substitution s = FrontendSubstitution::parse(input, &error);
    QVERIFY2(error.contains(message), qPrintable(error));
    QCOMPARE(s.kind, SKind::Unknown);
    QCOMPARE(s.text, input);
}

void TestLaunchSubstitutions::launchFunctions_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("value");
    QTest::addColumn<bool>("resolved");
    // mode = "navigation", sim = "True", rate = "10", nothing = unset
    QTest::newRow("equals text") << "$(equals $(var mode) navigation)"
                                 << "true" << true;
    QTest::newRow("equals quoted") << "$(equals $(var mode) 'mapping')"
                                   << "false" << true;
    QTest::newRow("not-equals") << "$(not-equals $(var mode) mapping)"
                                << "true" << true;
    // launch compares two booleans as booleans and two numbers as numbers
    QTest::newRow("equals bools") << "$(equals $(var sim) true)"
                                  << "true" << true;
    QTest::newRow("equals 1 and true") << "$(equals 1 true)"
                                       << "true" << true;
    QTest::newRow("equals numbers") << "$(equals $(var rate) 10.0)"
                                    << "true" << true;
    QTest::newRow("and") << "$(and $(var sim) false)"
                         << "false" << true;
    QTest::newRow("or") << "$(or $(var sim) false)"
                        << "true" << true;
    QTest::newRow("not") << "$(not $(var sim))"
                         << "false" << true;
    QTest::newRow("nested") << "$(and $(equals $(var mode) navigation) $(not false))"
                            << "true" << true;
    QTest::newRow("all") << "$(all true 1 $(var sim))"
                         << "true" << true;
    QTest::newRow("any") << "$(any false 0)"
                         << "false" << true;
    QTest::newRow("if then") << "$(if $(var sim) sim_ real_)x"
                             << "sim_x" << true;
    QTest::newRow("if else") << "$(if false a b)"
                             << "b" << true;
    QTest::newRow("if without else") << "$(if 0 a)"
                                     << "" << true;
    // what launch would refuse, or a guess inside, is not decided
    QTest::newRow("and of a word") << "$(and $(var mode) true)"
                                   << "$(and $(var mode) true)" << false;
    QTest::newRow("unset inside") << "$(equals $(var nothing) x)"
                                  << "false" << false;
}

void TestLaunchSubstitutions::launchFunctions()
{
    QFETCH(QString, input);
    QFETCH(QString, value);
    QFETCH(bool, resolved);
    QString error;
    const Substitution s = FrontendSubstitution::parse(input, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const QMap<QString, QString> configurations{
        {QStringLiteral("mode"), QStringLiteral("navigation")},
        {QStringLiteral("sim"), QStringLiteral("True")},
        {QStringLiteral("rate"), QStringLiteral("10")}};
    const SubstitutionEvaluator::Result r =
        SubstitutionEvaluator(configurations, QString()).evaluate(s);
    QCOMPARE(r.value, value);
    QCOMPARE(r.isResolved(), resolved);
}

QTEST_GUILESS_MAIN(TestLaunchSubstitutions)
#include "tst_launchsubstitutions.moc"
