#include "suggestions/llm/llmschemavalidator.h"

#include <QJsonArray>

#include <cmath>

namespace rosarch {

namespace {

bool hasType(const QJsonValue &value, const QString &type)
{
    if (type == QLatin1String("object"))
        return value.isObject();
    if (type == QLatin1String("array"))
        return value.isArray();
    if (type == QLatin1String("string"))
        return value.isString();
    if (type == QLatin1String("boolean"))
        return value.isBool();
    if (type == QLatin1String("null"))
        return value.isNull();
    if (type == QLatin1String("number"))
        return value.isDouble();
    if (type == QLatin1String("integer")) {
        // Only within the range a double holds exactly: converting 1e62 to an integer type
        // is undefined behaviour (libFuzzer found a reply citing line 1.3e62).
        const double d = value.toDouble();
        return value.isDouble() && std::isfinite(d) && std::abs(d) <= 9007199254740992.0 &&
               d == std::trunc(d);
    }
    return true; // unknown keywords do not reject
}

} // namespace

LlmSchemaValidator::LlmSchemaValidator(const QJsonObject &schema) : m_schema(schema) {}

bool LlmSchemaValidator::validate(const QJsonValue &value, QString *error) const
{
    return check(m_schema, value, QStringLiteral("$"), error);
}

bool LlmSchemaValidator::check(const QJsonObject &schema, const QJsonValue &value,
                               const QString &path, QString *error) const
{
    auto fail = [&](const QString &what) {
        *error = path + QStringLiteral(": ") + what;
        return false;
    };
    if (schema.contains(QLatin1String("type"))) {
        const QJsonValue t = schema.value(QLatin1String("type"));
        QStringList types;
        if (t.isArray())
            for (const QJsonValue &v : t.toArray())
                types << v.toString();
        else
            types << t.toString();
        bool any = false;
        for (const QString &type : std::as_const(types))
            any = any || hasType(value, type);
        if (!any)
            return fail(QStringLiteral("expected %1").arg(types.join(QLatin1String(" or "))));
    }
    if (schema.contains(QLatin1String("enum")) &&
        !schema.value(QLatin1String("enum")).toArray().contains(value))
        return fail(QStringLiteral("not one of the allowed values"));
    if (value.isString()) {
        const qsizetype n = value.toString().size();
        if (schema.contains(QLatin1String("minLength")) &&
            n < schema.value(QLatin1String("minLength")).toInt())
            return fail(QStringLiteral("string shorter than %1")
                            .arg(schema.value(QLatin1String("minLength")).toInt()));
        if (schema.contains(QLatin1String("maxLength")) &&
            n > schema.value(QLatin1String("maxLength")).toInt())
            return fail(QStringLiteral("string longer than %1")
                            .arg(schema.value(QLatin1String("maxLength")).toInt()));
    }
    if (value.isDouble()) {
        const double d = value.toDouble();
        if (schema.contains(QLatin1String("minimum")) &&
            d < schema.value(QLatin1String("minimum")).toDouble())
            return fail(QStringLiteral("below the minimum %1")
                            .arg(schema.value(QLatin1String("minimum")).toDouble()));
        if (schema.contains(QLatin1String("maximum")) &&
            d > schema.value(QLatin1String("maximum")).toDouble())
            return fail(QStringLiteral("above the maximum %1")
                            .arg(schema.value(QLatin1String("maximum")).toDouble()));
    }
    if (value.isArray()) {
        const QJsonArray a = value.toArray();
        if (schema.contains(QLatin1String("minItems")) &&
            a.size() < schema.value(QLatin1String("minItems")).toInt())
            return fail(QStringLiteral("fewer than %1 items")
                            .arg(schema.value(QLatin1String("minItems")).toInt()));
        if (schema.contains(QLatin1String("maxItems")) &&
            a.size() > schema.value(QLatin1String("maxItems")).toInt())
            return fail(QStringLiteral("more than %1 items")
                            .arg(schema.value(QLatin1String("maxItems")).toInt()));
        const QJsonObject items = schema.value(QLatin1String("items")).toObject();
        for (qsizetype i = 0; i < a.size(); ++i)
            if (!check(items, a.at(i), QStringLiteral("%1[%2]").arg(path).arg(i), error))
                return false;
    }
    if (value.isObject()) {
        const QJsonObject o = value.toObject();
        const QJsonObject properties = schema.value(QLatin1String("properties")).toObject();
        for (const QJsonValue &r : schema.value(QLatin1String("required")).toArray())
            if (!o.contains(r.toString()))
                return fail(QStringLiteral("missing required property \"%1\"").arg(r.toString()));
        const QJsonValue additional = schema.value(QLatin1String("additionalProperties"));
        for (auto it = o.begin(); it != o.end(); ++it) {
            const QString sub = path + QLatin1Char('.') + it.key();
            if (properties.contains(it.key())) {
                if (!check(properties.value(it.key()).toObject(), it.value(), sub, error))
                    return false;
            } else if (additional.isBool() && !additional.toBool()) {
                return fail(QStringLiteral("unexpected property \"%1\"").arg(it.key()));
            } else if (additional.isObject()) {
                if (!check(additional.toObject(), it.value(), sub, error))
                    return false;
            }
        }
    }
    return true;
}

} // namespace rosarch
