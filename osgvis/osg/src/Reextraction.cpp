// SPDX-License-Identifier: MIT
// reextractScene: a fresh extraction renumbered onto the ids of the previous one.
#include <osgVis/SceneExtractor>

#include "CullTree.h"
#include "Extraction.h"

#include <algorithm>

namespace osgVis
{
namespace
{
bool sameVec(const core::Vec3& a, const core::Vec3& b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

bool sameBounds(const core::Aabb& a, const core::Aabb& b)
{
    return (a.empty() && b.empty()) || (sameVec(a.min, b.min) && sameVec(a.max, b.max));
}

bool samePolygon(const core::ConvexPolygon& a, const core::ConvexPolygon& b)
{
    return a.size() == b.size() &&
           std::equal(a.vertices().begin(), a.vertices().end(), b.vertices().begin(), sameVec);
}

bool sameTriangle(const core::Triangle& a, const core::Triangle& b)
{
    return a.a == b.a && a.b == b.b && a.c == b.c;
}

// What object changes cannot express: if any of it differs, modules must rebuild.
bool sameStaticStructure(const core::Scene& a, const core::Scene& b)
{
    if (a.occluders.size() != b.occluders.size() || a.cells.size() != b.cells.size() ||
        a.portals.size() != b.portals.size())
        return false;
    for (std::size_t i = 0; i < a.occluders.size(); ++i)
        if (a.occluders[i].owner != b.occluders[i].owner || !samePolygon(a.occluders[i].polygon, b.occluders[i].polygon))
            return false;
    for (std::size_t i = 0; i < a.cells.size(); ++i)
        if (a.cells[i].name != b.cells[i].name || !sameBounds(a.cells[i].bounds, b.cells[i].bounds))
            return false;
    for (std::size_t i = 0; i < a.portals.size(); ++i)
        if (a.portals[i].cellA != b.portals[i].cellA || a.portals[i].cellB != b.portals[i].cellB ||
            !samePolygon(a.portals[i].polygon, b.portals[i].polygon))
            return false;
    return true;
}

bool sameObject(const core::Scene& a, const core::SceneObject& oa, const core::Scene& b, const core::SceneObject& ob)
{
    if (!sameBounds(oa.bounds, ob.bounds) || oa.triangleCount != ob.triangleCount || oa.flags != ob.flags)
        return false;
    // Triangles are compared only where both extractions kept them (counts match already).
    const bool keptA = oa.firstTriangle + std::size_t(oa.triangleCount) <= a.triangles.size();
    const bool keptB = ob.firstTriangle + std::size_t(ob.triangleCount) <= b.triangles.size();
    if (!keptA || !keptB || a.triangles.empty() || b.triangles.empty())
        return true;
    return std::equal(a.triangles.begin() + oa.firstTriangle, a.triangles.begin() + oa.firstTriangle + oa.triangleCount,
                      b.triangles.begin() + ob.firstTriangle, sameTriangle);
}

void addChange(std::vector<core::SceneChange>& changes, core::SceneChange::Kind kind, std::vector<core::ObjectId> ids)
{
    if (ids.empty())
        return;
    std::sort(ids.begin(), ids.end());
    changes.push_back({kind, std::move(ids)});
}
} // namespace

osg::ref_ptr<ExtractedScene> reextractScene(osg::Node& root, const ExtractedScene& previous,
                                            const ExtractionOptions& options)
{
    osg::ref_ptr<ExtractedScene> fresh = extractSceneQuietly(root, options);
    warnOversizedTiles(*fresh, &previous);
    // note: clusters are renumbered by a plain extraction (a fallback) rather than matched one by one:
    // a drawable's layout may change with its geometry.
    if (!sameStaticStructure(previous.scene, fresh->scene) || previous.clusteredDrawables != 0 ||
        fresh->clusteredDrawables != 0)
        return fresh;

    const core::Scene& before = previous.scene;
    const std::size_t previousCount = before.objects.size();
    osg::ref_ptr<ExtractedScene> out = new ExtractedScene;
    out->scene.triangles = std::move(fresh->scene.triangles); // firstTriangle indices stay valid
    out->scene.occluders = std::move(fresh->scene.occluders);
    out->scene.cells = std::move(fresh->scene.cells);
    out->scene.portals = std::move(fresh->scene.portals);
    out->scene.objects.resize(previousCount);
    out->refs.resize(previousCount);

    // Fresh id → stable id.
    std::vector<core::ObjectId> stableId(fresh->scene.objects.size(), core::InvalidObject);
    std::vector<bool> kept(previousCount, false);
    std::vector<core::ObjectId> inserted, moved, removed;
    for (core::ObjectId id = 0; id < fresh->scene.objects.size(); ++id)
    {
        const ObjectRef& ref = fresh->refs[id];
        core::ObjectId stable = previous.find(ref.node(), ref.path);
        if (stable == core::InvalidObject || kept[stable])
        {
            stable = static_cast<core::ObjectId>(out->scene.objects.size());
            out->scene.objects.emplace_back();
            out->refs.emplace_back();
            inserted.push_back(stable);
        }
        else
        {
            kept[stable] = true;
            if (!sameObject(before, before.objects[stable], out->scene, fresh->scene.objects[id]))
                moved.push_back(stable);
        }
        stableId[id] = stable;
        out->scene.objects[stable] = std::move(fresh->scene.objects[id]);
        out->scene.objects[stable].id = stable;
        out->refs[stable] = std::move(fresh->refs[id]);
    }
    for (core::ObjectId id = 0; id < previousCount; ++id)
    {
        if (kept[id])
            continue;
        core::SceneObject& slot = out->scene.objects[id];
        slot.id = id;
        slot.name = before.objects[id].name; // reports may still name it
        if (!previous.removed(id))
            removed.push_back(id);
    }
    for (core::ObjectId id = 0; id < out->scene.objects.size(); ++id)
        if (!out->removed(id))
            out->indexObject(id);
    for (core::OccluderCandidate& occluder : out->scene.occluders)
        if (occluder.owner != core::InvalidObject)
            occluder.owner = stableId[occluder.owner];

    out->oversizedTiles = std::move(fresh->oversizedTiles);
    out->occluderMasks = std::move(fresh->occluderMasks);
    for (const PagedNodeRecord& record : fresh->pagedNodes)
        out->pagedNodes.push_back({stableId[record.placeholder], record.children, record.childNodes});

    out->childRanges.reserve(fresh->childRanges.size());
    for (const ChildRange& range : fresh->childRanges)
    {
        ChildRange mapped;
        mapped.closed = range.closed;
        // note: a fresh extraction's ranges are always contiguous
        for (core::ObjectId id = range.first; id < range.end; ++id)
            mapped.ids.push_back(stableId[id]);
        std::sort(mapped.ids.begin(), mapped.ids.end());
        if (!mapped.ids.empty())
        {
            mapped.first = mapped.ids.front();
            mapped.end = mapped.ids.back() + 1;
        }
        out->childRanges.push_back(std::move(mapped));
    }

    // Order matters to ModuleChain only in that a later kind wins for an id; the kinds are disjoint.
    addChange(out->changes, core::SceneChange::Kind::Removed, std::move(removed));
    addChange(out->changes, core::SceneChange::Kind::Moved, std::move(moved));
    addChange(out->changes, core::SceneChange::Kind::Inserted, std::move(inserted));
    out->replaces = &previous;
    assignTileKeys(*out);
    out->cullTree = buildCullTree(*out, root);
    return out;
}
} // namespace osgVis
