#pragma once

#include "core/diagnostic.h"
#include "core/launchdependencies.h"

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>

namespace rosarch {

/// A ROS 2 parameter file (what `--params-file` reads), read statically: for each node key,
/// the parameters under its `ros__parameters`, nested names dotted as rclcpp names them.
struct ParameterFile
{
    struct Entry
    {
        QString pattern; ///< the node it is for, absolute: "/ns/node", "/**", "/*/node"
        QList<ParameterSetting> parameters; ///< source "file", in file order
    };
    QString file;
    QList<Entry> entries;
    QList<Diagnostic> diagnostics;

    /// Reads the YAML; problems (syntax, no `ros__parameters`, budget) become diagnostics.
    static ParameterFile read(const QByteArray &content, const QString &file);

    /// nav2_common's RewrittenYaml: the value of every parameter whose name, or last name
    /// segment, is a rewrite's key is replaced (keys that are not in the file are not added);
    /// a key "=X" replaces every value X (value_rewrites); with a root key, every entry moves
    /// under that namespace.
    void rewrite(const QList<QPair<QString, QString>> &rewrites, const QString &rootKey);

    /// The parameters for the node `fqn` as rclcpp applies one file: the entries matched by a
    /// wildcard first, then the node's own; a later value of a name replaces an earlier one.
    QList<ParameterSetting> forNode(const QString &fqn) const;

    /// Whether a node key matches a fully qualified node name: `*` stands for one name
    /// segment, `**` for any number of them.
    static bool matches(const QString &pattern, const QString &fqn);
};

} // namespace rosarch
