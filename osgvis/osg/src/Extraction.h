// SPDX-License-Identifier: MIT
#pragma once
// Internal: the extraction both extractScene and reextractScene run, and the warning about loaded
// tiles that reach outside their paged node's stated bound, which each new tile gets once.
#include <osgVis/SceneExtractor>

namespace osgVis
{
// extractScene without its warnings.
osg::ref_ptr<ExtractedScene> extractSceneQuietly(osg::Node& root, const ExtractionOptions& options);

// Warns about each of `scene`'s oversized tiles that `previous` (may be null) did not list.
void warnOversizedTiles(const ExtractedScene& scene, const ExtractedScene* previous);
} // namespace osgVis
