// cppsyntax::blankGrammarGaps: valid C++ the tree-sitter grammar cannot read is rewritten in
// place, keeping every offset, line and column, and never inside strings or comments.
#include "cppsyntax.h"
#include "syntaxtree.h"

#include <QtTest>

using namespace rosarch;

namespace {

QByteArray rewritten(const QByteArray &source)
{
    QByteArray out = source;
    cppsyntax::blankGrammarGaps(&out);
    [&] {
        QCOMPARE(out.size(), source.size());
        for (qsizetype i = 0; i < source.size(); ++i)
            if (source.at(i) == '\n' || out.at(i) == '\n')
                QCOMPARE(out.at(i), source.at(i));
    }();
    return out;
}

// The lines of `source`, whitespace simplified (columns are checked by rewritten()).
QList<QByteArray> lines(const QByteArray &source)
{
    QList<QByteArray> out;
    for (const QByteArray &line : source.split('\n'))
        if (!line.trimmed().isEmpty())
            out << line.simplified();
    return out;
}

bool parsesCleanly(const QByteArray &source)
{
    const SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Cpp, source, QString());
    return !ts_node_has_error(tree.root());
}

} // namespace

class TestGrammarGaps : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void explicitInstantiations()
    {
        const QByteArray src("namespace ns {\n"
                             "template <typename T> class Checker { T t; };\n"
                             "template class Checker<std::shared_ptr<Costmap2D>>;\n"
                             "template class ns::Checker<Costmap2D *>;\n"
                             "}  // namespace ns\n"
                             "extern template std::unordered_set<std::string> remove<Data>(\n"
                             "  std::map<int, Data> &, const double);\n"
                             "template struct Pair<int, char>;\n"
                             "void f() { bb->template set(\"a\", 1); }\n");
        QVERIFY(!parsesCleanly(src));
        const QByteArray out = rewritten(src);
        QCOMPARE(lines(out), (QList<QByteArray>{
                                 "namespace ns {", "template <typename T> class Checker { T t; };",
                                 "} // namespace ns", "void f() { bb-> set(\"a\", 1); }"}));
        QVERIFY(parsesCleanly(out));
    }

    // A braced default argument becomes `0`; braces elsewhere stay.
    void bracedDefaultArguments()
    {
        const QByteArray src(
            "struct C { C(const std::vector<float> & mean = {123.675, 116.28, 103.53},\n"
            "           const std::pair<double, double> s = {0.0, std::max<double>(1, 2)}); };\n"
            "void f(const std::map<char, T> & codes = {{'.', 0}, {'x', 255}},\n"
            "       std::vector<int> v = {\n"
            "         1, 2});\n"
            "void g() { std::vector<int> w = {1, 2}; if (a == b) {} h(x, {1, 2}); }\n");
        QVERIFY(!parsesCleanly(src));
        const QByteArray out = rewritten(src);
        QCOMPARE(lines(out),
                 (QList<QByteArray>{
                     "struct C { C(const std::vector<float> & mean = 0 ,",
                     "const std::pair<double, double> s = 0 ); };",
                     "void f(const std::map<char, T> & codes = 0 ,", "std::vector<int> v = 0", ");",
                     "void g() { std::vector<int> w = {1, 2}; if (a == b) {} h(x, {1, 2}); }"}));
        QVERIFY(parsesCleanly(out));
    }

    // gtest's EXPECT_THROW(statement, exception) with a declaration or block, and Qt's
    // SIGNAL(signature) / SLOT(signature), keep the call with blank parentheses; an
    // expression statement stays.
    void macroArguments()
    {
        const QByteArray src(
            "void f() {\n"
            "  EXPECT_THROW(GraphLoader loader(node, tf, frame), pluginlib::PluginlibException);\n"
            "  EXPECT_THROW(\n"
            "    auto tree = factory_->createTreeFromText(xml, bb),\n"
            "    BT::RuntimeError);\n"
            "  ASSERT_NO_THROW({ a(); b(); });\n"
            "  EXPECT_THROW(node->create_publisher<Msg>(\"chatter\", 10), std::exception);\n"
            "  connect(combo, SIGNAL(currentIndexChanged(int)), this, SLOT(onRate(int, "
            "QString)));\n"
            "  log(\"SIGNAL(x(int))\");\n"
            "}\n");
        QVERIFY(!parsesCleanly(src));
        const QByteArray out = rewritten(src);
        QCOMPARE(
            lines(out),
            (QList<QByteArray>{
                "void f() {", "EXPECT_THROW( );", "EXPECT_THROW(", ");", "ASSERT_NO_THROW( );",
                "EXPECT_THROW(node->create_publisher<Msg>(\"chatter\", 10), std::exception);",
                "connect(combo, SIGNAL( ), this, SLOT( ));", "log(\"SIGNAL(x(int))\");", "}"}));
        QVERIFY(parsesCleanly(out));
    }

    // Patterns in string literals, raw strings, character literals, comments and preprocessor
    // lines stay as written.
    void stringsAndCommentsStay()
    {
        const QByteArray src("const char *a = \"; template class X<int>;\";\n"
                             "// ; template class X<int>;\n"
                             "/* ; template class X<int>; x = new double *[n]; */\n"
                             "const char *b = R\"x(\"; template class X<int>; )\" )x\";\n"
                             "#define INSTANTIATE ; template class X<int>;\n"
                             "char c = '\"'; int d = 1'000; auto e = \"typename T::Goal()\";\n"
                             "void f(int n = {}, const char *s = \"f(int n = {})\");\n");
        const QByteArray out = rewritten(src);
        QCOMPARE(out.left(out.lastIndexOf("void f")), src.left(src.lastIndexOf("void f")));
        QVERIFY(out.endsWith("void f(int n = 0 , const char *s = \"f(int n = {})\");\n"));
    }
};

QTEST_GUILESS_MAIN(TestGrammarGaps)
#include "tst_grammargaps.moc"
