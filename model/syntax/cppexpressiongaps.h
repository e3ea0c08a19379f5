#pragma once

#include <QByteArray>

#include <string_view>

// Valid C++ inside functions and parameter lists that the grammar cannot read, rewritten for
// the parser (cppsyntax::blankGrammarGaps). Offsets are byte offsets into the source.
namespace rosarch::cppsyntax::expressions {

/// A name a macro is likely to have, also in mixed case: an underscore and a run of three
/// capitals (`PyObject_HEAD`, `KARTO_Object`, `BOOST_CLASS_EXPORT`). Type names in that style
/// are rare.
bool isMacroLikeWord(std::string_view word);

/// Rewrites, in `data` (the source `code` was made from by codeOnly, same offsets) and in `code`
/// alike:
/// - the default of an unnamed parameter, `const void * = 0`, `enable_if_t<B> * = nullptr`, is
///   blanked;
/// - a built-in type as a macro's argument, `Q_ARG(int, level)`, `va_arg(args, int)`, becomes
///   the name `_`;
/// - a `;` right before the `)` of a macro call, `LOG_STREAM(a << b;)`, is blanked;
/// - a macro standing for a keyword, `OGRE_NEW T(...)`, `OGRE_DELETE this->p;`, is blanked
///   where a value or a statement starts and a name follows;
/// - an attribute in capitals without an underscore before a declaration on its line,
///   `NOINLINE void * operator new(...)`, is blanked;
/// - a lambda capture initialised with braces, `[p{std::move(p)}]`, is written `[p=std::move(p)]`;
/// - a call standing for a loop header in a function body, `forEach(List, &items) {`, is
///   blanked (its block stays);
/// - a macro call that is an element of a braced initializer without its comma,
///   `{ PyVarObject_HEAD_INIT(nullptr, 0) "name", ...}`, is blanked.
void rewriteExpressionGaps(QByteArray *code, char *data);

} // namespace rosarch::cppsyntax::expressions
