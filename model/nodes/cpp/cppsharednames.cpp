#include "nodes/cpp/cppsharednames.h"

#include "syntax/cppsyntax.h"

#include <QRegularExpression>

namespace rosarch {

using namespace cppsyntax;

CppSharedNames::CppSharedNames(const QList<CppFileFacts> &files, const CppClassIndex &index)
    : m_index(index)
{
    for (const CppFileFacts &file : files) {
        for (auto it = file.constants.constBegin(); it != file.constants.constEnd(); ++it)
            m_constants[it.key()].append({file.package, it.value()});
        for (const CppFunction &fn : file.functions) {
            if (fn.fieldBindings.isEmpty())
                continue;
            const int cls = index.ownerOf(&fn);
            for (const CppFieldBinding &b : fn.fieldBindings) {
                FieldBinding binding{file.package, QString(), b.value, cls, &fn, &file};
                if (!b.target.objectType.isEmpty()) {
                    binding.structType = structType(b.target.objectType);
                } else if (!b.target.variable.isEmpty() && cls >= 0) {
                    QStringList templateParameters;
                    const QString type = memberType(b.target.variable, cls, &templateParameters);
                    binding.structType = structType(type, templateParameters);
                }
                m_fields[b.target.field].append(binding);
            }
        }
    }
}

QList<const CppSharedNames::FieldBinding *>
CppSharedNames::fieldBindings(const QString &field, const QString &structType,
                              const QString &package) const
{
    // Struct names repeat across packages (every nav2 server has its `Parameters`): the
    // package's own struct first.
    QList<const FieldBinding *> typedHere;
    QList<const FieldBinding *> typed;
    QList<const FieldBinding *> packaged;
    const auto it = m_fields.constFind(field);
    if (it == m_fields.constEnd())
        return {};
    for (const FieldBinding &b : *it) {
        if (!structType.isEmpty() && b.structType == structType)
            (b.package == package ? typedHere : typed).append(&b);
        else if (b.package == package && (b.structType.isEmpty() || structType.isEmpty()))
            packaged.append(&b);
    }
    if (!typedHere.isEmpty())
        return typedHere;
    return typed.isEmpty() ? packaged : typed;
}

QString CppSharedNames::constant(const QString &name, const QString &package) const
{
    const auto it = m_constants.constFind(name);
    if (it == m_constants.constEnd())
        return QString();
    for (const bool samePackage : {true, false}) {
        QString value;
        bool ambiguous = false;
        for (const Constant &c : *it) {
            if (samePackage && c.package != package)
                continue;
            if (value.isNull())
                value = c.value;
            else if (value != c.value)
                ambiguous = true;
        }
        if (ambiguous)
            return QString();
        if (!value.isNull())
            return value;
    }
    return QString();
}

QString CppSharedNames::structType(const QString &written, const QStringList &templateParameters)
{
    static const QRegularExpression qualifiers(
        QStringLiteral("\\b(const|volatile|struct|class|typename|mutable|static)\\b|[*&]"));
    static const QRegularExpression wrapper(QStringLiteral(
        "^(::)?(std::)?(shared_ptr|unique_ptr|weak_ptr|optional|reference_wrapper)<(.*)>$"));
    static const QRegularExpression pointerAlias(
        QStringLiteral("::(SharedPtr|ConstSharedPtr|UniquePtr|WeakPtr|Ptr|ConstPtr)$"));
    QString type = QString(written).remove(qualifiers).simplified().remove(u' ');
    for (int step = 0; step < 3; ++step) {
        const auto m = wrapper.match(type);
        if (!m.hasMatch())
            break;
        type = m.captured(4);
    }
    type.remove(pointerAlias);
    type = lastSegment(withoutTemplateArguments(type));
    if (type == QLatin1String("auto") || templateParameters.contains(type))
        return QString();
    return type;
}

QString CppSharedNames::memberType(const QString &member, int cls,
                                   QStringList *templateParameters) const
{
    for (int c : m_index.lineage(cls)) {
        const CppClass &info = *m_index.at(c).cls;
        const auto it = info.memberTypes.constFind(member);
        if (it != info.memberTypes.constEnd()) {
            *templateParameters = info.templateParameters;
            return *it;
        }
    }
    return QString();
}

} // namespace rosarch
