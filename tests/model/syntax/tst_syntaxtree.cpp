// ts::type and ts::field answer from per-grammar tables instead of asking tree-sitter to look
// the name up each time; on every node of a C++ and a Python file, with errors and aliases,
// they must give what tree-sitter's own lookups give, and so must ts::TypeSet and the lookups by
// field id.
#include "syntax/syntaxtree.h"

#include <QtTest>

#include <algorithm>
#include <cstring>

using namespace rosarch;

namespace {

// Compares both lookups on every node; returns how many nodes were checked.
int compareEverywhere(const SyntaxTree &tree, SyntaxTree::Grammar grammar)
{
    const TSLanguage *language = ts_tree_language(tree.root().tree);
    const uint32_t fields = ts_language_field_count(language);
    // Named and anonymous types of both grammars, an alias, the error symbol and a repeat.
    const std::vector<std::string_view> names = {
        "identifier", "field_identifier", "ERROR",       "call_expression",     "call",
        "(",          "string",           "declaration", "function_definition", "no_such_type",
        "identifier"};
    const ts::TypeSet set(grammar, {names[0], names[1], names[2], names[3], names[4], names[5],
                                    names[6], names[7], names[8], names[9], names[10]});
    int checked = 0;
    bool same = true;
    ts::walk(tree.root(), [&](TSNode n) {
        ++checked;
        if (ts::type(n) != std::string_view(ts_node_type(n))) {
            qWarning("type of node %d: %s, tree-sitter says %s", checked,
                     std::string(ts::type(n)).c_str(), ts_node_type(n));
            same = false;
        }
        const auto at = std::find(names.begin(), names.end(), std::string_view(ts_node_type(n)));
        if (set.index(n) != (at == names.end() ? -1 : int(at - names.begin()))) {
            qWarning("type set index of a %s: %d", ts_node_type(n), set.index(n));
            same = false;
        }
        for (TSFieldId id = 1; id <= fields; ++id) {
            const char *name = ts_language_field_name_for_id(language, id);
            const TSNode expected =
                ts_node_child_by_field_name(n, name, uint32_t(std::strlen(name)));
            const TSNode got = ts::field(n, name);
            const TSNode byId = ts::field(n, ts::fieldId(grammar, name));
            if (ts_node_is_null(expected) != ts_node_is_null(got) ||
                (!ts_node_is_null(got) && !ts_node_eq(expected, got)) ||
                ts_node_is_null(byId) != ts_node_is_null(got) ||
                (!ts_node_is_null(got) && !ts_node_eq(byId, got))) {
                qWarning("field %s of a %s differs", name, ts_node_type(n));
                same = false;
            }
            const std::vector<TSNode> all = ts::fieldChildren(n, name);
            const std::vector<TSNode> allById = ts::fieldChildren(n, ts::fieldId(grammar, name));
            if (all.size() != allById.size() ||
                !std::equal(all.begin(), all.end(), allById.begin(), ts_node_eq)) {
                qWarning("children of field %s of a %s differ", name, ts_node_type(n));
                same = false;
            }
        }
        return true;
    });
    return same ? checked : -1;
}

} // namespace

class TestSyntaxTree : public QObject
{
    Q_OBJECT

private slots:
    void cppLookupsMatchTreeSitter()
    {
        // An alias (a field_identifier is an aliased identifier), a template, a lambda, and a
        // syntax error, so that ERROR and MISSING nodes are among those compared.
        const QByteArray source = "namespace ns {\n"
                                  "template <typename T> class Talker : public rclcpp::Node {\n"
                                  "  int count_ = 0;\n"
                                  "  void f(const std::string & topic = \"chatter\") {\n"
                                  "    auto pub = create_publisher<T>(topic, 10);\n"
                                  "    auto cb = [this](int x) { return x + count_; };\n"
                                  "    for (int i = 0; i < 3; ++i) { pub->publish(i) }\n"
                                  "    int broken = (1 + ;\n"
                                  "  }\n"
                                  "};\n"
                                  "}\n";
        const SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Cpp, source, {});
        QVERIFY(ts_node_has_error(tree.root()));
        QVERIFY(ts::field(tree.root(), "no_such_field").id == nullptr);
        QVERIFY(ts::type(TSNode{}).empty());
        QCOMPARE(ts::TypeSet(SyntaxTree::Grammar::Cpp, {"identifier"}).index(TSNode{}), -1);
        QCOMPARE(ts::fieldId(SyntaxTree::Grammar::Cpp, "no_such_field"), TSFieldId(0));
        const int checked = compareEverywhere(tree, SyntaxTree::Grammar::Cpp);
        QVERIFY2(checked > 100, qPrintable(QString::number(checked)));
    }

    void pythonLookupsMatchTreeSitter()
    {
        const QByteArray source =
            "import rclpy\n"
            "class Talker(Node):\n"
            "    def __init__(self, name='talker'):\n"
            "        super().__init__(name)\n"
            "        self.pub = self.create_publisher(String, f'{name}/x', 10)\n"
            "    def broken(self:\n"
            "        return [x for x in range(3) if x]\n";
        const SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Python, source, {});
        QVERIFY(ts_node_has_error(tree.root()));
        const int checked = compareEverywhere(tree, SyntaxTree::Grammar::Python);
        QVERIFY2(checked > 60, qPrintable(QString::number(checked)));
    }
};

QTEST_GUILESS_MAIN(TestSyntaxTree)
#include "tst_syntaxtree.moc"
