#include "launch/classifierruns.h"
#include "core/rosnames.h"

#include <QHash>
#include <QThreadPool>

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <vector>

namespace rosarch {

namespace {

const QString kPrefix = QStringLiteral("c");

/// `id` ("<kind><number>") with its number moved up by `by`; any other text as it is.
QString shifted(const QString &id, const QString &kind, qsizetype by)
{
    if (by == 0 || !id.startsWith(kind))
        return id;
    bool ok = false;
    const qlonglong number = QStringView(id).mid(kind.size()).toLongLong(&ok);
    return ok ? kind + QString::number(number + by) : id;
}

} // namespace

struct ClassifierRuns::State
{
    enum class Step
    {
        Waiting,
        Running,
        Done,
        Taken ///< finish() runs it, or took its run
    };
    struct Item
    {
        QString file;
        Step step = Step::Waiting;
        Run run;
    };

    State(const Workspace &w, const AtomicNodeList &n, LaunchExecutor::Loader l,
          const StageControl &c, qsizetype b)
        : workspace(w), nodes(n), loader(std::move(l)), control(c), budget(b)
    {
    }

    /// The executor the pool threads copy, made (or set) before they begin.
    const LaunchExecutor &prototypeOr(const LaunchExecutor *warm)
    {
        if (!prototype) {
            if (warm)
                prototype.emplace(*warm);
            else
                prototype.emplace(workspace, nodes, loader, nullptr);
            prototype->setIdPrefix(kPrefix);
            prototype->setOutput(nullptr); // each run sets its own
        }
        return *prototype;
    }

