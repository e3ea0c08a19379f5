// cppsyntax::blankGrammarGaps: valid C++ the tree-sitter grammar cannot read is rewritten in
// place, keeping every offset, line and column, and never inside strings or comments.
#include "syntax/cppsyntax.h"
#include "syntax/syntaxtree.h"

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

    // decltype(a, b) keeps its last operand; an operator function called by name gets
    // underscores for its symbol; typeid(int) loses its built-in type.
    void expressionsTheGrammarCannotRead()
    {
        const QByteArray src(
            "template <typename T> struct H<T, decltype((void)T::header, nullptr)> {};\n"
            "template <typename T> auto s(T r) -> decltype(r->success, void()) {}\n"
            "size_t operator()(T const & o) const\n"
            "  noexcept(noexcept(std::declval<H>().operator()(std::declval<T>()))) { return 0; }\n"
            "void f() {\n"
            "  const auto d = this->operator()(x, y);\n"
            "  if (c) { operator++(); }\n"
            "  bool i = a.type() == typeid(int) || a.type() == typeid(unsigned int);\n"
            "  bool s = a.type() == typeid(std::string) && sizeof(decltype(x)) > 1;\n"
            "}\n"
            "struct I { I & operator++(); bool operator==(const I & o) const; };\n");
        QVERIFY(!parsesCleanly(src));
        const QByteArray out = rewritten(src);
        QCOMPARE(
            lines(out),
            (QList<QByteArray>{
                "template <typename T> struct H<T, decltype( nullptr)> {};",
                "template <typename T> auto s(T r) -> decltype( void()) {}",
                "size_t operator()(T const & o) const",
                "noexcept(noexcept(std::declval<H>().operator__(std::declval<T>()))) { "
                "return 0; }",
                "void f() {", "const auto d = this->operator__(x, y);", "if (c) { operator__(); }",
                "bool i = a.type() == typeid( ) || a.type() == typeid( );",
                "bool s = a.type() == typeid(std::string) && sizeof(decltype(x)) > 1;", "}",
                "struct I { I & operator++(); bool operator==(const I & o) const; };"}));
        QVERIFY(parsesCleanly(out));
    }

    // Pointer-to-member types become function pointers, `->*` becomes `->`, and the `...` of
    // a using-declaration's pack expansion goes.
    void pointersToMembersAndPackExpansions()
    {
        const QByteArray src(
            "template <class S, class I>\n"
            "using Callback = void (I::*)(const typename S::Message::ConstSharedPtr);\n"
            "typedef void (ns::Node<int>::*Handler)(int);\n"
            "template <class T, class Req>\n"
            "void handle(void (T::*callback)(Req), T * instance, Req req)\n"
            "{\n"
            "  (instance->*callback)(req);\n"
            "}\n"
            "template <class... Ts> struct Visitor : Ts... { using Ts::operator()...; };\n");
        QVERIFY(!parsesCleanly(src));
        const QByteArray out = rewritten(src);
        QCOMPARE(lines(out), (QList<QByteArray>{
                                 "template <class S, class I>",
                                 "using Callback = void ( *)(const typename "
                                 "S::Message::ConstSharedPtr);",
                                 "typedef void ( *Handler)(int);", "template <class T, class Req>",
                                 "void handle(void ( *callback)(Req), T * instance, Req req)", "{",
                                 "(instance-> callback)(req);", "}",
                                 "template <class... Ts> struct Visitor : Ts... { using "
                                 "Ts::operator() ; };"}));
        QVERIFY(parsesCleanly(out));
    }

    // A reference initialised with parentheses around a member access gets braces, also after
    // a standalone macro; a declaration as the unbraced body of a loop loses its declarator.
    // Function declarations returning a reference stay.
    void declarationsTheGrammarMisreads()
    {
        const QByteArray src("const Foo & get(const Bar & b);\n"
                             "const Foo & get(double x = a.b);\n"
                             "void f() {\n"
                             "  const rclcpp::Time & newest(records.rbegin()->header.stamp);\n"
                             "  const Pose & p(msg.pose);\n"
                             "  TRACE_SCOPE(this)\n"
                             "  const Time & stamp(cloud->header.stamp);\n"
                             "  for (const auto & polygon : polygons)\n"
                             "    const auto result = checker.intersections(polygon);\n"
                             "  while (a == b) auto & x = g();\n"
                             "  if (x) y = 2;\n"
                             "}\n");
        QVERIFY(!parsesCleanly(src));
        const QByteArray out = rewritten(src);
        QCOMPARE(lines(out),
                 (QList<QByteArray>{
                     "const Foo & get(const Bar & b);", "const Foo & get(double x = a.b);",
                     "void f() {", "const rclcpp::Time & newest{records.rbegin()->header.stamp};",
                     "const Pose & p{msg.pose};", "const Time & stamp{cloud->header.stamp};",
                     "for (const auto & polygon : polygons)", "checker.intersections(polygon);",
                     "while (a == b) g();", "if (x) y = 2;", "}"}));
        QVERIFY(parsesCleanly(out));
    }

    // A macro invocation standing alone without `;` at statement or member level is blanked;
    // a function header (`TEST(a, b) {`), a statement with `;`, an expression, an enumerator
    // and the registration macros the analysis reads stay.
    void standaloneMacros()
    {
        const QByteArray src(
            "BOOST_GEOMETRY_REGISTER_POINT_3D(geometry_msgs::msg::Point, double, cs::cartesian,\n"
            "                                 x, y, z)\n"
            "POINT_CLOUD_REGISTER_POINT_STRUCT(\n"
            "  LivoxPoint, (float, x, x)(std::uint8_t, tag, tag))\n"
            "namespace ns {\n"
            "ROBIN_HOOD_HASH_INT(unsigned char);\n"
            "CHECK_FIELD(0, float, autoware::point_types::PointXYZIRCAEDT, x);\n"
            "struct Result {\n"
            "  float p;\n"
            "  EIGEN_MAKE_ALIGNED_OPERATOR_NEW\n"
            "  friend bool operator<(const Result & a, const Result & b) { return a.p < b.p; }\n"
            "};\n"
            "struct Aligned {\n"
            "  float p;\n"
            "public:\n"
            "  EIGEN_MAKE_ALIGNED_OPERATOR_NEW\n"
            "};\n"
            "class Observation {\n"
            "public:\n"
            "  RCLCPP_SMART_PTR_DEFINITIONS(Observation)\n"
            "  /* comment */\n"
            "  Observation() = default;\n"
            "  int find() const {\n"
            "    ROBIN_HOOD_TRACE(this)\n"
            "    return 1;\n"
            "  }\n"
            "};\n"
            "enum Mode { MODE_A,\n"
            "  MODE_B };\n"
            "enum Single {\n"
            "  SINGLE_MODE\n"
            "};\n"
            "void g() {\n"
            "  EXPECT_EQ(1, count(x));\n"
            "  f(x, \n"
            "    MAX_SIZE\n"
            "    );\n"
            "}\n"
            "TEST(Foo, Bar)\n"
            "{\n"
            "  RCLCPP_INFO(logger, \"x\");\n"
            "  CHECK_VALUE(x)\n"
            "    << \"message\";\n"
            "}\n"
            "}  // namespace ns\n"
            "RCLCPP_COMPONENTS_REGISTER_NODE(ns::Observation)\n"
            "BENCHMARK_MAIN()\n");
        QVERIFY(!parsesCleanly(src));
        const QByteArray out = rewritten(src);
        QCOMPARE(
            lines(out),
            (QList<QByteArray>{
                "namespace ns {",
                ";",
                ";",
                "struct Result {",
                "float p;",
                "friend bool operator<(const Result & a, const Result & b) { return a.p < b.p; }",
                "};",
                "struct Aligned {",
                "float p;",
                "public:",
                "};",
                "class Observation {",
                "public:",
                "/* comment */",
                "Observation() = default;",
                "int find() const {",
                "return 1;",
                "}",
                "};",
                "enum Mode { MODE_A,",
                "MODE_B };",
                "enum Single {",
                "SINGLE_MODE",
                "};",
                "void g() {",
                "EXPECT_EQ(1, count(x));",
                "f(x,",
                "MAX_SIZE",
                ");",
                "}",
                "TEST(Foo, Bar)",
                "{",
                "RCLCPP_INFO(logger, \"x\");",
                "CHECK_VALUE(x)",
                "<< \"message\";",
                "}",
                "} // namespace ns",
                "RCLCPP_COMPONENTS_REGISTER_NODE(ns::Observation)"}));
        QVERIFY(parsesCleanly(out.left(out.indexOf("RCLCPP_COMPONENTS"))));
    }

    // Classes of syntax errors met in rviz, slam_toolbox's Karto SDK, ros2/demos, geometry2 and
    // rosbag2, each written anew: all of it compiles, none of it names a port.
    void macrosAndExpressionsOfUnseenRepositories()
    {
        const QByteArray src(
            "#define forEach(T, l) for (T::iterator it = (l)->begin(); it != (l)->end(); ++it)\n"
            "template <typename T> struct Pool {\n"
            "  T * allocate(size_t size, const void * = 0) { return nullptr; }\n"
            "  template <class U, typename std::enable_if<std::is_same<U, T>::value>::type * =\n"
            "                       nullptr>\n"
            "  explicit Pool(U u) {}\n"
            "  void swap(Pool & other) POOL_NOEXCEPT;\n"
            "  Member Pool::*field;\n"
            "};\n"
            "NOINLINE void * operator new(std::size_t size) { return nullptr; }\n"
            "typedef struct {\n"
            "  PyObject_HEAD\n"
            "  Core * core;\n"
            "} core_t;\n"
            "static PyTypeObject core_type = {\n"
            "  PyVarObject_HEAD_INIT(nullptr, 0)\n"
            "  \"_mod.Core\",\n"
            "};\n"
            "class Writer {\n"
            "  std::atomic_bool running_\n"
            "    RCPPUTILS_TSA_GUARDED_BY(mutex_) {false};\n"
            "  KARTO_Object(Writer)\n"
            "public:\n"
            "  void f();\n"
            "};\n"
            "BOOST_CLASS_EXPORT(ns::Writer)\n"
            "BOOST_CLASS_EXPORT(ns::Reader)\n"
            "void Writer::f() {\n"
            "  switch (mode) {\n"
            "    case RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL:\n"
            "      std::cout << \"transient local\";\n"
            "      break;\n"
            "  }\n"
            "  const std::map<int, int> names{{RMW_X_LOCAL, 1}};\n"
            "  QMetaObject::invokeMethod(this, \"set\", Q_ARG(int, level), Q_ARG(QString, name));\n"
            "  int x = va_arg(args, unsigned int);\n"
            "  LOG_ERROR_STREAM(\n"
            "    a << \" is invalid.\";\n"
            "  );\n"
            "  OGRE_DELETE this->overlay_;\n"
            "  Ptr p = Ptr(OGRE_NEW Stream(&file, false));\n"
            "  queue([this, props{std::move(props)}] { use(props); });\n"
            "  forEach(Items, &items_)\n"
            "  {\n"
            "    delete *it;\n"
            "  }\n"
            "  for (;;) { if (x) { break; } }\n"
            "  CHECK(a <= b);\n"
            "  y = x * 2;\n"
            "  out.*(f.ptr) = 1.*y;\n"
            "  z = 1.0 / (double)RAND_MAX;\n"
            "}\n");
        QVERIFY(!parsesCleanly(src));
        const QByteArray out = rewritten(src);
        QCOMPARE(
            lines(out),
            (QList<QByteArray>{
                "#define forEach(T, l) for (T::iterator it = (l)->begin(); it != (l)->end(); "
                "++it)",
                "template <typename T> struct Pool {",
                "T * allocate(size_t size, const void * ) { return nullptr; }",
                "template <class U, typename std::enable_if<std::is_same<U, T>::value>::type *",
                ">",
                "explicit Pool(U u) {}",
                "void swap(Pool & other) ;",
                "Member *field;",
                "};",
                "void * operator new(std::size_t size) { return nullptr; }",
                "typedef struct {",
                "Core * core;",
                "} core_t;",
                "static PyTypeObject core_type = {",
                "\"_mod.Core\",",
                "};",
                "class Writer {",
                "std::atomic_bool running_",
                "{false};",
                "public:",
                "void f();",
                "};",
                "void Writer::f() {",
                "switch (mode) {",
                "case RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL:",
                "std::cout << \"transient local\";",
                "break;",
                "}",
                "const std::map<int, int> names{{RMW_X_LOCAL, 1}};",
                "QMetaObject::invokeMethod(this, \"set\", Q_ARG(_ , level), Q_ARG(QString, "
                "name));",
                "int x = va_arg(args, _ );",
                "LOG_ERROR_STREAM(",
                "a << \" is invalid.\"",
                ");",
                "this->overlay_;",
                "Ptr p = Ptr( Stream(&file, false));",
                "queue([this, props=std::move(props) ] { use(props); });",
                "{",
                "delete *it;",
                "}",
                "for (;;) { if (x) { break; } }",
                "CHECK(a <= b);",
                "y = x * 2;",
                "out *(f.ptr) = 1.*y;",
                "z = 1.0 / (double)RAND_MAX;",
                "}"}));
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
                             "// EIGEN_MAKE_ALIGNED_OPERATOR_NEW\n"
                             "auto g = \"x.operator()(1); typeid(int) (a->*b)\";\n"
                             "void f(int n = {}, const char *s = \"f(int n = {})\");\n");
        const QByteArray out = rewritten(src);
        QCOMPARE(out.left(out.lastIndexOf("void f")), src.left(src.lastIndexOf("void f")));
        QVERIFY(out.endsWith("void f(int n = 0 , const char *s = \"f(int n = {})\");\n"));
    }

    // Each rewrite is tried only where a word of its pattern stands; these pin what the
    // patterns matched when they were tried at every offset (spaces that are no blanks, a gate
    // on text the file lacks, `returntypename`, the start of the file).
    void rewritesAtTheirWords_data()
    {
        QTest::addColumn<QByteArray>("source");
        QTest::addColumn<QByteArray>("expected");
        QTest::newRow("new: only where the file has `new `")
            << QByteArray("void f() { auto p = new\tint *[3]; auto q = new int *[3]; }")
            << QByteArray("void f() { auto p = new\tint  [3]; auto q = new int  [3]; }");
        QTest::newRow("new: no `new ` in the file")
            << QByteArray("void f() { auto p = new\tint *[3]; }")
            << QByteArray("void f() { auto p = new\tint *[3]; }");
        QTest::newRow("typename: after return without a space")
            << QByteArray("template <typename T> T f() { returntypename T::Goal(); }")
            << QByteArray("template <typename T> T f() { return         T::Goal(); }");
        QTest::newRow("typename: after return and =")
            << QByteArray("template <typename T> T f() { return  typename T::Goal(); x = typename "
                          "T::A<int>{}; }")
            << QByteArray("template <typename T> T f() { return           T::Goal(); x =          "
                          "T::A<int>{}; }");
        QTest::newRow("typename: no `typename ` in the file")
            << QByteArray("void f() { g(a,typename\tT::B()); }")
            << QByteArray("void f() { g(a,typename\tT::B()); }");
        QTest::newRow("template after -> and .")
            << QByteArray("void f() { bb->template set(\"a\", 1); cc .  template get (); "
                          "dd.template get<int>(); }")
            << QByteArray("void f() { bb->         set(\"a\", 1); cc .           get (); "
                          "dd.template get<int>(); }");
        QTest::newRow("reference initialisers, at the start too")
            << QByteArray(
                   "const T & x(a.b);\nvoid f() { const Foo<int>&y(p->q); if (a && b(c)) {} }")
            << QByteArray(
                   "const T & x{a.b};\nvoid f() { const Foo<int>&y{p->q}; if (a && b(c)) {} }");
        QTest::newRow("unbraced declaration bodies")
            << QByteArray("void f() { for (int i = 0; i < n; ++i) const auto r = g(i); while(x) "
                          "constexpr int k = h(); if (y) auto z = 1; }")
            << QByteArray("void f() { for (int i = 0; i < n; ++i)                g(i); while(x)    "
                          "               h(); if (y)          1; }");
        QTest::newRow("a head after a vertical tab")
            << QByteArray("void f() { if\v(a) auto b = c; iffy(x); }")
            << QByteArray("void f() { if\v(a)          c; iffy(x); }");
        QTest::newRow("operator calls")
            << QByteArray("void f() { x.operator()(a); operator++(); this->operator [](1); }")
            << QByteArray("void f() { x.operator__(a); operator__(); this->operator___(1); }");
        QTest::newRow("using pack expansion")
            << QByteArray("struct S : Ts... { using Ts::operator()...; };")
            << QByteArray("struct S : Ts... { using Ts::operator()   ; };");
        QTest::newRow("typeid of built-in types")
            << QByteArray("void f() { auto t = typeid(int); auto u = typeid ( const char * ); }")
            << QByteArray("void f() { auto t = typeid(   ); auto u = typeid (              ); }");
        QTest::newRow("macro arguments")
            << QByteArray("void f() { EXPECT_THROW(Foo f(x), E); connect(a, SIGNAL(b(int)), c, "
                          "SLOT(d())); }")
            << QByteArray("void f() { EXPECT_THROW(           ); connect(a, SIGNAL(      ), c, "
                          "SLOT(   )); }");
        QTest::newRow("decltype commas")
            << QByteArray(
                   "void f() { decltype(a, b) x; using T = decltype((void)T::header, nullptr); }")
            << QByteArray(
                   "void f() { decltype(   b) x; using T = decltype(                 nullptr); }");
        QTest::newRow("pointers to members")
            << QByteArray("void f() { void (C::*pm)(int) = &C::g; (obj->*pm)(1); }")
            << QByteArray("void f() { void (   *pm)(int) = &C::g; (obj-> pm)(1); }");
    }
    void macrosTheGrammarCannotReadWhereTheyStand_data()
    {
        // Each class of syntax error seen in moveit2, rviz, ros2_controllers,
        // geometry2 and rosbag2, in our own words. Each fails to parse as written.
        QTest::addColumn<QByteArray>("source");
        QTest::addColumn<QByteArray>("expected");
        QTest::newRow("constants joined to string literals")
            << QByteArray("void f() { g(\"/ns/\" TOPIC_NAME \"/x\"); h(\"a\" SUFFIX_TEXT); }")
            << QByteArray("void f() { g(\"/ns/\"+TOPIC_NAME+\"/x\"); h(\"a\"+SUFFIX_TEXT); }");
        QTest::newRow("a unit after a number")
            << QByteArray("const double kTolerance = 0.01f METERS, kStep = 2 UNIT_MM;")
            << QByteArray("const double kTolerance = 0.01f       , kStep = 2        ;");
        QTest::newRow("test macros in a class")
            << QByteArray("class T {\n  FRIEND_TEST(Suite, 3_wheels);\n  MOCK_METHOD(int, f, (), "
                          "(const, override));\n};")
            << QByteArray("class T {\n                              ;\n                          "
                          "                  ;\n};");
        QTest::newRow("type caster macro in a struct")
            << QByteArray("namespace n {\nstruct caster {\n  TYPE_CASTER_OF(a::Time, _(\"x\"));"
                          "\n};\n}")
            << QByteArray("namespace n {\nstruct caster {\n                                 ;"
                          "\n};\n}");
        QTest::newRow("thread-safety annotations")
            << QByteArray("class C {\n  int x_ TSA_GUARDED_BY(m_);\n  bool b_ TSA_GUARDED_BY(\n"
                          "    m_) = false;\n  void f(int a) const TSA_REQUIRES(m_);\n  "
                          "std::map<int, int> t_ TSA_GUARDED_BY(m_);\n};")
            << QByteArray("class C {\n  int x_                   ;\n  bool b_                \n"
                          "        = false;\n  void f(int a) const                 ;\n  "
                          "std::map<int, int> t_                   ;\n};");
        QTest::newRow("attribute macros before declarations")
            << QByteArray("template <class T>\nSIMD_FORCE_INLINE const T & lesser(const T & a) "
                          "{ return a; }\nclass V {\n  explicit SIMD_FORCE_INLINE V(int a) {}\n"
                          "  SIMD_FORCE_INLINE V (const V & o) : a_(o.a_) {}\n"
                          "};\nALIGNED_16(class) Q\n{\n};")
            << QByteArray("template <class T>\n                  const T & lesser(const T & a) "
                          "{ return a; }\nclass V {\n  explicit                   V(int a) {}\n"
                          "                    V (const V & o) : a_(o.a_) {}\n"
                          "};\n           class  Q\n{\n};");
    }
    void macrosTheGrammarCannotReadWhereTheyStand()
    {
        QFETCH(QByteArray, source);
        QFETCH(QByteArray, expected);
        QVERIFY(!parsesCleanly(source));
        const QByteArray out = rewritten(source);
        QCOMPARE(out, expected);
        QVERIFY2(parsesCleanly(out), out.constData());
    }
    void aMacroWithNothingBeforeIt()
    {
        // Found by fuzz_nodeanalyzers: a macro word at offset 1, with no code before it, was
        // read as following a string literal at offset -1.
        QCOMPARE(rewritten(" FIRST_WORD(x);"), QByteArray("              ;"));
        QCOMPARE(rewritten(" SUFFIX_TEXT \"a\";"), QByteArray(" SUFFIX_TEXT+\"a\";"));
        // Also found by it: a standalone macro first in the file, before a `}`.
        QCOMPARE(rewritten("SOME_MACRO\n}"), QByteArray("          \n}"));
    }

    void macrosThatAreCodeStay()
    {
        // A constant initialised in capitals, a call guarded by an if, a registration macro,
        // a macro in a function body: as written.
        for (const QByteArray &source :
             {QByteArray("static const std::string DEFAULT_TOPIC(\"scan\");"),
              QByteArray("int DEFAULT_SIZE(3);"),
              QByteArray(
                  "void f() { if (x) LOG_ERROR(\"a\"); MY_MACRO(1, 2); return CALL_IT(y); }"),
              QByteArray("RCLCPP_COMPONENTS_REGISTER_NODE(pkg::Node)\n"),
              QByteArray("void f() { auto v = MAKE_VALUE(3); }"),
              QByteArray("LOAD_STATUS loadMap(const std::string & file);"),
              QByteArray("inline Consumer LOG_VERBOSE(const Logger & l)\n{\n  return {};\n}")})
            QCOMPARE(rewritten(source), source);
    }

    void rewritesAtTheirWords()
    {
        QFETCH(QByteArray, source);
        QFETCH(QByteArray, expected);
        QCOMPARE(rewritten(source), expected);
    }
};

QTEST_GUILESS_MAIN(TestGrammarGaps)
#include "tst_grammargaps.moc"
