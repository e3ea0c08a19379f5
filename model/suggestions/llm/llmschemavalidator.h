#pragma once

#include <QJsonObject>
#include <QJsonValue>
#include <QString>

namespace rosarch {

/// Checks a JSON value against the subset of JSON Schema the prompt contracts use: type,
/// properties, required, additionalProperties (false or a schema), items, enum, min/maxItems,
/// min/maxLength, minimum/maximum.
class LlmSchemaValidator
{
public:
    explicit LlmSchemaValidator(const QJsonObject &schema);
    /// True when `value` fits; otherwise `error` names the first offending path, e.g.
    /// "$.descriptions[0].node_id: expected string".
    bool validate(const QJsonValue &value, QString *error) const;

private:
    bool check(const QJsonObject &schema, const QJsonValue &value, const QString &path,
               QString *error) const;
    QJsonObject m_schema;
};

} // namespace rosarch
