// SPDX-License-Identifier: MIT
// moveObjects: a frame whose only change is some transforms' matrices (what animations do) places
// the objects below them again, instead of extracting the whole subgraph again.
#include "Extraction.h"
#include "OccluderEligibility.h"

#include <osg/Transform>

#include <algorithm>

namespace osgVis
{
namespace
{
// `moved` sorted.
bool below(const osg::NodePath& path, const std::vector<const osg::Node*>& moved)
{
    return std::any_of(path.begin(), path.end(),
                       [&](const osg::Node* node) { return std::binary_search(moved.begin(), moved.end(), node); });
}

// What a copy of the scene cannot express by moving objects: those are placed by a fresh extraction.
bool placedOnlyByExtraction(const ExtractedScene& scene)
{
    return scene.clusteredDrawables != 0 || !scene.pagedNodes.empty() || !scene.scene.occluders.empty() ||
           !scene.scene.cells.empty() || !scene.scene.portals.empty();
}
} // namespace

osg::ref_ptr<ExtractedScene> moveObjects(const ExtractedScene& previous, const std::vector<const osg::Node*>& moved,
                                         const ExtractionOptions& options)
{
    if (placedOnlyByExtraction(previous))
        return nullptr;
    std::vector<const osg::Node*> sorted(moved);
    std::sort(sorted.begin(), sorted.end());
    osg::ref_ptr<ExtractedScene> out = new ExtractedScene(previous);
    out->changes.clear();
    std::vector<core::ObjectId> movedIds;
    std::vector<core::Triangle> triangles;
    for (core::ObjectId id = 0; id < out->refs.size(); ++id)
    {
        ObjectRef& ref = out->refs[id];
        if (!ref.drawable || !below(ref.path, sorted))
            continue;
        core::SceneObject& object = out->scene.objects[id];
        ref.world = osg::computeLocalToWorld(ref.path);
        triangles.clear();
        const bool clockwiseFront = options.keepTriangles && occluderEligibility(ref.path).clockwiseFront;
        const DrawablePlacement placed =
            placeDrawable(*ref.drawable, ref.world, clockwiseFront, options.keepTriangles ? &triangles : nullptr);
        if (options.keepTriangles && placed.stored != object.triangleCount)
            return nullptr; // a triangle turned non-finite, or back: the triangle ranges would shift
        std::copy(triangles.begin(), triangles.end(), out->scene.triangles.begin() + object.firstTriangle);
        object.bounds = placed.bounds;
        if (placed.nonFinite)
            object.flags |= core::OBJECT_ALWAYS_VISIBLE;
        movedIds.push_back(id);
    }
    if (!movedIds.empty())
        out->changes.push_back({core::SceneChange::Kind::Moved, std::move(movedIds)});
    out->replaces = &previous;
    return out;
}
} // namespace osgVis
