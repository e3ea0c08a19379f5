#pragma once

#include "cppfacts.h"
#include "syntaxtree.h"

namespace rosarch {

/// Phase 1 of the C++ analysis: turns one parsed file into text-only facts (classes, functions,
/// aliases, component registrations). Independent per file, so it runs in parallel.
class CppFileExtractor
{
public:
    static CppFileFacts extract(const SyntaxTree &tree, const QString &package);
};

} // namespace rosarch
