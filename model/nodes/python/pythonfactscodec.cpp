#include "nodes/python/pythonfactscodec.h"

#include "cache/cachecodec.h"

namespace rosarch::cachecodec {

template <class F> void cacheFields(Tag, PythonHandle &v, F f)
{
    f(v.kind, v.index, v.name, v.method);
}
template <class F> void cacheFields(Tag, PythonArgument &v, F f)
{
    f(v.keyword, v.text, v.isString, v.value, v.origin, v.parameter, v.parameterIndex,
      v.interfaceType, v.items);
}
template <class F> void cacheFields(Tag, PythonParameterRef &v, F f)
{
    f(v.index, v.name, v.method);
}
template <class F> void cacheFields(Tag, PythonNamePart &v, F f)
{
    f(v.text, v.from);
}
template <class F> void cacheFields(Tag, PythonPortFact &v, F f)
{
    f(v.port, v.method, v.handle, v.nameFrom, v.typeFrom, v.nameParts);
}
template <class F> void cacheFields(Tag, PythonHandoff &v, F f)
{
    f(v.target, v.argument, v.keyword, v.handle, v.method, v.arguments, v.evidence);
}
template <class F> void cacheFields(Tag, PythonCall &v, F f)
{
    f(v.target, v.arguments, v.evidence);
}
template <class F> void cacheFields(Tag, PythonProcedural &v, F f)
{
    f(v.nodeName, v.function, v.lifecycle, v.evidence);
}
template <class F> void cacheFields(Tag, PythonParameter &v, F f)
{
    f(v.name, v.hasDefault, v.defaultIsString, v.defaultValue);
}
template <class F> void cacheFields(Tag, PythonClassFacts &v, F f)
{
    f(v.ports, v.handoffs, v.calls, v.procedurals, v.name, v.qualifiedName, v.bases, v.baseTargets,
      v.evidence, v.methods, v.methodParameters, v.superCalledMethods, v.hasInit, v.initParameters,
      v.hasBaseInitCall, v.baseInitArguments, v.parameterDeclarations, v.acceptsUndeclared);
}
template <class F> void cacheFields(Tag, PythonFunctionFacts &v, F f)
{
    f(v.ports, v.handoffs, v.calls, v.procedurals, v.name, v.parameters, v.evidence,
      v.parameterDeclarations, v.acceptsUndeclared);
}
template <class F> void cacheFields(Tag, PythonModuleFacts &v, F f)
{
    f(v.file, v.package, v.modulePath, v.classes, v.functions, v.diagnostics);
}
template <class F> void cacheFields(Tag, PythonFileResult &v, F f)
{
    f(v.module, v.diagnostics);
}

} // namespace rosarch::cachecodec

namespace rosarch {

QByteArray PythonFactsCodec::encode(const PythonFileResult &result)
{
    return cachecodec::encode(result);
}

bool PythonFactsCodec::decode(const QByteArray &bytes, PythonFileResult *result)
{
    return cachecodec::decode(bytes, result);
}

} // namespace rosarch
