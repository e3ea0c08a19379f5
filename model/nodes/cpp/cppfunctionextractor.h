#pragma once

#include "cppfacts.h"
#include "cppsyntax.h"
#include "syntaxtree.h"

#include <QHash>

namespace rosarch {

/// Extracts the facts of one C++ function definition: its ports, parameter declarations,
/// member assignments, instantiations and procedurally created nodes. Locals are resolved on
/// the spot (in document order); members and parameter defaults are left for the linker.
class CppFunctionExtractor
{
public:
    struct Context
    {
        int ownerClass = -1;            ///< inline member: index of the class in the file
        QString className;              ///< inline member: the class's unqualified name
        QStringList namespaces;         ///< enclosing namespaces
        QStringList templateParameters; ///< of enclosing class templates
        bool rclcppNodeInScope = false; ///< `using rclcpp::Node` / `using namespace rclcpp`
        bool lifecycleNodeInScope = false;
    };

    CppFunctionExtractor(const SyntaxTree &tree, Context context);

    CppFunction extract(TSNode functionDefinition, const QStringList &functionTemplateParameters);

private:
    struct Local
    {
        QString type;
        TSNode value{};    ///< latest value (initializer or assignment)
        QString parameter; ///< bound through get_parameter("p", local)
    };

    void readSignature(TSNode functionDefinition);
    void readInitializers(TSNode functionDefinition);
    void visit(TSNode body);
    void onDeclaration(TSNode declaration);
    void onAssignment(TSNode assignment);
    void onCall(TSNode call);
    void onNew(TSNode expression);
    void onParameterCall(const QString &name, const std::vector<TSNode> &args);
    bool onPortCall(TSNode call, const cppsyntax::CallShape &shape,
                    const std::vector<TSNode> &args);
    void addInstantiation(const QString &className, const std::vector<TSNode> &args, TSNode where,
                          const QString &member = {});
    void addProceduralNode(TSNode creation, const std::vector<TSNode> &args, bool lifecycle);
    bool isProceduralNodeType(const QString &className, bool *lifecycle) const;
    void addFreeCall(const cppsyntax::CallShape &shape, const std::vector<TSNode> &args);
    QString assignedVariable(TSNode expression) const;

    CppValue evaluate(TSNode expression, int depth = 0) const;
    CppValue evaluateIdentifier(const QString &name, int depth) const;
    int literalParameterIndex(const std::vector<TSNode> &args, QString *parameter) const;
    QString callbackName(const std::vector<TSNode> &args, int first) const;
    void guardOf(TSNode call, QString *guard, CppValue *guardValue) const;

    const SyntaxTree &m_tree;
    Context m_context;
    CppFunction m_function;
    TSNode m_definition{};
    bool m_member = false;
    QStringList m_templateParameters;
    QHash<QString, Local> m_locals;
    QStringList m_returned; ///< locals the function returns (node factories are no nodes)
};

} // namespace rosarch
