#pragma once

#include "core/launchaction.h"
#include "launch/xmlyaml/frontendentity.h"

#include <QList>

namespace rosarch {

/// Translates frontend entities (read from XML or YAML) into LaunchActions, the same way for
/// both formats. Values stay symbolic; nothing about scopes or arguments is evaluated here.
class FrontendActionMapper
{
public:
    /// Problems found while mapping (bad substitutions, missing attributes) go to `diagnostics`.
    explicit FrontendActionMapper(QList<Diagnostic> *diagnostics) : m_diagnostics(diagnostics) {}

    /// Maps the entities inside the root `launch` entity, in document order.
    QList<LaunchAction> map(const QList<FrontendEntity> &entities);

private:
    void mapInto(const FrontendEntity &e, QList<LaunchAction> *out);
    LaunchAction start(const FrontendEntity &e, LaunchAction::Kind kind);
    LaunchAction node(const FrontendEntity &e, LaunchAction::Kind kind);
    LaunchAction composableNode(const FrontendEntity &e);
    LaunchAction group(const FrontendEntity &e);

    Substitution value(const FrontendEntity &e, const QString &name, bool required = false);
    Substitution value(const FrontendEntity &e, const FrontendAttribute &a);
    LaunchCondition condition(const FrontendEntity &e);
    QList<LaunchRemap> remaps(const FrontendEntity &e);
    void parameters(const FrontendEntity &e, const Substitution &prefix,
                    QList<LaunchParameter> *out);
    void commandLine(const FrontendEntity &e, const FrontendAttribute &a, bool rosArgsOnly,
                     LaunchAction *node);
    void report(const QString &code, const QString &message, const Evidence &evidence,
                Diagnostic::Severity severity = Diagnostic::Severity::Warning);

    QList<Diagnostic> *m_diagnostics;
    int m_depth = 0;
};

} // namespace rosarch
