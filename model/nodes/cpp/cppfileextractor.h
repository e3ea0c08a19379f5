#pragma once

#include "nodes/cpp/cppfacts.h"
#include "syntax/cppmacro.h"
#include "syntax/syntaxtree.h"

namespace rosarch {

/// Phase 1 of the C++ analysis: turns one parsed file into text-only facts (classes, functions,
/// aliases, component registrations). Independent per file, so it runs in parallel.
class CppFileExtractor
{
public:
    /// `macros` are those in effect at the end of the file (CppPreprocessor): the object-like
    /// ones that stand for a string or a number become file constants, like `const` strings.
    static CppFileFacts extract(const SyntaxTree &tree, const QString &package,
                                const CppMacros &macros = {});
};

} // namespace rosarch
