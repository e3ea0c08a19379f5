#include "cppfactscodec.h"

#include "cachecodec.h"

#include <QCryptographicHash>

#include <algorithm>

namespace rosarch::cachecodec {

template <class F> void cacheFields(Tag, CppValue &v, F f)
{
    f(v.kind, v.text, v.literal, v.variable, v.parameter, v.index, v.parts, v.field, v.objectType);
}
template <class F> void cacheFields(Tag, CppParameterDeclaration &v, F f)
{
    f(v.parameter, v.defaultValue);
}
template <class F> void cacheFields(Tag, CppMemberBinding &v, F f)
{
    f(v.member, v.value);
}
template <class F> void cacheFields(Tag, CppFieldBinding &v, F f)
{
    f(v.target, v.value);
}
template <class F> void cacheFields(Tag, CppPortCall &v, F f)
{
    f(v.kind, v.name, v.typeWritten, v.typeIsTemplateParameter, v.callback, v.callbackParameter,
      v.guard, v.guardValue, v.receiver, v.transportType, v.qos, v.evidence);
}
template <class F> void cacheFields(Tag, CppInstantiation &v, F f)
{
    f(v.className, v.member, v.arguments, v.evidence);
}
template <class F> void cacheFields(Tag, CppMethodCall &v, F f)
{
    f(v.member, v.method, v.templateArguments, v.arguments, v.evidence);
}
template <class F> void cacheFields(Tag, CppFreeCall &v, F f)
{
    f(v.function, v.arguments, v.evidence);
}
template <class F> void cacheFields(Tag, CppProceduralNode &v, F f)
{
    f(v.variable, v.member, v.nodeName, v.lifecycle, v.evidence);
}
template <class F> void cacheFields(Tag, CppBaseInitializer &v, F f)
{
    f(v.name, v.firstArgument);
}
template <class F> void cacheFields(Tag, CppFunction &v, F f)
{
    f(v.name, v.ownerScope, v.ownerClass, v.namespaces, v.isConstructor, v.parameterNames,
      v.parameterTypes, v.parameterDefaults, v.requiredParameters, v.variadic, v.aliases,
      v.baseInitializers, v.ports, v.parameterDeclarations, v.memberBindings, v.fieldBindings,
      v.instantiations, v.freeCalls, v.methodCalls, v.proceduralNodes, v.templateParameters,
      v.returnValue, v.evidence);
}
template <class F> void cacheFields(Tag, CppClass &v, F f)
{
    f(v.name, v.qualifiedName, v.scope, v.bases, v.templateParameters, v.aliases, v.memberTypes,
      v.memberInitializers, v.memberInstantiations, v.evidence);
}
template <class F> void cacheFields(Tag, CppPluginExport &v, F f)
{
    f(v.className, v.baseClass, v.evidence);
}
template <class F> void cacheFields(Tag, CppFileFacts &v, F f)
{
    f(v.path, v.package, v.isHeader, v.classes, v.functions, v.aliases, v.usingNamespaces,
      v.constants, v.registrations, v.pluginExports, v.diagnostics);
}

} // namespace rosarch::cachecodec

namespace rosarch {

QByteArray CppFactsCodec::encode(const CppFileFacts &facts)
{
    return cachecodec::encode(facts);
}

bool CppFactsCodec::decode(const QByteArray &bytes, CppFileFacts *facts)
{
    return cachecodec::decode(bytes, facts);
}

QByteArray CppFactsCodec::digest(const CppMacros &macros)
{
    QList<QByteArray> names = macros.keys();
    std::sort(names.begin(), names.end());
    QCryptographicHash hash(QCryptographicHash::Sha1);
    for (const QByteArray &name : std::as_const(names)) {
        const CppMacro &m = *macros.constFind(name);
        // Separators that cannot occur in a name, a body or a parameter.
        hash.addData(name);
        hash.addData(QByteArrayView("\0", 1));
        hash.addData(m.body);
        hash.addData(QByteArrayView(m.functionLike ? "\1(" : "\1", m.functionLike ? 2 : 1));
        for (const QByteArray &p : m.parameters) {
            hash.addData(p);
            hash.addData(QByteArrayView("\2", 1));
        }
        hash.addData(QByteArrayView("\3", 1));
    }
    return hash.result();
}

} // namespace rosarch
