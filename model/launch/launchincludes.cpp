// LaunchExecutor's includes: running one (its arguments, scope and condition), and where its
// evaluated path points (a workspace launch file, a package outside the workspace, or nothing).
#include "launch/includereach.h"
#include "launch/launchexecutor.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

namespace rosarch {

namespace {
constexpr int kMaxIncludeDepth = 40;
} // namespace

IncludeTarget LaunchExecutor::resolveInclude(const QString &rawPath, const QString &fromFile) const
{
    const QString key = rawPath + QChar(0) + fromFile;
    const auto known = m_includeTargets.constFind(key);
    if (known != m_includeTargets.cend())
        return *known;
    const IncludeTarget t = findInclude(rawPath, fromFile);
    m_includeTargets.insert(key, t);
    return t;
}

IncludeTarget LaunchExecutor::findInclude(const QString &rawPath, const QString &fromFile) const
{
    IncludeTarget t;
    QString path = rawPath.trimmed();
    static const QRegularExpression share(
        QStringLiteral("^\\$\\(find-pkg-(?:share|prefix) ([^)\\s]+)\\)/*(.*)$"));
    const auto m = share.match(path);
    auto existing = [&](const QString &rel) {
        const auto it = m_isFile.constFind(rel);
        if (it != m_isFile.cend())
            return *it;
        const QString absolute = m_workspace.absolutePath(rel);
        const bool file = !absolute.isEmpty() && QFileInfo(absolute).isFile();
        m_isFile.insert(rel, file);
        return file;
    };
    if (m.hasMatch()) {
        t.package = m.captured(1);
        QString rest = m.captured(2);
        if (rest.startsWith(QLatin1String("share/") + t.package + QLatin1Char('/')))
            rest = rest.mid(7 + t.package.size()); // find-pkg-prefix + share/<pkg>/...
        t.shareRelative = rest;
        if (!m_packagePaths.contains(t.package)) {
            t.external = true;
            return t;
        }
        const QString pkgPath = m_packagePaths.value(t.package);
        const QString direct = pkgPath.isEmpty() ? rest : pkgPath + QLatin1Char('/') + rest;
        if (existing(direct)) {
            t.file = direct;
            return t;
        }
        // Installed share layouts rarely mirror the source tree: match on the longest suffix.
        const QString name = QFileInfo(rest).fileName();
        int best = -1;
        for (const SourceFile &f : m_workspace.files) {
            if (f.package != t.package || QFileInfo(f.path).fileName() != name)
                continue;
            int score = 0;
            const QStringList a = f.path.split(QLatin1Char('/'));
            const QStringList b = rest.split(QLatin1Char('/'));
            while (score < a.size() && score < b.size() &&
                   a[a.size() - 1 - score] == b[b.size() - 1 - score])
                ++score;
            if (score > best) {
                best = score;
                t.file = f.path;
            }
        }
        return t;
    }
    // Relative to the including file (ThisLaunchFileDir, or a bare relative path).
    if (!path.startsWith(QLatin1Char('/'))) {
        const QString rel = QFileInfo(path).isRelative() && !existing(path)
                                ? launchFileDir(fromFile) + QLatin1Char('/') + path
                                : path;
        const QString clean = QDir::cleanPath(rel);
        if (existing(clean)) {
            t.file = clean;
            t.package = m_filePackages.value(clean);
            return t;
        }
    }
    return t;
}

void LaunchExecutor::executeInclude(const LaunchAction &a, Scope &scope, Frame &frame, int depth)
{
    if (!frame.collectOnly && m_budget.overBudget(m_out, a.evidence))
        return;
    QList<Unresolved> found;
    const QString path = evaluate(a.path, scope, frame, &found, a.evidence);
    const bool pathUndecided = !found.isEmpty();
    bool undecided = false;
    const bool active = scope.active && conditionHolds(a, scope, frame, &found, &undecided);
    const IncludeTarget target = resolveInclude(path, frame.file);
    if (frame.collectOnly) {
        IncludeReach::note(a, target, active, pathUndecided, m_out->launchFiles, frame.includes,
                           frame.conditionalIncludes);
        return;
    }
    LaunchFileInstance inst;
    inst.id = (m_idPrefix + QStringLiteral("lf%1")).arg(m_out->instances.size() + 1);
    inst.parentId = m_out->instances[frame.instance].id;
    inst.type = QFileInfo(target.file.isEmpty() ? path : target.file).fileName();
    inst.file = target.file;
    inst.package = target.package;
    inst.external = target.external;
    inst.evidence = a.evidence;
    inst.condition = a.condition.text;
    inst.active = active;
    inst.unresolved = found;
    Scope inner = scope;
    inner.active = active;
    inner.activeByGuess = scope.activeByGuess || undecided;
    for (const auto &[name, value] : a.arguments) {
        const QString n = evaluate(name, scope, frame, &inst.unresolved, a.evidence);
        bool guessed = false;
        const QString v = evaluate(value, scope, frame, &inst.unresolved, a.evidence, &guessed);
        configure(inner, n, v, guessed);
        inst.arguments.append({n, v});
    }
    if (target.external)
        ModelledPorts::forInclude(&inst, target.package, target.shareRelative, scope.nameSpace);
    if (target.file.isEmpty() && !target.external) {
        inst.unresolved.append({QStringLiteral("include"), path, QString(), a.evidence});
    }
    const LaunchFileDescription *d = target.file.isEmpty() ? nullptr : m_load(target.file);
    if (d)
        inst.format = formatName(d->format);
    const bool cycle = !target.file.isEmpty() && frame.chain.contains(target.file);
    if (cycle) {
        inst.unresolved.append(
            {QStringLiteral("cycle"),
             (frame.chain + QStringList{target.file}).join(QStringLiteral(" → ")), QString(),
             a.evidence});
        Diagnostic diag;
        diag.severity = Diagnostic::Severity::Error;
        diag.code = QStringLiteral("include-cycle");
        diag.message =
            QStringLiteral("Include cycle: %1; the repeated include is not followed.")
                .arg((frame.chain + QStringList{target.file}).join(QStringLiteral(" → ")));
        diag.evidence = a.evidence;
        m_out->diagnostics.append(diag);
    }
    const QString parentNs = scope.nameSpace;
    m_out->instances.append(inst);
    const int index = int(m_out->instances.size()) - 1;
    m_out->instances[frame.instance].includedLaunchFiles.append(inst.id);
    addToNamespace(frame.instance, parentNs, inst.id);
    if (!d || cycle)
        return;
    if (depth >= kMaxIncludeDepth || frame.chain.size() >= kMaxIncludeDepth) {
        m_out->instances[index].unresolved.append({QStringLiteral("include"),
                                                   QStringLiteral("include depth limit"), QString(),
                                                   a.evidence});
        return;
    }
    Frame child;
    child.instance = index;
    child.file = target.file;
    child.chain = frame.chain + QStringList{target.file};
    execute(d->actions, inner, child, depth + 1);
}

} // namespace rosarch
