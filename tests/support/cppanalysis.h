#pragma once

// The C++ analyzer on the fixture workspaces, and ports as comparable text.
#include "analysistext.h"
#include "nodes/cpp/cppnodeanalyzer.h"
#include "support/testsupport.h"
#include "workspace/workspacescanner.h"

#include <QFile>
#include <QTemporaryDir>

namespace rosarch::test {

// The C++ analyzer on the fixture workspaces tests/data/cpp_*/ws.
namespace cpp {

inline LanguageAnalysis analyzeCase(const QString &name)
{
    const Workspace ws = WorkspaceScanner::scan(dataDir(name + QStringLiteral("/ws")));
    return CppNodeAnalyzer(ws).analyze();
}

inline const AtomicNode *findNode(const LanguageAnalysis &a, const QString &className)
{
    for (const AtomicNode &n : a.nodes)
        if (n.className == className)
            return &n;
    return nullptr;
}

inline QStringList classNames(const LanguageAnalysis &a)
{
    QStringList names;
    for (const AtomicNode &n : a.nodes)
        names << n.packageName + QLatin1Char('/') + n.className;
    return names;
}

// "publisher chatter std_msgs/msg/String cb= origin=literal expr= param= guard= gp= via=
// @file:line"
inline QString describe(const Port &p)
{
    return AnalysisText::port(p);
}

inline QStringList describePorts(const AtomicNode &n)
{
    QStringList out;
    for (const Port &p : n.ports)
        out << describe(p);
    return out;
}

// "name origin [parameter]" of each port of `n`, in order.
inline QStringList resolvedPortNames(const AtomicNode &n)
{
    QStringList out;
    for (const Port &p : n.ports)
        out << p.name + QLatin1Char(' ') + nameOriginName(p.nameOrigin) +
                   (p.parameter.isEmpty() ? QString() : QLatin1Char(' ') + p.parameter);
    return out;
}

// The analysis of a workspace holding one C++ file of package `pkg`.
inline LanguageAnalysis analyzeFile(const QTemporaryDir &dir, const QString &name,
                                    const QByteArray &content)
{
    QFile f(dir.filePath(name));
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(content);
    f.close();
    Workspace ws;
    ws.root = dir.path();
    ws.files.append({name, QStringLiteral("pkg"), SourceFile::Language::Cpp, f.size()});
    return CppNodeAnalyzer(ws).analyze();
}

} // namespace cpp

} // namespace rosarch::test
