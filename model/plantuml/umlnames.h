#pragma once

#include <QString>
#include <QStringList>

namespace rosarch::UmlNames {

/// Canonical stereotypes the reader knows.
inline const QString AtomicRosNodeClassifier = QStringLiteral("AtomicRosNodeClassifier");
inline const QString ComposedRosNodeClassifier = QStringLiteral("ComposedRosNodeClassifier");
inline const QString RosNodePart = QStringLiteral("RosNodePart");
inline const QString NamespaceStereotype = QStringLiteral("namespace");
inline const QString ServiceStereotype = QStringLiteral("Service");
inline const QString ActionStereotype = QStringLiteral("Action");

/// The known stereotype `written` stands for: equal ignoring case, else the one unique closest
/// within edit distance 2 (ignoring case). "" when none. `note` says what changed, if anything.
QString stereotype(const QString &written, QString *note);
/// An interface type as "pkg/msg/T": from `pkg::msg::T`, `pkg/msg/T`, `pkg.msg.T` or `pkg/T`
/// (then `kind` — "msg", "srv" or "action" — is inserted); `**` and blanks dropped.
QString interfaceType(const QString &written, const QString &kind, QString *note);
/// A ROS name without blanks and without its leading '/'.
QString name(const QString &written);
/// A namespace without leading and trailing '/'; the root is "/".
QString nameSpace(const QString &written);
/// A launch stem: "robot" for "robot.launch.py", "robot_launch.py", "robot.launch", "robot.puml".
QString launchStem(const QString &written, QString *note);
/// A function name: "on_msg" for "on_msg(...)", "self.on_msg", "&Talker::on_msg", "this->on_msg()".
QString functionName(const QString &written, QString *note);

} // namespace rosarch::UmlNames
