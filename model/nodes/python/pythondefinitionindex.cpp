#include "nodes/python/pythondefinitionindex.h"

#include <QStringList>

#include <algorithm>
#include <functional>

namespace rosarch {

namespace {
/// The written name and a definition's qualified name agree on their trailing segments.
bool alignedSuffix(const QStringList &a, const QStringList &b)
{
    const qsizetype n = std::min(a.size(), b.size());
    if (n < 2)
        return false;
    for (qsizetype i = 1; i <= n; ++i)
        if (a.at(a.size() - i) != b.at(b.size() - i))
            return false;
    return true;
}

int findIn(const QString &target, const QHash<QString, int> &exact,
           const QHash<QString, QList<int>> &byName, const std::function<QString(int)> &qualified)
{
    const auto it = exact.constFind(target);
    if (it != exact.constEnd())
        return it.value();
    const QStringList segs = target.split(QLatin1Char('.'));
    if (segs.size() < 2)
        return -1;
    int found = -1;
    for (int id : byName.value(segs.last())) {
        if (!alignedSuffix(segs, qualified(id).split(QLatin1Char('.'))))
            continue;
        if (found >= 0)
            return -1; // ambiguous
        found = id;
    }
    return found;
}
} // namespace

PythonDefinitionIndex::PythonDefinitionIndex(const QList<PythonModuleFacts> &modules)
    : m_modules(modules)
{
    for (int m = 0; m < m_modules.size(); ++m) {
        const PythonModuleFacts &module = m_modules.at(m);
        for (int c = 0; c < module.classes.size(); ++c) {
            const int id = int(m_classRefs.size());
            m_classRefs.emplace_back(m, c);
            if (!m_classes.contains(module.classes.at(c).qualifiedName))
                m_classes.insert(module.classes.at(c).qualifiedName, id);
            m_classesByName[module.classes.at(c).name].append(id);
        }
        for (int f = 0; f < module.functions.size(); ++f) {
            const PythonFunctionFacts &function = module.functions.at(f);
            const int id = int(m_functionRefs.size());
            m_functionRefs.emplace_back(m, f);
            if (function.name.isEmpty())
                continue; // the module-level statements
            const QString q = module.modulePath + QLatin1Char('.') + function.name;
            if (!m_functions.contains(q))
                m_functions.insert(q, id);
            m_functionsByName[function.name].append(id);
        }
    }
}

const PythonClassFacts &PythonDefinitionIndex::classFacts(int id) const
{
    const auto &[m, c] = m_classRefs.at(size_t(id));
    return m_modules.at(m).classes.at(c);
}

const PythonModuleFacts &PythonDefinitionIndex::classModule(int id) const
{
    return m_modules.at(m_classRefs.at(size_t(id)).first);
}

const PythonFunctionFacts &PythonDefinitionIndex::functionFacts(int id) const
{
    const auto &[m, f] = m_functionRefs.at(size_t(id));
    return m_modules.at(m).functions.at(f);
}

const PythonModuleFacts &PythonDefinitionIndex::functionModule(int id) const
{
    return m_modules.at(m_functionRefs.at(size_t(id)).first);
}

int PythonDefinitionIndex::findClass(const QString &target) const
{
    return findIn(target, m_classes, m_classesByName,
                  [this](int id) { return classFacts(id).qualifiedName; });
}

int PythonDefinitionIndex::findFunction(const QString &target) const
{
    return findIn(target, m_functions, m_functionsByName, [this](int id) {
        return functionModule(id).modulePath + QLatin1Char('.') + functionFacts(id).name;
    });
}

QList<int> PythonDefinitionIndex::projectBases(int id) const
{
    QList<int> out;
    for (const QString &base : classFacts(id).baseTargets) {
        const int b = findClass(base);
        if (b >= 0 && b != id)
            out.append(b);
    }
    return out;
}

} // namespace rosarch
