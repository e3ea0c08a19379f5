#pragma once

#include <QJsonObject>
#include <QList>
#include <QRegularExpression>
#include <QString>
#include <QStringList>

namespace rosarch {

/// Recognises observability outputs (blueprint §1): debug, visualisation, diagnostics and
/// processing-time publishers, meant for tools rather than for the nodes of the system. The
/// rules are data (interfaces/observability.json, schemas/observability.schema.json): by the
/// message's package, by a segment of the resolved name, and by the helper that creates the
/// port.
class Observability
{
public:
    /// The rules shipped with rosarch.
    static const Observability &builtIn();
    /// Rules read from a JSON object of the schema's shape; a bad regular expression is left
    /// out and named in `problems`.
    static Observability fromJson(const QJsonObject &rules, QStringList *problems = nullptr);

    /// These rules and `other`'s.
    Observability merged(const Observability &other) const;

    /// Whether a port with this resolved name, canonical type ("pkg/msg/T") and creating
    /// helper ("" when the node creates it itself) is an observability output.
    bool covers(const QString &name, const QString &type, const QString &helper) const;

    bool isEmpty() const;

private:
    QStringList m_packages;
    QList<QRegularExpression> m_segments;
    QStringList m_helpers;
};

} // namespace rosarch
