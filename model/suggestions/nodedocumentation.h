#pragma once

#include "core/atomicnode.h"
#include "suggestions/suggestionsource.h"

#include <QString>

#include <optional>

namespace rosarch {

/// A node class's own documentation: a Python docstring, else the comment block right above
/// the class (or a procedural node's module docstring), its first paragraph as one line with
/// Doxygen's bookkeeping (`@class`, `@file`, banners) left out.
struct NodeDocumentation
{
    QString text;  ///< the description
    QString quote; ///< the first line of the documentation, as written
    int first = 0; ///< the lines it occupies (1-based)
    int last = 0;

    /// `node`'s documentation in the files `source` reads; none when it has none (or only a
    /// licence header).
    static std::optional<NodeDocumentation> read(const SuggestionSource &source,
                                                 const AtomicNode &node);
};

} // namespace rosarch
