#pragma once

#include "core/port.h"

#include <QJsonObject>
#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// The ports that code outside the workspace creates (blueprint §1, "Interface models"): a
/// well-known executable a launch file starts (robot_state_publisher, rviz2, ...), or a launch
/// file of a package outside the workspace that a launch file includes (a simulator's spawn
/// file). Read from data files (interfaces/models/*.json, schemas/interface-model.schema.json).
struct InterfaceModel
{
    struct ModelPort
    {
        PortKind kind = PortKind::Publisher;
        QString name; ///< as the code writes it (relative, private or absolute)
        QString type; ///< canonical "pkg/msg/T"
        bool operator==(const ModelPort &) const = default;
    };

    QString name;
    QString description;
    QString package;
    /// package -> executables that start the modelled node (the model's own package first).
    QList<QPair<QString, QStringList>> executables;
    QStringList launchFiles;   ///< relative to the package's share folder
    QString namespaceArgument; ///< launch files: the argument that namespaces their nodes
    QList<ModelPort> ports;
    /// Executables that read a configuration file named on their command line (rviz2's `-d`):
    /// the flag, and the display class -> message type table for its "rviz" format.
    QString configArgument;
    QString configFormat;
    QList<QPair<QString, QString>> configTypes;

    /// The model in `o` (the schema's shape); false with `error` when it is not one.
    static bool fromJson(const QJsonObject &o, InterfaceModel *model, QString *error);
    /// The model's ports as atomic ports ("m1", "m2", ...), each citing `evidence` (where the
    /// launch file starts or includes what the model describes) and naming the model as `via`.
    QList<Port> portsAt(const Evidence &evidence) const;
    /// The subscriptions a configuration file of the model's format sets up (an RViz
    /// configuration: every display's topics), each citing its line of `file`; ids go on from
    /// `firstId`. Read as text, tolerant of anything it does not know.
    QList<Port> portsFromConfig(const QByteArray &text, const QString &file, int firstId) const;
    /// At most this many ports are read from one configuration file.
    static constexpr qsizetype kMaxConfigPorts = 1000;
    bool operator==(const InterfaceModel &) const = default;
};

/// The interface models a run knows: the ones shipped with rosarch.
class InterfaceModels
{
public:
    static const InterfaceModels &builtIn();
    /// Reads every `*.json` of `folder`; files that are not models are named in `problems`.
    static InterfaceModels fromFolder(const QString &folder, QStringList *problems = nullptr);

    /// The model of the executable `executable` of `package`, or null.
    const InterfaceModel *executable(const QString &package, const QString &executable) const;
    /// The model of the launch file `file` (relative to its share folder) of `package`, or null.
    const InterfaceModel *launchFile(const QString &package, const QString &file) const;

    const QList<InterfaceModel> &all() const { return m_models; }

private:
    QList<InterfaceModel> m_models; ///< sorted by name
};

} // namespace rosarch
