#pragma once

#include "core/launchdependencies.h"

#include <QHash>
#include <QList>
#include <QRegularExpression>
#include <QSet>
#include <QString>

namespace rosarch {

/// What the architecture checks leave to something outside the system they judge (blueprint
/// §1, docs/checks.md): topics an RViz configuration of the workspace displays, ports the
/// project declares as expected externals, and names the entry point takes as launch arguments.
class CheckScope
{
public:
    explicit CheckScope(const LaunchDependencies &launch);

    /// The system about to be checked, by its entry point's file.
    void enterSystem(const QString &rootFile);

    /// Displayed by an RViz configuration of the workspace, also in a namespace the
    /// configuration does not write (`/global_costmap/costmap` for `/robot1/global_costmap/...`).
    bool isViewed(const QString &name) const;

    /// A name whose other side is expected outside the system: declared so in the project, or
    /// the default of a launch argument the entry point declares (the file takes the name
    /// from whoever includes it: `<arg name="output/objects" default="/perception/rois"/>`).
    bool isInterface(const QString &name, bool output) const;

    /// The declaration that accepts a finding about `name` as an expected external
    /// (Diagnostic::external). Only a fully qualified name can be declared, not one resting on
    /// an unresolved expression.
    static QString externalOf(const QString &name, bool output);

    /// Whether the checks judge the system of a root launch-file instance: an entry point's.
    /// Without entry points (a composition of given instances), every root.
    static bool isJudged(const LaunchDependencies &launch, const QString &rootFile);

    /// The launch-file instances of the judged systems: each root and what it includes.
    static QSet<QString> judgedInstances(const LaunchDependencies &launch);

private:
    bool isExpectedExternal(const QString &name, bool output) const;

    QList<ExpectedExternal> m_externals;
    QList<QRegularExpression> m_externalPatterns;     ///< m_externals', in order
    QSet<QString> m_viewed;                           ///< absolute
    QHash<QString, QSet<QString>> m_argumentDefaults; ///< entry point -> absolute defaults
    QSet<QString> m_rootArguments;                    ///< those of the system being checked
};

} // namespace rosarch
