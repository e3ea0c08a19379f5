#pragma once

#include "site/sitehtml.h"
#include "site/sitemodel.h"

namespace rosarch {

/// The page of one launch file, as analysed on its own with its declared defaults (its
/// classifier, blueprint §1): its diagram, arguments, includes, namespaces and nodes, each with
/// its source line, and the systems it is part of.
class LaunchPage
{
public:
    static SiteFile write(const SiteContext &context, const QString &file);
};

} // namespace rosarch
