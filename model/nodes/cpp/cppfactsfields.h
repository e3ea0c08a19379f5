#pragma once

#include "core/languageanalysis.h"
#include "core/modelfields.h"
#include "nodes/cpp/cppfacts.h"

// The field lists of the C++ facts and of a language analysis (as modelfields.h gives those of
// the model types): one list per type, for the analysis cache's codec (CppFactsCodec) and for
// comparing facts apart from their locations (evidencewalk, CppLinkMemo). A field added to a
// type is added here once; changing a list means bumping AnalysisCache::kFormatVersion.

namespace rosarch {

template <class F> void fields(CppValue &v, F f)
{
    f(v.kind, v.text, v.literal, v.variable, v.parameter, v.index, v.parts, v.field, v.objectType);
}
template <class F> void fields(CppParameterDeclaration &v, F f)
{
    f(v.parameter, v.defaultValue, v.name, v.via, v.type, v.hasDefault, v.defaultText, v.readOnly,
      v.dynamicTyping, v.description, v.range, v.guard, v.evidence);
}
template <class F> void fields(CppMemberBinding &v, F f)
{
    f(v.member, v.value);
}
template <class F> void fields(CppFieldBinding &v, F f)
{
    f(v.target, v.value);
}
template <class F> void fields(CppPortCall &v, F f)
{
    f(v.kind, v.name, v.typeWritten, v.typeIsTemplateParameter, v.callback, v.callbackParameter,
      v.guard, v.guardValue, v.receiver, v.transportType, v.qos, v.evidence);
}
template <class F> void fields(CppInstantiation &v, F f)
{
    f(v.className, v.member, v.arguments, v.guard, v.evidence, v.guardValue);
}
template <class F> void fields(CppMethodCall &v, F f)
{
    f(v.member, v.method, v.templateArguments, v.arguments, v.guard, v.guardValue, v.evidence);
}
template <class F> void fields(CppFreeCall &v, F f)
{
    f(v.function, v.arguments, v.evidence);
}
template <class F> void fields(CppProceduralNode &v, F f)
{
    f(v.variable, v.member, v.nodeName, v.lifecycle, v.evidence);
}
template <class F> void fields(CppBaseInitializer &v, F f)
{
    f(v.name, v.firstArgument, v.arguments);
}
template <class F> void fields(CppFunction &v, F f)
{
    f(v.name, v.ownerScope, v.ownerClass, v.namespaces, v.isConstructor, v.parameterNames,
      v.parameterTypes, v.parameterDefaults, v.requiredParameters, v.variadic, v.aliases,
      v.baseInitializers, v.ports, v.parameterDeclarations, v.memberBindings, v.fieldBindings,
      v.outBindings, v.instantiations, v.freeCalls, v.builderCalls, v.methodCalls,
      v.proceduralNodes, v.templateParameters, v.returnValue, v.evidence, v.acceptsUndeclared);
}
template <class F> void fields(CppClass &v, F f)
{
    f(v.name, v.qualifiedName, v.scope, v.bases, v.templateParameters, v.aliases, v.memberTypes,
      v.memberInitializers, v.memberInstantiations, v.declaredDefaults, v.evidence);
}
template <class F> void fields(CppPluginExport &v, F f)
{
    f(v.className, v.baseClass, v.evidence);
}
template <class F> void fields(ComponentRegistration &v, F f)
{
    f(v.file, v.pluginClass, v.evidence);
}
template <class F> void fields(CppFileFacts &v, F f)
{
    f(v.path, v.package, v.isHeader, v.classes, v.functions, v.aliases, v.usingNamespaces,
      v.constants, v.registrations, v.pluginExports, v.diagnostics);
}
template <class F> void fields(EntryPoint &v, F f)
{
    f(v.file, v.function, v.instantiatedClasses, v.constructions, v.evidence);
}
template <class F> void fields(LanguageAnalysis &v, F f)
{
    f(v.nodes, v.entryPoints, v.registrations, v.diagnostics, v.helperParameters);
}

} // namespace rosarch
