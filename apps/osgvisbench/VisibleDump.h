// SPDX-License-Identifier: MIT
#pragma once
// --dump-visible DIR: the OSG side of the comparison with osgvisrawgl (docs/visapi.md, "A renderer
// that is not OSG"). Every module-chain mode culls the scene as a VisibilityGroup holding the model
// extracts it (extractScene with the default options, triangles kept) over the walk's views, and
// DIR/<mode>.visible gets one line per view with the sorted canonical identities of the visible
// objects (apps/common/GltfIdentity.h); DIR/objects.txt gets every object's identity, flags, triangle
// count, world bounds (%.17g) and an FNV-1a hash of its world triangles' bits, so that differing sets
// can be traced to the extraction.
#include "BenchMode.h"
#include "BenchOptions.h"

#include <ostream>
#include <vector>

namespace osgVis::bench
{
// Throws UsageError for a mode that is no module chain (osg, osg-oq, exact), std::runtime_error when
// the folder or a file cannot be written. Prints one line per file written.
void writeVisibleDumps(const BenchOptions& options, const std::vector<BenchMode>& modes, std::ostream& out);
} // namespace osgVis::bench
