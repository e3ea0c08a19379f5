// What stage 2's executor tests build on: hand-built launch descriptions in a workspace folder
// with real files (include resolution checks them), and summaries of what the executor made.
#pragma once

#include "launch/launchexecutor.h"
#include "support/launchsupport.h"

#include <QTemporaryDir>
#include <QtTest>

namespace rosarch::test::executor {

inline Substitution lit(const QString &s)
{
    return Substitution::literal(s);
}

inline Substitution share(const QString &pkg, const QString &rest)
{
    Substitution s;
    s.kind = Substitution::Kind::FindPackageShare;
    s.parts << lit(pkg);
    Substitution join;
    join.kind = Substitution::Kind::PathJoin;
    join.parts << s << lit(rest);
    return join;
}

inline Evidence at(const QString &file, int line)
{
    return Evidence{file, line, 1, line, 10};
}

inline LaunchAction node(const QString &pkg, const QString &exe, const QString &name, int line)
{
    LaunchAction a;
    a.kind = LaunchAction::Kind::Node;
    a.package = lit(pkg);
    a.executable = lit(exe);
    a.name = lit(name);
    a.evidence = at(QStringLiteral("x"), line);
    return a;
}

inline LaunchAction declare(const QString &name, const QString *value)
{
    LaunchAction a;
    a.kind = LaunchAction::Kind::DeclareArgument;
    a.name = lit(name);
    if (value) {
        a.value = lit(*value);
        a.hasValue = true;
    }
    return a;
}

inline LaunchAction include(const Substitution &path,
                            QList<QPair<Substitution, Substitution>> args = {})
{
    LaunchAction a;
    a.kind = LaunchAction::Kind::Include;
    a.path = path;
    a.arguments = std::move(args);
    return a;
}

/// A workspace folder with real files (include resolution checks them) and hand-built readers.
struct Fixture
{
    QTemporaryDir dir;
    Workspace ws;
    AtomicNodeList nodes;
    QMap<QString, LaunchFileDescription> files;

    Fixture()
    {
        ws.root = dir.path();
        RosPackage pkg;
        pkg.name = QStringLiteral("bringup");
        pkg.path = QStringLiteral("bringup");
        pkg.buildType = QStringLiteral("ament_cmake");
        ws.packages << pkg;
        AtomicNode talker;
        talker.id = QStringLiteral("arc_1");
        talker.className = QStringLiteral("Talker");
        talker.nodeName = QStringLiteral("talker_in_code");
        talker.packageName = QStringLiteral("demo");
        talker.executables << QStringLiteral("talker");
        talker.compileType = AtomicNode::CompileType::Python;
        AtomicNode filter;
        filter.id = QStringLiteral("arc_2");
        filter.className = QStringLiteral("Filter");
        filter.nodeName = QStringLiteral("filter");
        filter.packageName = QStringLiteral("demo");
        filter.plugins << QStringLiteral("demo::Filter");
        nodes.nodes << talker << filter;
    }

    void add(const QString &path, QList<LaunchAction> actions)
    {
        QDir(dir.path()).mkpath(QFileInfo(path).path());
        QFile f(dir.filePath(path));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("# launch\n");
        SourceFile sf;
        sf.path = path;
        sf.package = QStringLiteral("bringup");
        sf.language = SourceFile::Language::Python;
        ws.files << sf;
        LaunchFileDescription d;
        d.file = path;
        d.actions = std::move(actions);
        files.insert(path, d);
    }

    LaunchDependencies run(const QString &root, const QMap<QString, QString> &args = {})
    {
        LaunchDependencies out;
        LaunchExecutor exec(
            ws, nodes,
            [this](const QString &f) -> const LaunchFileDescription * {
                const auto it = files.constFind(f);
                return it == files.constEnd() ? nullptr : &*it;
            },
            &out);
        exec.runRoot(root, args);
        return out;
    }
};

/// "name=value (source line)" for each effective parameter of `n`.
inline QStringList effective(const NodeInstance &n)
{
    QStringList out;
    for (const ParameterSetting &p : n.effectiveParameters)
        out << QStringLiteral("%1=%2 (%3 %4)").arg(p.name, p.value, p.source).arg(p.evidence.line);
    return out;
}

inline LaunchParameter parameterFile(const Substitution &path)
{
    return LaunchParameter{Substitution(), path, true, at(QStringLiteral("x"), 9)};
}

inline LaunchParameter value(const QString &name, const QString &v)
{
    return LaunchParameter{lit(name), lit(v), false, at(QStringLiteral("x"), 8)};
}

inline QStringList summary(const LaunchDependencies &d)
{
    QStringList out;
    for (const NodeInstance &n : d.nodes) {
        QStringList remaps;
        for (const auto &[f, t] : n.remaps)
            remaps << f + QStringLiteral("->") + t;
        QStringList params;
        for (const auto &[k, v] : n.parameters)
            params << k + QLatin1Char('=') + v;
        out << QStringLiteral("%1 %2 %3 class=%4 kind=%5 active=%6 remaps=[%7] params=[%8]")
                   .arg(n.nameSpace, n.nodeName, n.execName, n.className, n.nodeKind)
                   .arg(n.active)
                   .arg(remaps.join(','), params.join(','));
    }
    return out;
}

} // namespace rosarch::test::executor
