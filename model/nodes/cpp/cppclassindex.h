#pragma once

#include "nodes/cpp/cppfacts.h"

#include <QHash>
#include <QList>
#include <vector>

namespace rosarch {

/// All classes of the analysed C++ files, with their member functions attached (inline and
/// out-of-line) and the ROS node question answered transitively through project base classes.
class CppClassIndex
{
public:
    struct FunctionRef
    {
        const CppFileFacts *file = nullptr;
        const CppFunction *function = nullptr;
    };

    struct ClassInfo
    {
        const CppFileFacts *file = nullptr;
        const CppClass *cls = nullptr;
        QList<FunctionRef> functions; ///< inline members first, then out-of-line ones by file
        QList<int> projectBases;      ///< direct bases found in the workspace
        bool node = false;
        bool lifecycle = false;
    };

    explicit CppClassIndex(const QList<CppFileFacts> &files);

    int size() const { return int(m_classes.size()); }
    const ClassInfo &at(int index) const { return m_classes[size_t(index)]; }

    /// Resolves a class name as written from a scope (namespaces and classes, outermost
    /// first) in a file, the way C++ name lookup would; -1 when not in the workspace.
    int lookup(const QString &written, const QStringList &fromScope,
               const CppFileFacts *file) const;

    /// The one workspace class with this unqualified name, -1 when none or several.
    int uniqueBySimpleName(const QString &name) const
    {
        const QList<int> found = m_bySimpleName.value(name);
        return found.size() == 1 ? found.front() : -1;
    }

    /// Functions that are members of no class in the workspace (main, helpers, ...).
    const QList<FunctionRef> &freeFunctions() const { return m_freeFunctions; }

    /// The class a function belongs to, -1 for a free function.
    int ownerOf(const CppFunction *function) const { return m_owner.value(function, -1); }

    /// The given class and all its project bases, nearest first (no duplicates).
    QList<int> lineage(int index) const;

private:
    enum class Root
    {
        None,
        Node,
        Lifecycle
    };
    Root rootOf(const QString &base, const ClassInfo &info, int depth = 0) const;
    void decideNode(int index, std::vector<int> &state);
    int pick(const QList<int> &candidates, const CppFileFacts *file) const;

    std::vector<ClassInfo> m_classes;
    QHash<QString, QList<int>> m_byQualifiedName;
    QHash<QString, QList<int>> m_bySimpleName;
    QList<FunctionRef> m_freeFunctions;
    QHash<const CppFunction *, int> m_owner;
};

} // namespace rosarch
