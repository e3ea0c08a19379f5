#pragma once

#include "core/diagnostic.h"
#include "nodes/python/pythonmodulefacts.h"

#include <QByteArray>
#include <QList>

#include <optional>

namespace rosarch {

/// What the analysis of one Python file gives: its module's facts (none when it could not be
/// parsed) and the diagnostics of its parse.
struct PythonFileResult
{
    std::optional<PythonModuleFacts> module;
    QList<Diagnostic> diagnostics;
};

/// The binary form of one Python file's result in the analysis cache.
class PythonFactsCodec
{
public:
    static QByteArray encode(const PythonFileResult &result);
    /// False when `bytes` are not a whole, well-formed entry.
    static bool decode(const QByteArray &bytes, PythonFileResult *result);
};

} // namespace rosarch
