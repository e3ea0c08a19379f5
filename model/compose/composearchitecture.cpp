#include "compose/composearchitecture.h"
#include "compose/architecturechecks.h"
#include "compose/composer.h"

#include <QtConcurrent/QtConcurrentRun>

#include <atomic>

namespace rosarch {

Architecture composeArchitecture(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                                 const StageControl &control,
                                 const QHash<QString, QString> &renamed)
{
    // One progression for the stage over the systems and the launch files' own classifiers,
    // which are composed at the same time (on a pool thread): each finished launch-file
    // instance counts one, whichever part it belongs to.
    const int all = int(launch.instances.size() + launch.classifierInstances.size());
    std::atomic<int> done{0};
    StageControl part = control;
    if (control.progressed)
        part.progressed = [&done, all, progressed = control.progressed](
                              int, int, const QString &what) { progressed(++done, all, what); };
    // The classifiers do not depend on the systems' composites nor on their checks.
    QFuture<Architecture> classifiers;
    if (!launch.classifierInstances.isEmpty())
        classifiers = QtConcurrent::run([&nodes, &launch, &part, &renamed] {
            LaunchDependencies alone;
            alone.instances = launch.classifierInstances;
            alone.nodes = launch.classifierNodes;
            return Composer::run(nodes, alone, part, renamed);
        });
    Architecture arch = Composer::run(nodes, launch, part, renamed);
    if (!arch.canceled)
        arch.diagnostics += ArchitectureChecks::run(arch, nodes, launch); // after its own notes
    if (classifiers.isValid()) {
        // Taken even when canceled: the lambda refers to this frame.
        Architecture alone = classifiers.result();
        arch.canceled = arch.canceled || alone.canceled;
        if (!arch.canceled)
            for (Composite &c : alone.composites)
                if (c.parentId.isEmpty())
                    arch.classifiers.append(std::move(c));
    }
    return arch;
}

} // namespace rosarch
