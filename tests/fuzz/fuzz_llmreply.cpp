// libFuzzer target: an LLM reply's content, parsed and checked against a schema shaped like
// the node-description prompt's (what the client does with every reply).
#include "fuzzsupport.h"
#include "suggestions/llm/llmclient.h"
#include "suggestions/llm/llmschemavalidator.h"

#include <QJsonArray>
#include <QJsonObject>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    // The shape of the node-description reply: an object with a list of cited descriptions.
    static const QJsonObject schema =
        QJsonDocument::fromJson(R"({"type": "object", "required": ["descriptions"],
          "additionalProperties": false, "properties": {"descriptions": {"type": "array",
          "maxItems": 50, "items": {"type": "object", "required": ["node_id", "description"],
          "properties": {"node_id": {"type": "string"}, "description": {"type": "string",
          "maxLength": 300}, "evidence": {"type": "array", "items": {"type": "object",
          "properties": {"file": {"type": "string"}, "line": {"type": "integer",
          "minimum": 1}}}}}}}}})")
            .object();
    QString error;
    const QJsonDocument doc =
        rosarch::LlmClient::parseReply(QString::fromUtf8(rosarch::fuzz::bytes(data, size)), &error);
    if (doc.isNull())
        return 0;
    const QJsonValue value = doc.isObject() ? QJsonValue(doc.object()) : QJsonValue(doc.array());
    rosarch::LlmSchemaValidator(schema).validate(value, &error);
    return 0;
}
