#pragma once

#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// Which of the two diagram kinds of blueprint §3 a PlantUML diagram is.
enum class UmlLevel
{
    Unknown,
    Acd,
    Ccd
};

/// "acd", "ccd" or "unknown".
QString umlLevelName(UmlLevel level);

/// Element kinds of the canonical models (blueprint §4). Actions are kinds of their own rather
/// than folded into the service kinds, so a service recovered as an action counts as wrong.
/// Values: types "pkg/msg/T"; names without a leading '/'; part "name" (the type when
/// unnamed); part_type "name:Type" (":stem" for an included launch file); namespace
/// "(ns, part)" with the root "/"; boundary_port "(in, pkg/msg/T)"; connection
/// "publish part -> topic", "subscribe topic -> part", "client part -> service",
/// "server part -> service", "delegation boundary:in/T -> part", "delegation part ->
/// boundary:out/T".
namespace UmlKind {
// ACD, per AtomicRosNodeClassifier
inline const QString ArcName = QStringLiteral("arc_name");
inline const QString ArcStereotype = QStringLiteral("arc_stereotype");
inline const QString MessageType = QStringLiteral("message_type");
inline const QString Callback = QStringLiteral("callback");
inline const QString ServiceType = QStringLiteral("service_type");
inline const QString ServiceFunction = QStringLiteral("service_function");
inline const QString ActionType = QStringLiteral("action_type");
inline const QString ActionFunction = QStringLiteral("action_function");
// CCD, per ComposedRosNodeClassifier
inline const QString Part = QStringLiteral("part");
inline const QString PartType = QStringLiteral("part_type");
inline const QString Namespace = QStringLiteral("namespace");
inline const QString Topic = QStringLiteral("topic");
inline const QString Service = QStringLiteral("service");
inline const QString Action = QStringLiteral("action");
inline const QString BoundaryPort = QStringLiteral("boundary_port");
inline const QString Connection = QStringLiteral("connection");
} // namespace UmlKind

/// The element kinds of a level, in report order.
QStringList umlKinds(UmlLevel level);
/// A readable name for an element kind ("message type").
QString umlKindLabel(const QString &kind);

/// One canonical element: what is compared. `line` only says where it was read.
struct UmlElement
{
    QString kind;  ///< one of UmlKind
    QString value; ///< canonical text, e.g. "std_msgs/msg/String" or "publish talker -> chatter"
    int line = 0;  ///< 1-based line in the source file (0 when built by hand)
    /// The recovered element it was written from (a DiagramBuilder key such as "part:p1"), so
    /// a difference can be shown where it is drawn; "" for elements read from a reference.
    QString key;

    bool sameAs(const UmlElement &o) const { return kind == o.kind && value == o.value; }
};

/// One diagram read from PlantUML: an ACD (one ARC) or a CCD (one launch file).
struct UmlDiagram
{
    UmlLevel level = UmlLevel::Unknown;
    QString name; ///< class name (ACD) or launch stem (CCD); what diagrams are matched by
    QString file; ///< the file it was read from ("" for text)
    QList<UmlElement> elements;
    QStringList notes;    ///< "line 4: stereotype 'X' read as Y": what the reader normalized
    QStringList warnings; ///< "line 9: cannot read '...'": lines the reader skipped
    /// Parts whose label has no ':' (read as a name): a model that has a classifier of that
    /// name reads the part as typed by it instead (UmlModel::typeByClassifiers).
    struct BareLabel
    {
        QString text;
        int line = 0;
    };
    QList<BareLabel> bareParts;

    /// The values of the elements of one kind, in reading order.
    QStringList values(const QString &kind) const;
};

} // namespace rosarch
