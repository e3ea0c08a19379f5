#pragma once

#include "core/parameter.h"
#include "nodes/cpp/cppclassindex.h"
#include "nodes/cpp/cpphelperports.h"
#include "nodes/cpp/cpplinkcontext.h"
#include "nodes/cpp/cppnameresolver.h"

#include <QList>
#include <QSet>

#include <map>

namespace rosarch {

/// The parameters a C++ node class or plugin declares (blueprint §1, "Parameters of a
/// class"), from the declarations of the functions on its lineage, with names, defaults and
/// types resolved in each class's context, and whether it takes undeclared parameters.
class CppParameterLinker
{
public:
    /// `files` are those `index` was built from. Helper classes and free functions are followed to
    /// the helpers' depth bound; where it is hit, `helpers` records it for the helper-depth note.
    CppParameterLinker(const QList<CppFileFacts> &files, const CppClassIndex &index,
                       const CppNameResolver &names, const CppHelperPorts &helpers);

    /// The declarations of class `cls` and its bases; a plugin's are resolved with the
    /// substitutions of its lineage (its name is `{plugin}`), given per class.
    QList<ParameterDeclaration>
    declarations(int cls, const std::map<int, CppSubstitution> *substitutions = nullptr) const;

    /// Whether code of the class, or a free function in one of its files, lets its node take
    /// parameters nobody declares.
    bool acceptsUndeclared(int cls) const;

    /// What free functions and classes that are no nodes declare on a node they are handed,
    /// resolved in their own context (LanguageAnalysis::helperParameters).
    /// Plugins count too: a plugin loads plugins of its own (a local planner's trajectory
    /// generator) that declare under its name, which its instances do not show.
    QList<ParameterDeclaration> helperDeclarations() const;

private:
    void addDeclarations(const CppFunction &fn, const CppLinkContext &ctx, bool inherited,
                         QList<ParameterDeclaration> *out, QStringList *undeclared) const;
    void addFreeCalls(const CppFunction &fn, const CppLinkContext &ctx, int node, int depth,
                      QList<ParameterDeclaration> *out, QStringList *undeclared) const;
    void collect(int cls, int node, const std::map<int, CppSubstitution> *substitutions, int self,
                 int depth, QList<int> *visited, QList<ParameterDeclaration> *out,
                 QStringList *undeclared) const;
    int memberHelper(const QString &type, int cls) const;
    QString nameOf(const CppParameterDeclaration &d, const CppLinkContext &ctx) const;
    QString helperName(const CppParameterDeclaration &d, const CppLinkContext &ctx) const;
    QString textOf(const CppValue &value, const CppLinkContext &ctx) const;
    QString defaultOf(const CppParameterDeclaration &d, const CppLinkContext &ctx) const;

    const CppClassIndex &m_index;
    const CppNameResolver &m_names;
    const CppHelperPorts &m_helpers;
    QHash<QString, QList<CppClassIndex::FunctionRef>> m_freeFunctions; ///< by name
    QSet<QString> m_pluginClasses; ///< exported plugin classes and their interfaces, unqualified
};

} // namespace rosarch
