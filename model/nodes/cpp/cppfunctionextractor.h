#pragma once

#include "nodes/cpp/cppfacts.h"
#include "nodes/cpp/cppportcallreader.h"
#include "nodes/cpp/cppvalueevaluator.h"
#include "syntax/cppsyntax.h"
#include "syntax/syntaxtree.h"

#include <QHash>

namespace rosarch {

/// Extracts the facts of one C++ function definition: its ports, parameter declarations,
/// member assignments, instantiations and procedurally created nodes. Locals are resolved on
/// the spot (in document order); members and parameter defaults are left for the linker.
/// What an expression refers to is CppValueEvaluator's job, which calls create ports
/// CppPortCallReader's.
class CppFunctionExtractor
{
public:
    struct Context
    {
        int ownerClass = -1;            ///< inline member: index of the class in the file
        QString className;              ///< inline member: the class's unqualified name
        QStringList namespaces;         ///< enclosing namespaces
        QStringList templateParameters; ///< of enclosing class templates
        /// inline member: the class's `using X = ...;` declared before it
        QHash<QString, QString> classAliases;
        bool rclcppNodeInScope = false; ///< `using rclcpp::Node` / `using namespace rclcpp`
        bool lifecycleNodeInScope = false;
        const CppMacros *macros = nullptr; ///< in effect in the file (function-like ones expand)
    };

    CppFunctionExtractor(const SyntaxTree &tree, Context context);
    // The evaluator and the port call reader refer to this object's members.
    CppFunctionExtractor(const CppFunctionExtractor &) = delete;
    CppFunctionExtractor &operator=(const CppFunctionExtractor &) = delete;

    CppFunction extract(TSNode functionDefinition, const QStringList &functionTemplateParameters);

private:
    void readSignature(TSNode functionDefinition);
    void readInitializers(TSNode functionDefinition);
    void visit(TSNode root);
    bool visitNode(TSNode n);
    bool inLoopHead(TSNode value, std::initializer_list<TSNode> near) const;
    void onDeclaration(TSNode declaration);
    void onAssignment(TSNode assignment);
    bool joinsItself(TSNode value, const QString &name) const;
    void addMemberBinding(const QString &name, TSNode value, bool joinsItself);
    void onCall(TSNode call);
    void onNew(TSNode expression);
    void onParameterCall(TSNode call, const cppsyntax::CallShape &shape,
                         const std::vector<TSNode> &args);
    void addFieldBinding(TSNode target, const CppValue &value);
    void addInstantiation(const QString &className, const std::vector<TSNode> &args, TSNode where,
                          const QString &member = {});
    void addProceduralNode(TSNode creation, const std::vector<TSNode> &args, bool lifecycle);
    bool isProceduralNodeType(const QString &className, bool *lifecycle) const;
    void addMethodCall(TSNode call, const cppsyntax::CallShape &shape,
                       const std::vector<TSNode> &args);
    void addFreeCall(TSNode where, const cppsyntax::CallShape &shape,
                     const std::vector<TSNode> &args);
    void markOutArguments(const cppsyntax::CallShape &shape, const std::vector<TSNode> &args);
    QString assignedVariable(TSNode expression) const;

    const SyntaxTree &m_tree;
    Context m_context;
    CppFunction m_function;
    TSNode m_definition{};
    bool m_member = false;
    QStringList m_templateParameters;
    QHash<QString, CppLocal> m_locals;
    std::vector<TSNode> m_path; ///< while visiting: the ancestors of the node visited
    QStringList m_returned;     ///< locals the function returns (node factories are no nodes)
    CppValueEvaluator m_values{m_tree, m_locals, m_function, m_context.macros};
    CppPortCallReader m_portCalls{m_tree,
                                  m_values,
                                  m_locals,
                                  m_templateParameters,
                                  m_definition,
                                  m_function,
                                  m_context.classAliases};
};

} // namespace rosarch
