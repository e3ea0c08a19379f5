#pragma once

#include "nodes/cpp/cppfacts.h"
#include "nodes/cpp/cppvalueevaluator.h"
#include "syntax/cppsyntax.h"
#include "syntax/syntaxtree.h"

#include <QHash>
#include <QStringList>

#include <vector>

namespace rosarch {

/// The port-creating calls of a function: which calls create ports, their name and type
/// arguments, callbacks and the `if` conditions around them.
class CppPortCallReader
{
public:
    /// Reads the extractor's state as it is when asked; ports go to `function`.
    CppPortCallReader(const SyntaxTree &tree, const CppValueEvaluator &values,
                      const QHash<QString, CppLocal> &locals, const QStringList &templateParameters,
                      const TSNode &definition, CppFunction &function,
                      const QHash<QString, QString> &classAliases);

    /// Adds the port `call` creates to the function; false when it creates none.
    bool read(TSNode call, const cppsyntax::CallShape &shape, const std::vector<TSNode> &args);
    bool readMessageFilter(TSNode call, const cppsyntax::CallShape &shape,
                           const std::vector<TSNode> &args);
    /// The callback among the arguments from `first` on ("" when none).
    QString callbackName(const std::vector<TSNode> &args, int first) const;
    /// The `if` condition around `call` within the function, and the value it tests.
    void guardOf(TSNode call, QString *guard, CppValue *guardValue) const;

private:
    const SyntaxTree &m_tree;
    const CppValueEvaluator &m_values;
    const QHash<QString, CppLocal> &m_locals;
    const QStringList &m_templateParameters;
    const TSNode &m_definition;
    CppFunction &m_function;
    const QHash<QString, QString> &m_classAliases; ///< of an inline member's class
};

} // namespace rosarch
