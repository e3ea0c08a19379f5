#pragma once

#include "nodes/python/pythonmodulefacts.h"

#include <QList>
#include <QString>

// How the arguments at a call site complete what a callee leaves open: port names and types
// taken from parameters, names built from parts, and arguments passed on to further calls.

namespace rosarch::PythonBinding {

/// The argument given by keyword `keyword`, else the positional one at `index`.
const PythonArgument *argumentAt(const QList<PythonArgument> &args, int index,
                                 const QString &keyword);
/// The port's name is a parameter; the caller passed `a` for it.
void substituteName(Port *port, const PythonArgument &a);
/// Completes a port created in a scope whose parameters of `method` ("" = constructor or
/// function) the call site supplies as `args`; `parameters` give the defaults of those left out.
void applyArguments(Port *port, const PythonPortFact &fact, const QString &method,
                    const QList<PythonArgument> &args, const QList<PythonParameter> *parameters);
/// The arguments of a call made inside a function, with those that name the function's own
/// parameters replaced by what its caller passed (`outer`) or their defaults.
QList<PythonArgument> bind(const QList<PythonArgument> &inner, const QList<PythonArgument> &outer,
                           const QList<PythonParameter> &parameters);
/// What a class built with `args` passes on to its project base's constructor.
QList<PythonArgument> forwardToBase(const PythonClassFacts &c, const QList<PythonArgument> &args);

} // namespace rosarch::PythonBinding
