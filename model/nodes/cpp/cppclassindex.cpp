#include "nodes/cpp/cppclassindex.h"

#include "syntax/cppsyntax.h"

namespace rosarch {

using namespace cppsyntax;

namespace {

QString normalizedName(const QString &written)
{
    QString n = withoutTemplateArguments(written).remove(u' ');
    if (n.startsWith(QLatin1String("::")))
        n = n.mid(2);
    return n;
}

} // namespace

CppClassIndex::CppClassIndex(const QList<CppFileFacts> &files)
{
    // Flatten, keeping a per-file offset so that inline members find their class.
    QHash<const CppFileFacts *, int> offset;
    for (const CppFileFacts &file : files) {
        offset.insert(&file, int(m_classes.size()));
        for (const CppClass &cls : file.classes) {
            ClassInfo info;
            info.file = &file;
            info.cls = &cls;
            m_byQualifiedName[cls.qualifiedName].append(int(m_classes.size()));
            m_bySimpleName[cls.name].append(int(m_classes.size()));
            m_classes.push_back(info);
        }
    }
    for (const CppFileFacts &file : files) {
        for (const CppFunction &fn : file.functions) {
            int owner = -1;
            if (fn.ownerClass >= 0) {
                owner = offset.value(&file) + fn.ownerClass;
            } else if (!fn.ownerScope.isEmpty()) {
                owner = lookup(fn.ownerScope, fn.namespaces, &file);
            }
            if (owner >= 0) {
                m_classes[size_t(owner)].functions.append({&file, &fn});
                m_owner.insert(&fn, owner);
            } else {
                m_freeFunctions.append({&file, &fn});
            }
        }
    }
    for (size_t i = 0; i < m_classes.size(); ++i) {
        ClassInfo &info = m_classes[i];
        QStringList scope = info.cls->scope;
        for (const QString &base : info.cls->bases) {
            if (rootOf(base, info) != Root::None)
                continue;
            const int b = lookup(base, scope, info.file);
            if (b >= 0 && b != int(i) && !info.projectBases.contains(b))
                info.projectBases.append(b);
        }
    }
    std::vector<int> state(m_classes.size(), 0);
    for (size_t i = 0; i < m_classes.size(); ++i)
        decideNode(int(i), state);
}

int CppClassIndex::pick(const QList<int> &candidates, const CppFileFacts *file) const
{
    if (candidates.isEmpty())
        return -1;
    for (int c : candidates)
        if (m_classes[size_t(c)].file == file)
            return c;
    if (file)
        for (int c : candidates)
            if (m_classes[size_t(c)].file->package == file->package)
                return c;
    return candidates.first();
}

int CppClassIndex::lookup(const QString &written, const QStringList &fromScope,
                          const CppFileFacts *file) const
{
    const bool global = written.trimmed().startsWith(QLatin1String("::"));
    QString name = normalizedName(written);
    if (name.isEmpty())
        return -1;
    // A namespace-level alias (using X = ns::Y / using ns::Y) names another class.
    if (file && !name.contains(QLatin1String("::"))) {
        const QString target = file->aliases.value(name);
        if (!target.isEmpty() && normalizedName(target) != name)
            name = normalizedName(target);
    }
    if (global)
        return pick(m_byQualifiedName.value(name), file);
    for (qsizetype k = fromScope.size(); k >= 0; --k) {
        const QStringList prefix = fromScope.mid(0, k);
        const QString candidate =
            prefix.isEmpty() ? name
                             : prefix.join(QStringLiteral("::")) + QStringLiteral("::") + name;
        const auto it = m_byQualifiedName.constFind(candidate);
        if (it != m_byQualifiedName.constEnd())
            return pick(*it, file);
    }
    if (file) {
        for (const QString &ns : file->usingNamespaces) {
            const auto it =
                m_byQualifiedName.constFind(normalizedName(ns) + QStringLiteral("::") + name);
            if (it != m_byQualifiedName.constEnd())
                return pick(*it, file);
        }
    }
    return -1;
}

CppClassIndex::Root CppClassIndex::rootOf(const QString &base, const ClassInfo &info,
                                          int depth) const
{
    const QString b = normalizedName(base);
    if (b == QLatin1String("rclcpp::Node"))
        return Root::Node;
    if (b == QLatin1String("rclcpp_lifecycle::LifecycleNode"))
        return Root::Lifecycle;
    if (depth < 4) {
        const QString alias = info.cls->aliases.value(b, info.file->aliases.value(b));
        if (!alias.isEmpty() && normalizedName(alias) != b)
            return rootOf(alias, info, depth + 1);
    }
    const bool inRclcpp = info.cls->scope.value(0) == QLatin1String("rclcpp");
    const bool inLifecycle = info.cls->scope.value(0) == QLatin1String("rclcpp_lifecycle");
    if (b == QLatin1String("Node") &&
        (inRclcpp || info.file->usingNamespaces.contains(QStringLiteral("rclcpp"))))
        return Root::Node;
    if (b == QLatin1String("LifecycleNode") &&
        (inLifecycle || info.file->usingNamespaces.contains(QStringLiteral("rclcpp_lifecycle"))))
        return Root::Lifecycle;
    return Root::None;
}

void CppClassIndex::decideNode(int index, std::vector<int> &state)
{
    // 0 = unvisited, 1 = in progress (a cycle means "not through this path"), 2 = done.
    if (state[size_t(index)] != 0)
        return;
    state[size_t(index)] = 1;
    ClassInfo &info = m_classes[size_t(index)];
    for (const QString &base : info.cls->bases) {
        const Root root = rootOf(base, info);
        if (root != Root::None) {
            info.node = true;
            info.lifecycle = info.lifecycle || root == Root::Lifecycle;
        }
    }
    for (int b : std::as_const(info.projectBases)) {
        decideNode(b, state);
        const ClassInfo &base = m_classes[size_t(b)];
        if (base.node) {
            info.node = true;
            info.lifecycle = info.lifecycle || base.lifecycle;
        }
    }
    state[size_t(index)] = 2;
}

QList<int> CppClassIndex::lineage(int index) const
{
    QList<int> out{index};
    for (qsizetype i = 0; i < out.size() && out.size() < 64; ++i)
        for (int b : m_classes[size_t(out[i])].projectBases)
            if (!out.contains(b))
                out.append(b);
    return out;
}

} // namespace rosarch
