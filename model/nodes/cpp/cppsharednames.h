#pragma once

#include "nodes/cpp/cppclassindex.h"
#include "nodes/cpp/cppfacts.h"

#include <QHash>
#include <QList>
#include <QString>

namespace rosarch {

/// Names that one file or class defines and another uses, gathered over the workspace: fields
/// of parameters structs that some class fills from parameters (`params_.odom_topic =
/// declare_parameter("odom_topic", ...)` in a ParameterHandler, read as `params_->odom_topic`
/// by the node), and namespace-level string constants of every file (`constexpr char kTopic[]`
/// in another package's header).
class CppSharedNames
{
public:
    /// One `object.field = value` (or `get_parameter("p", object.field)`), and where it is.
    struct FieldBinding
    {
        QString package;
        QString structType; ///< the object's struct type, unqualified ("" when unknown)
        CppValue value;
        int cls = -1; ///< the class of the function that binds it
        const CppFunction *fn = nullptr;
        const CppFileFacts *file = nullptr;
    };

    CppSharedNames(const QList<CppFileFacts> &files, const CppClassIndex &index);

    /// The bindings of `field` an object of `structType` ("" when unknown) read in `package`
    /// may see: those of the same struct type (in the package, else anywhere), else those of
    /// the package where one of the two types is unknown.
    QList<const FieldBinding *> fieldBindings(const QString &field, const QString &structType,
                                              const QString &package) const;

    /// The value of the namespace-level constant `name` seen from `package`: its definition
    /// in the package, else in the workspace, when all such definitions agree (null if not).
    QString constant(const QString &name, const QString &package) const;

    /// The struct a written object type stands for: `const Parameters *`,
    /// `std::shared_ptr<ns::Parameters>`, `Parameters::SharedPtr` -> "Parameters"; "" for
    /// `auto` and for one of `templateParameters`.
    static QString structType(const QString &written, const QStringList &templateParameters = {});

    /// The written type of `member` in `cls` or its project bases, with the template
    /// parameters of the class it is declared in ("" when not declared).
    QString memberType(const QString &member, int cls, QStringList *templateParameters) const;

private:
    const CppClassIndex &m_index;
    QHash<QString, QList<FieldBinding>> m_fields; ///< field -> bindings
    struct Constant
    {
        QString package;
        QString value;
    };
    QHash<QString, QList<Constant>> m_constants; ///< unqualified name -> definitions
};

} // namespace rosarch
