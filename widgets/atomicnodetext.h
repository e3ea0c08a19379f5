#pragma once

#include "core/atomicnode.h"
#include "document/nodedescription.h"

#include <QCoreApplication>
#include <QString>

namespace rosarch {

struct RosPackage;

/// The words the node tree shows: details columns and tooltips that say what an element
/// is and where it comes from (file:line).
class AtomicNodeText
{
    Q_DECLARE_TR_FUNCTIONS(rosarch::AtomicNodeText)
public:
    /// "Publisher", "Service server", ... for people.
    static QString portKindLabel(PortKind kind);
    /// "node: talker · exec: talker · Python"
    static QString nodeDetails(const AtomicNode &node);
    /// "callback: on_echo · param: echo_topic · guard: use_echo"
    static QString portDetails(const Port &port);
    /// `pkg` may be null for a package named only by node sources.
    static QString packageToolTip(const QString &name, const RosPackage *pkg, int nodeCount);
    /// What the class is and where it comes from, with its description in effect and the
    /// source of that description.
    /// `loaded`: the plugin classes the class's launched instances load (their parameters
    /// name them), each shown with what it serves.
    static QString nodeToolTip(const AtomicNode &node, const NodeDescription &description,
                               const QList<const AtomicNode *> &loaded = {});
    static QString portToolTip(const AtomicNode &node, const Port &port);
    /// "12 declared · takes any parameter"
    static QString parametersDetails(const AtomicNode &node);
    static QString parametersToolTip(const AtomicNode &node);
    /// "default: 0.5 · read-only · range: [0.0, 1.0] · guard: use_x"
    static QString parameterDetails(const ParameterDeclaration &parameter);
    static QString parameterToolTip(const AtomicNode &node, const ParameterDeclaration &parameter);
};

} // namespace rosarch
