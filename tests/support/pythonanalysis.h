#pragma once

// The Python analyzer on the fixture workspaces, and ports as comparable text.
#include "nodes/python/pythonnodeanalyzer.h"
#include "support/testsupport.h"
#include "workspace/workspacescanner.h"

#include <QStringList>

namespace rosarch::test::python {

inline QString range(const Evidence &e)
{
    return QStringLiteral("%1:%2:%3-%4:%5")
        .arg(e.file)
        .arg(e.line)
        .arg(e.column)
        .arg(e.endLine)
        .arg(e.endColumn);
}

/// Every field of a port on one line, so that a comparison shows exactly what differs.
inline QString portLine(const Port &p)
{
    QStringList s{portKindName(p.kind), p.name, p.type, QStringLiteral("cb=") + p.callback,
                  nameOriginName(p.nameOrigin)};
    if (!p.nameExpression.isEmpty())
        s << QStringLiteral("expr=") + p.nameExpression;
    if (!p.parameter.isEmpty())
        s << QStringLiteral("param=") + p.parameter;
    if (!p.guard.isEmpty())
        s << QStringLiteral("guard=[%1]").arg(p.guard);
    if (!p.guardParameter.isEmpty())
        s << QStringLiteral("guard_param=") + p.guardParameter;
    if (!p.via.isEmpty())
        s << QStringLiteral("via=") + p.via;
    if (p.inherited)
        s << QStringLiteral("inherited");
    s << QStringLiteral("@") + range(p.evidence);
    return s.join(QLatin1Char(' '));
}

inline QStringList portLines(const AtomicNode &n)
{
    QStringList out;
    for (const Port &p : n.ports)
        out << portLine(p);
    return out;
}

inline LanguageAnalysis analyzeFixture(const QString &name)
{
    const Workspace ws = WorkspaceScanner::scan(dataDir(name + QStringLiteral("/ws")));
    return PythonNodeAnalyzer(ws).analyze();
}

inline const AtomicNode *node(const LanguageAnalysis &a, const QString &qualifiedName)
{
    for (const AtomicNode &n : a.nodes)
        if (n.qualifiedName == qualifiedName)
            return &n;
    return nullptr;
}

inline QStringList qualifiedNames(const LanguageAnalysis &a)
{
    QStringList out;
    for (const AtomicNode &n : a.nodes)
        out << n.qualifiedName;
    return out;
}

} // namespace rosarch::test::python
