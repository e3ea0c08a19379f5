#pragma once

#include "core/diagnostic.h"

#include <QByteArray>
#include <QString>

#include <yaml-cpp/yaml.h>

namespace rosarch {

/// YAML aliases share nodes, so a small file can stand for a huge tree ("billion laughs").
/// Every walk over a YAML tree spends from one budget of node visits per file; when it runs
/// out, the rest is not read and a diagnostic says so.
struct YamlBudget
{
    static constexpr qint64 kVisits = 200000;
    qint64 left = kVisits;
    bool exhausted = false;
    bool spend()
    {
        if (left <= 0) {
            exhausted = true;
            return false;
        }
        --left;
        return true;
    }
};

/// A value as text: a scalar as written, a sequence as "[a, b]" (nested to `maxDepth`), spending
/// from `budget`; a mapping gives "".
QString yamlValueText(const YAML::Node &n, YamlBudget *budget, int maxDepth, int depth = 0);

/// Loads YAML text. On a syntax error, `*error` becomes a `malformed-yaml` diagnostic naming
/// the line, and the result is what the lines before the error give on their own.
YAML::Node loadYaml(const QByteArray &content, const QString &file, Diagnostic *error);

} // namespace rosarch