    const Workspace &workspace;
    const AtomicNodeList &nodes;
    const LaunchExecutor::Loader loader;
    std::optional<LaunchExecutor> prototype;
    const StageControl &control;
    const qsizetype budget;
    std::mutex mutex;
    std::condition_variable changed;
    std::vector<Item> items;
    QHash<QString, qsizetype> byFile;
    qsizetype next = 0; ///< no item before it is waiting
    qsizetype made = 0; ///< instances the runs made: past the budget, the pool stops
    int running = 0;    ///< items running on pool threads
    bool stopped = false;
};

ClassifierRuns::ClassifierRuns(const Workspace &workspace, const AtomicNodeList &nodes,
                               LaunchExecutor::Loader loader, const StageControl &control,
                               qsizetype budget)
    : m_state(std::make_shared<State>(workspace, nodes, std::move(loader), control, budget))
{
}

ClassifierRuns::~ClassifierRuns()
{
    stop();
}

ClassifierRuns::Run ClassifierRuns::runFile(LaunchExecutor &executor, const StageControl &control,
                                            const QString &file)
{
    Run run;
    if (control.isCanceled())
        return run;
    run.ran = true;
    executor.setOutput(&run.made);
    executor.setUnfoundContainers(&run.unfound);
    const FileWork work(control, file);
    if (!work.skip(&run.made.diagnostics))
        executor.runRoot(file, {}, QLatin1String(RosNames::kClassifierScope));
    executor.setOutput(nullptr);
    executor.setUnfoundContainers(nullptr);
    return run;
}

void ClassifierRuns::work(const std::shared_ptr<State> &state)
{
    State &s = *state;
    std::optional<LaunchExecutor> executor;
    std::unique_lock lock(s.mutex);
    for (;;) {
        while (s.next < qsizetype(s.items.size()) && s.items[s.next].step != State::Step::Waiting)
            ++s.next;
        // Past the budget, what finish() still needs it runs itself.
        if (s.stopped || s.next == qsizetype(s.items.size()) || s.made > s.budget)
            break;
        const qsizetype at = s.next;
        s.items[at].step = State::Step::Running;
        const QString file = s.items[at].file;
        ++s.running;
        lock.unlock();
        if (!executor)
            executor.emplace(*s.prototype);
        Run run = runFile(*executor, s.control, file);
        lock.lock();
        s.made += run.made.instances.size() + run.made.nodes.size();
        s.items[at].run = std::move(run);
        s.items[at].step = State::Step::Done;
        --s.running;
        s.changed.notify_all();
    }
}

void ClassifierRuns::start(const QStringList &files, const LaunchExecutor *warm)
{
    State &s = *m_state;
    qsizetype added = 0;
    {
        const std::lock_guard lock(s.mutex);
        s.prototypeOr(warm);
        for (const QString &f : files)
            if (!s.byFile.contains(f)) {
                s.byFile.insert(f, qsizetype(s.items.size()));
                s.items.push_back({f, State::Step::Waiting, {}});
                ++added;
            }
        s.next = 0;
    }
    // The caller works too (on the system's runs, then on these).
    QThreadPool *pool = QThreadPool::globalInstance();
    const qsizetype threads = std::min<qsizetype>(added, std::max(1, pool->maxThreadCount() - 1));
    for (qsizetype i = 0; i < threads; ++i)
        pool->start([state = m_state] { work(state); });
}

LaunchExecutor &ClassifierRuns::executor(const LaunchExecutor *warm)
{
    if (!m_executor) {
        const std::lock_guard lock(m_state->mutex);
        m_executor.emplace(warm ? *warm : m_state->prototypeOr(nullptr));
        m_executor->setIdPrefix(kPrefix);
    }
    return *m_executor;
}

void ClassifierRuns::runWaiting(const QStringList &files, const LaunchExecutor *warm)
{
    // From the end of the list, while the pool threads work from its start: this thread waits
    // the least for runs it needs first.
    State &s = *m_state;
    std::unique_lock lock(s.mutex);
    for (auto f = files.crbegin(); f != files.crend(); ++f) {
        const auto it = s.byFile.constFind(*f);
        if (it == s.byFile.cend() || s.items[*it].step != State::Step::Waiting)
            continue;
        if (s.stopped || s.made > s.budget || s.control.isCanceled())
            return;
        const qsizetype at = *it;
        s.items[at].step = State::Step::Running;
        lock.unlock();
        Run run = runFile(executor(warm), s.control, *f);
        lock.lock();
        s.made += run.made.instances.size() + run.made.nodes.size();
        s.items[at].run = std::move(run);
        s.items[at].step = State::Step::Done;
        s.changed.notify_all();
    }
}

ClassifierRuns::Run ClassifierRuns::take(const QString &file, const LaunchExecutor *warm)
{
    State &s = *m_state;
    std::unique_lock lock(s.mutex);
    const auto it = s.byFile.constFind(file);
    State::Item *item = it == s.byFile.cend() ? nullptr : &s.items[*it];
    if (!item || item->step == State::Step::Waiting) {
        if (item)
            item->step = State::Step::Taken;
        lock.unlock();
        Run run = runFile(executor(warm), s.control, file);
        lock.lock();
        s.made += run.made.instances.size() + run.made.nodes.size();
        return run;
    }
    const qsizetype at = *it; // items may have moved while waiting
    s.changed.wait(lock, [&] { return s.items[at].step != State::Step::Running; });
    s.items[at].step = State::Step::Taken;
    return std::move(s.items[at].run);
}

void ClassifierRuns::stop()
{
    State &s = *m_state;
    std::unique_lock lock(s.mutex);
    s.stopped = true;
    // The runs begun use the workspace and the loader, which live no longer than this object.
    s.changed.wait(lock, [&] { return s.running == 0; });
}

void ClassifierRuns::append(LaunchDependencies *merged, Run &run)
{
    const QString instanceKind = kPrefix + QStringLiteral("lf");
    const QString nodeKind = kPrefix + QStringLiteral("n");
    const qsizetype instances = merged->instances.size();
    const qsizetype nodes = merged->nodes.size();
    const auto instance = [&](const QString &id) { return shifted(id, instanceKind, instances); };
    const auto node = [&](const QString &id) { return shifted(id, nodeKind, nodes); };
    std::vector<bool> named(run.made.nodes.size(), false); // containers named, not found
    for (const LaunchExecutor::UnfoundContainer &u : std::as_const(run.unfound))
        for (qsizetype k = u.first; k < u.end; ++k)
            named[k] = true;
    for (LaunchFileInstance &i : run.made.instances) {
        i.id = instance(i.id);
        i.parentId = instance(i.parentId);
        for (QString &id : i.nodes)
            id = node(id);
        for (QString &id : i.includedLaunchFiles)
            id = instance(id);
        for (QStringList &ids : i.namespaces)
            for (QString &id : ids)
                id = id.startsWith(instanceKind) ? instance(id) : node(id);
        merged->instances.append(std::move(i));
    }
    for (qsizetype k = 0; k < run.made.nodes.size(); ++k) {
        NodeInstance &n = run.made.nodes[k];
        n.id = node(n.id);
        n.launchFileId = instance(n.launchFileId);
        if (!named[k])
            n.container = node(n.container);
        merged->nodes.append(std::move(n));
    }
    // One executor would have found these containers among the nodes of the files before.
    for (const LaunchExecutor::UnfoundContainer &u : std::as_const(run.unfound)) {
        const LaunchExecutor::ContainerName name(u.target, u.nameSpace);
        for (qsizetype j = nodes - 1; j >= 0; --j)
            if (name.matches(merged->nodes.at(j))) {
                for (qsizetype k = u.first; k < u.end; ++k)
                    merged->nodes[nodes + k].container = merged->nodes.at(j).id;
                break;
            }
    }
}

void ClassifierRuns::finish(const QStringList &files, LaunchDependencies *out,
                            const LaunchExecutor *warm)
{
    State &s = *m_state;
    bool begun = false;
    {
        const std::lock_guard lock(s.mutex);
        begun = !s.items.empty();
    }
    if (!begun)
        start(files, warm);
    runWaiting(files, warm);
    LaunchDependencies alone;
    for (const QString &file : files) {
        if (s.control.isCanceled()) {
            stop();
            return;
        }
        if (alone.instances.size() + alone.nodes.size() > s.budget) {
            Diagnostic d;
            d.code = QStringLiteral("launch-evaluation-limit");
            d.message = QStringLiteral("Analysing each launch file on its own for its diagram "
                                       "stopped after %1 instances; the diagrams of %2 and later "
                                       "files show them as included by the system.")
                            .arg(s.budget)
                            .arg(file);
            d.evidence = Evidence::startOf(file);
            out->diagnostics.append(d);
            break;
        }
        Run run = take(file, warm);
        if (!run.ran) { // canceled
            stop();
            return;
        }
        append(&alone, run);
    }
    stop();
    out->classifierInstances = std::move(alone.instances);
    out->classifierNodes = std::move(alone.nodes);
}

} // namespace rosarch
