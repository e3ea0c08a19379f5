#include "nodes/python/pythonbinding.h"

namespace rosarch::PythonBinding {

namespace {
PythonArgument defaultArgument(const PythonParameter &p)
{
    PythonArgument a;
    a.keyword = p.name;
    a.text = p.defaultValue;
    a.isString = p.defaultIsString;
    a.value = p.defaultIsString ? p.defaultValue : QString();
    a.origin = p.defaultIsString ? NameOrigin::Literal : NameOrigin::Expression;
    return a;
}
} // namespace

const PythonArgument *argumentAt(const QList<PythonArgument> &args, int index,
                                 const QString &keyword)
{
    if (!keyword.isEmpty())
        for (const PythonArgument &a : args)
            if (a.keyword == keyword)
                return &a;
    int position = 0;
    for (const PythonArgument &a : args) {
        if (!a.keyword.isEmpty())
            continue;
        if (position++ == index)
            return &a;
    }
    return nullptr;
}

void substituteName(Port *port, const PythonArgument &a)
{
    port->name = a.value;
    port->nameOrigin = a.origin == NameOrigin::Literal ? NameOrigin::Local : a.origin;
    port->parameter = a.parameter;
}

void applyArguments(Port *port, const PythonPortFact &fact, const QString &method,
                    const QList<PythonArgument> &args, const QList<PythonParameter> *parameters)
{
    if (fact.nameFrom.isValid() && fact.nameFrom.method == method) {
        const PythonArgument *a = argumentAt(args, fact.nameFrom.index, fact.nameFrom.name);
        if (a && a->isString)
            substituteName(port, *a);
    }
    if (fact.typeFrom.isValid() && fact.typeFrom.method == method) {
        const PythonArgument *a = argumentAt(args, fact.typeFrom.index, fact.typeFrom.name);
        if (a && !a->interfaceType.isEmpty())
            port->type = a->interfaceType;
    }
    if (fact.nameParts.isEmpty())
        return;
    QString name;
    for (const PythonNamePart &part : fact.nameParts) {
        if (!part.from.isValid()) {
            name += part.text;
            continue;
        }
        if (part.from.method != method)
            return;
        const PythonArgument *a = argumentAt(args, part.from.index, part.from.name);
        PythonArgument left;
        if (!a && parameters && part.from.index < parameters->size()) {
            left = defaultArgument(parameters->at(part.from.index));
            a = &left;
        }
        // a part from a declared parameter would hide that launch files can change it
        if (!a || !a->isString || !a->parameter.isEmpty())
            return;
        name += a->value;
    }
    port->name = name;
    port->nameOrigin = NameOrigin::Local;
    port->parameter.clear();
}

QList<PythonArgument> bind(const QList<PythonArgument> &inner, const QList<PythonArgument> &outer,
                           const QList<PythonParameter> &parameters)
{
    QList<PythonArgument> out = inner;
    for (PythonArgument &a : out) {
        if (a.parameterIndex < 0 || a.parameterIndex >= parameters.size())
            continue;
        const PythonParameter &p = parameters.at(a.parameterIndex);
        const PythonArgument *given = argumentAt(outer, a.parameterIndex, p.name);
        const PythonArgument value = given ? *given : defaultArgument(p);
        a.isString = value.isString;
        a.value = value.value;
        a.origin = value.origin;
        a.parameter = value.parameter;
        a.interfaceType = value.interfaceType;
        a.parameterIndex = -1;
    }
    return out;
}

QList<PythonArgument> forwardToBase(const PythonClassFacts &c, const QList<PythonArgument> &args)
{
    if (!c.hasInit)
        return args;
    if (!c.hasBaseInitCall)
        return {};
    return bind(c.baseInitArguments, args, c.initParameters);
}

} // namespace rosarch::PythonBinding
