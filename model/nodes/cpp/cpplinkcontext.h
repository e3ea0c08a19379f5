#pragma once

#include "nodes/cpp/cppfacts.h"

#include <QHash>
#include <QList>
#include <QString>

namespace rosarch {

/// Bound for alias, member and helper chains while linking C++ facts.
constexpr int kMaxLinkDepth = 12;

struct CppSubstitution;

/// Where the linker resolves a name or a port: the class (or -1 outside one), the function and
/// file the code is in, and, inside a helper, what its parameters stand for.
struct CppLinkContext
{
    int cls = -1;
    const CppFunction *fn = nullptr;
    const CppFileFacts *file = nullptr;
    const CppSubstitution *subst = nullptr; ///< arguments of the helper's instantiation
    int self = -1; ///< the object's most derived class, for virtual calls (-1: `cls`)
};

/// The arguments a helper was handed, and where they were written.
struct CppSubstitution
{
    QList<CppValue> arguments;
    CppLinkContext outer;
    QHash<QString, QString> templateArguments; ///< helper template parameter -> type
    const CppFunction *function = nullptr;     ///< free helper function; null: the constructors
    /// A pluginlib plugin's own code: a parameter typed as a node handle is the node it is
    /// given (`configure(parent, ...)`), since the loader hands it over.
    bool plugin = false;
    /// A method called on a helper object (`debug_->publish<T>("x", v)`): the arguments the
    /// object was constructed with, for its constructors.
    const CppSubstitution *constructed = nullptr;
};

/// A port name as resolved: where it comes from, the name (or the expression as written),
/// and the parameter it is declared by.
struct CppResolvedName
{
    CppResolvedName() = default;
    CppResolvedName(NameOrigin o, QString n, QString e, QString p)
        : origin(o), name(std::move(n)), expression(std::move(e)), parameter(std::move(p))
    {
    }

    NameOrigin origin = NameOrigin::Expression;
    QString name;
    QString expression;
    QString parameter;
    QString parameterPrefix; ///< a joined name: the text around the parameter's value
    QString parameterSuffix;
};

/// One assignment to a member, and where it is.
struct CppBinding
{
    CppValue value;
    const CppFunction *fn = nullptr;
    const CppFileFacts *file = nullptr;
};

/// What a class's members hold and which parameters it declares, in source order.
struct CppMemberFacts
{
    QHash<QString, QList<CppBinding>> bindings;
    QHash<QString, CppParameterDeclaration> parameters;
};

/// What the parameters of the function in `ctx` stand for: the arguments of the helper's
/// instantiation (its constructors), of the call (a free helper function or a method called on
/// a helper), or, in a constructor of a helper whose method was called, of its construction.
inline const CppSubstitution *substitutionFor(const CppLinkContext &ctx)
{
    if (!ctx.subst || !ctx.fn)
        return nullptr;
    if (ctx.subst->function ? ctx.fn == ctx.subst->function : ctx.fn->isConstructor)
        return ctx.subst;
    if (ctx.subst->constructed && ctx.fn->isConstructor)
        return ctx.subst->constructed;
    return nullptr;
}

inline bool substitutes(const CppLinkContext &ctx)
{
    return substitutionFor(ctx) != nullptr;
}

} // namespace rosarch
