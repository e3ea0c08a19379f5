#include "launch/includereach.h"

namespace rosarch {

void IncludeReach::note(const LaunchAction &include, const IncludeTarget &target, bool active,
                        bool pathUndecided, const QStringList &launchFiles, QStringList *includes,
                        QStringList *conditional)
{
    if (!target.file.isEmpty() && active)
        includes->append(target.file);
    else if (!target.file.isEmpty() && conditional)
        conditional->append(target.file);
    if (!conditional || target.shareRelative.isEmpty() ||
        !(include.path.findsPackageByConfiguration() || pathUndecided))
        return;
    for (const QString &f : launchFiles)
        if (f.endsWith(QLatin1Char('/') + target.shareRelative) && f != target.file)
            conditional->append(f);
}

} // namespace rosarch
