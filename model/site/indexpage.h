#pragma once

#include "site/sitehtml.h"
#include "site/sitemodel.h"

namespace rosarch {

/// The site's entry pages: the index (systems with their counts, packages), a page per
/// package, the search page, and the search index the script reads.
class IndexPage
{
public:
    static SiteFile index(const SiteContext &context);
    static SiteFile package(const SiteContext &context, const RosPackage &package);
    static SiteFile search(const SiteContext &context);
    /// `assets/search-index.js`: the names a person searches for (systems, node classes and
    /// node names, topics, services, actions, launch files, packages) as JSON, handed to the
    /// site's script (a script file, not a fetched one, so that search works from file://).
    static SiteFile searchIndex(const SiteModel &model);
};

} // namespace rosarch
