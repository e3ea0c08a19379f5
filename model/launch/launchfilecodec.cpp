#include "launch/launchfilecodec.h"

#include "cache/cachecodec.h"

namespace rosarch::cachecodec {

template <class F> void cacheFields(Tag, LaunchRemap &v, F f)
{
    f(v.from, v.to, v.evidence);
}
template <class F> void cacheFields(Tag, LaunchParameter &v, F f)
{
    f(v.name, v.value, v.isFile, v.evidence);
}
template <class F> void cacheFields(Tag, LaunchCondition &v, F f)
{
    f(v.expression, v.unless, v.text);
}
template <class F> void cacheFields(Tag, LaunchAction &v, F f)
{
    f(v.kind, v.evidence, v.condition, v.package, v.executable, v.plugin, v.name, v.nameSpace,
      v.lifecycle, v.commandLine, v.remaps, v.parameters, v.children, v.scoped, v.target, v.path,
      v.arguments, v.value, v.hasValue, v.description, v.expression);
}
template <class F> void cacheFields(Tag, LaunchFileDescription &v, F f)
{
    f(v.file, v.format, v.actions, v.diagnostics);
}

} // namespace rosarch::cachecodec

namespace rosarch {

QByteArray LaunchFileCodec::encode(const std::optional<LaunchFileDescription> &read)
{
    return cachecodec::encode(read);
}

bool LaunchFileCodec::decode(const QByteArray &bytes, std::optional<LaunchFileDescription> *read)
{
    return cachecodec::decode(bytes, read);
}

} // namespace rosarch
