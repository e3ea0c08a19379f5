#pragma once

#include "syntax/syntaxtree.h"

#include <QString>
#include <QStringList>

namespace rosarch::cppsyntax {

// Small helpers over the tree-sitter C++ grammar and over C++ names as text.

/// The C++ grammar's field ids, looked up once: ts::field(n, fields().name) in the code that
/// runs on every node of a function body.
struct Fields
{
    TSFieldId alternative, argument, arguments, body, condition, consequence, declarator,
        defaultValue, field, function, left, name, op, parameters, right, scope, type, value;
};
const Fields &fields();

/// The shape of a call's function: `scope::name<templateArguments>` or `receiver->name<...>`.
struct CallShape
{
    QString name;  ///< last identifier: "create_publisher", "make_shared", "bind"
    QString scope; ///< qualifier before the name: "rclcpp_action", "std", "rclcpp::Node"
    TSNode templateArguments{}; ///< template_argument_list, null when none
    TSNode receiver{};          ///< field_expression object, null when none
    bool arrow = false;         ///< receiver->name (else receiver.name)
};

/// Decomposes the `function` child of a call_expression.
CallShape callShape(const SyntaxTree &tree, TSNode function);

/// The first template argument's text (simplified), "" when none.
QString firstTemplateArgument(const SyntaxTree &tree, TSNode templateArguments);

/// Named arguments of an argument_list / initializer_list (comments skipped).
std::vector<TSNode> arguments(TSNode list);

/// The content of a string literal or of adjacent literals ("a" "b"); false when `n` is none.
bool stringLiteral(const SyntaxTree &tree, TSNode n, QString *content);

/// Strips parentheses, casts, std::move, std::string(...), rclcpp::ParameterValue(...).
TSNode unwrap(const SyntaxTree &tree, TSNode n);

/// The identifier a declarator declares (through references, pointers, arrays, initializers).
TSNode declaredName(TSNode declarator);

/// Source text with runs of whitespace collapsed to one space.
QString simplified(const SyntaxTree &tree, TSNode n);

/// Splits "a::b<c::d>::E" into {"a", "b<c::d>", "E"}; a leading "::" is dropped.
QStringList splitScope(const QString &qualified);
/// "ns::Foo<int>" -> "ns::Foo".
QString withoutTemplateArguments(const QString &name);
/// "ns::Helper<a::B, C<int>>" -> {"a::B", "C<int>"}.
QStringList templateArgumentsOf(const QString &type);
/// "ns::Foo<int>" -> "Foo".
QString lastSegment(const QString &qualified);

/// "std_msgs::msg::String", "std_msgs::msg::String::SharedPtr" -> "std_msgs/msg/String";
/// anything that is not an interface type is returned simplified as written.
QString canonicalInterfaceType(const QString &written);

/// Overwrites symbol-visibility macros (FOO_PUBLIC, FOO_EXPORT, ..., PCL_EXPORTS) and CUDA's
/// `__device__` / `__host__` / `__global__` outside preprocessor lines with spaces: the parser
/// cannot expand them and they derail whole class bodies. Offsets, lines and columns stay the
/// same.
void blankExportMacros(QByteArray *source);

/// Overwrites the Qt moc keywords the parser cannot read, keeping offsets, lines and columns:
/// a `Q_OBJECT` / `Q_GADGET` line is blanked, `public slots:` / `public Q_SLOTS:` loses its
/// `slots`, and `signals:` / `Q_SIGNALS:` becomes `public:` (what moc's headers define them as).
void blankQtKeywords(QByteArray *source);

/// Overwrites, keeping offsets, lines and columns, what valid C++ the grammar cannot read:
/// the `*` of `new T *[n]` and the `()` of `new T[n]()`, `typename` before a dependent type
/// constructed in an expression (`x = typename T::Goal();`), `template` after `->` / `.`
/// without template arguments (`bb->template set(...)`), a braced default argument (`= {}`,
/// `= {1.0, 2.0}`), which becomes `0`, explicit instantiations (`template class X<int>;`),
/// the arguments of gtest's EXPECT_THROW(declaration, e) family and of Qt's SIGNAL() / SLOT(),
/// all but the last operand of `decltype(a, b)`, the symbol of an operator function called by
/// name (`x.operator()(a)` becomes `x.operator__(a)`), the class of a pointer-to-member type
/// (`void (C::*)(int)`) and the `*` of `->*`, the `...` of `using Ts::operator()...;`, a
/// built-in type in `typeid(int)`, the parentheses of a reference initialised with a member
/// (`const T & x(a.b);` becomes `{a.b}`), the declarator of a declaration that is the unbraced
/// body of `for` / `while` / `if`, and a macro invocation standing alone without `;`
/// (`EIGEN_MAKE_ALIGNED_OPERATOR_NEW`, `ROBIN_HOOD_TRACE(this)`). Strings, comments and
/// preprocessor lines stay as written. None of it names a port.
void blankGrammarGaps(QByteArray *source);

/// True for header extensions (.h .hh .hpp .hxx .inl).
bool isHeaderPath(const QString &path);

} // namespace rosarch::cppsyntax
