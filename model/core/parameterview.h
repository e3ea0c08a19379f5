#pragma once

#include "core/atomicnodelist.h"
#include "core/launchdependencies.h"

#include <QHash>
#include <QList>
#include <QPair>
#include <QStringList>

namespace rosarch {

/// One parameter of a node instance (blueprint §1): what its class, or a plugin it loads,
/// declares, joined with the value in effect and where that value comes from.
/// The items of a list value as the parameters give it (`[a, 'b']`), without their quotes;
/// empty when `value` is no list.
QStringList parameterListItems(const QString &value);

struct InstanceParameter
{
    QString name;   ///< as the instance's node knows it (`FollowPath.max_vel_x`)
    QString plugin; ///< the plugin instance that declares it ("" for the node's class)
    bool declared = false;
    QString type;
    QString defaultValue;
    bool hasDefault = false;
    QString value;         ///< the value in effect ("" when nothing sets it)
    bool hasValue = false; ///< set by the launch file or a parameter file
    QString source;        ///< "launch", "file", "default"; "" when neither set nor defaulted
    QString file;          ///< the parameter file for source "file"
    Evidence valueEvidence;
    QString description;
    bool readOnly = false;
    QString range;
    Evidence declaration; ///< the declaration in code (none for an undeclared value)
};

/// Joins an instance's declarations (its class's and those of the plugins its parameters
/// load, `{plugin}` filled in) with its parameters in effect. One query for the architecture
/// JSON, the GUI and the parameter checks.
class ParameterView
{
public:
    explicit ParameterView(const AtomicNodeList &nodes);

    /// The declarations that apply to `n`; `unknownPlugins` gets the names of plugins it loads
    /// whose classes are not in the workspace (their parameters cannot be judged).
    QList<ParameterDeclaration> declarationsOf(const NodeInstance &n,
                                               QStringList *unknownPlugins = nullptr) const;
    /// Every declared parameter and every value given, sorted by name.
    QList<InstanceParameter> of(const NodeInstance &n) const;
    /// A declaration as a row without a value set (its default, if any, in effect).
    static InstanceParameter declared(const ParameterDeclaration &d, const QString &plugin = {});

    /// The plugins `n` loads, by the name each is loaded under, with their classes: those its
    /// `<name>.plugin` values load, and those a loaded plugin loads by class name from a list
    /// parameter of its own. `unknownPlugins` as for declarationsOf.
    QList<QPair<QString, const AtomicNode *>>
    loadedPlugins(const NodeInstance &n, QStringList *unknownPlugins = nullptr) const;
    /// The plugin class loaded under a `<name>.plugin` value, or null.
    const AtomicNode *pluginClass(const QString &written) const;
    /// The helper code's declaration (AtomicNodeList::helperParameters) that names `key`, or
    /// null.
    const ParameterDeclaration *helperDeclaring(const QString &key) const;

private:
    const AtomicNodeList &m_nodes;
    QHash<QString, const AtomicNode *> m_plugins; ///< by qualified name
    /// helper declarations by exact name, and those with run-time parts
    QHash<QString, const ParameterDeclaration *> m_helperNames;
    QList<const ParameterDeclaration *> m_helperPatterns;
};

} // namespace rosarch
