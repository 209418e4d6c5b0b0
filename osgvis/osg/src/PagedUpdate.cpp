// SPDX-License-Identifier: MIT
// updatePagedScene: an extraction brought up to date after the pager merged or expired tiles, by
// extracting only the changed paged nodes' new children (docs/paging.md).
#include <osgVis/SceneExtractor>

#include "Extraction.h"

#include <algorithm>
#include <unordered_set>

namespace osgVis
{
namespace
{
// A copy of `previous` that a change may extend: same ids, same triangles, and a fresh lookup table.
osg::ref_ptr<ExtractedScene> copyOf(const ExtractedScene& previous)
{
    osg::ref_ptr<ExtractedScene> out = new ExtractedScene;
    out->scene = previous.scene;
    out->refs = previous.refs;
    out->childRanges = previous.childRanges;
    // note: the tree ends at paged nodes, so their new tiles change none of its nodes but the ids
    // of those above, which hold a paged node and so are never closed: stale, they only keep more
    out->cullTree = previous.cullTree;
    out->pagedNodes = previous.pagedNodes;
    out->oversizedTiles = previous.oversizedTiles;
    out->clusteredDrawables = previous.clusteredDrawables;
    out->occluderMasks = previous.occluderMasks;
    for (core::ObjectId id = 0; id < out->scene.objects.size(); ++id)
        out->indexObject(id);
    return out;
}

// True when `path` runs through `prefix` (root .. paged node) into one of `gone`.
bool below(const osg::NodePath& path, const osg::NodePath& prefix, const std::unordered_set<const osg::Node*>& gone)
{
    return path.size() > prefix.size() && gone.count(path[prefix.size()]) != 0 &&
           std::equal(prefix.begin(), prefix.end(), path.begin());
}

// Empties the slot of an object whose tile was expired (what reextractScene leaves for a gone object).
void empty(ExtractedScene& out, core::ObjectId id)
{
    core::SceneObject& slot = out.scene.objects[id];
    std::string name = slot.name;
    slot = core::SceneObject();
    slot.id = id;
    slot.name = std::move(name);
    out.refs[id] = ObjectRef();
}

// The root's child range holding the paged node at the end of `prefix`, as an explicit id list.
ChildRange* rangeOf(ExtractedScene& out, const osg::NodePath& prefix)
{
    if (prefix.size() < 2 || !prefix.front()->asGroup())
        return nullptr;
    const unsigned index = prefix.front()->asGroup()->getChildIndex(prefix[1]);
    if (index >= out.childRanges.size())
        return nullptr;
    ChildRange& range = out.childRanges[index];
    if (range.ids.empty())
        for (core::ObjectId id = range.first; id < range.end; ++id)
            range.ids.push_back(id);
    return &range;
}
} // namespace

osg::ref_ptr<ExtractedScene> updatePagedScene(const ExtractedScene& previous, const ExtractionOptions& options)
{
    osg::ref_ptr<ExtractedScene> out = copyOf(previous);
    std::vector<core::ObjectId> inserted, removed;
    const std::size_t occluders = out->scene.occluders.size(), cells = out->scene.cells.size(),
                      portals = out->scene.portals.size();
    // note: a merged tile may hold paged nodes of its own, appended to the list while it is walked.
    for (std::size_t r = 0; r < out->pagedNodes.size(); ++r)
    {
        if (out->removed(out->pagedNodes[r].placeholder))
            continue;
        const core::ObjectId placeholder = out->pagedNodes[r].placeholder;
        osg::Group& node = *out->refs[placeholder].paged;
        if (node.getNumChildren() == out->pagedNodes[r].children)
            continue;
        // A bound computed from the loaded children changes with them, and so would the placeholder.
        if (!boundStated(node))
            return nullptr;
        const osg::NodePath prefix = out->refs[placeholder].path;
        std::unordered_set<const osg::Node*> gone;
        for (const osg::ref_ptr<osg::Node>& child : out->pagedNodes[r].childNodes)
            if (!node.containsNode(child.get()))
                gone.insert(child.get());
        ChildRange* range = rangeOf(*out, prefix);
        if (!gone.empty())
            for (core::ObjectId id = 0; id < out->scene.objects.size(); ++id)
                if (!out->removed(id) && below(out->refs[id].path, prefix, gone))
                {
                    empty(*out, id);
                    removed.push_back(id);
                    if (range)
                        range->ids.erase(std::remove(range->ids.begin(), range->ids.end(), id), range->ids.end());
                }
        const auto firstNew = static_cast<core::ObjectId>(out->scene.objects.size());
        std::vector<osg::ref_ptr<osg::Node>> children;
        for (unsigned c = 0; c < node.getNumChildren(); ++c)
        {
            osg::Node* child = node.getChild(c);
            children.push_back(child);
            const auto& known = out->pagedNodes[r].childNodes;
            if (std::find(known.begin(), known.end(), child) == known.end())
                extractBelow(*out, prefix, *child, options);
        }
        checkWithinStatedBound(*out, placeholder, prefix.size() - 1, firstNew);
        for (core::ObjectId id = firstNew; id < out->scene.objects.size(); ++id)
        {
            inserted.push_back(id);
            if (range)
                range->ids.push_back(id);
        }
        out->pagedNodes[r].children = node.getNumChildren();
        out->pagedNodes[r].childNodes = std::move(children);
    }
    // Markers in a merged tile change what object changes cannot describe; so do too many empty slots'
    // triangles, which only a full extraction gives back.
    std::size_t liveTriangles = 0;
    for (const core::SceneObject& object : out->scene.objects)
        liveTriangles += object.triangleCount;
    if (out->scene.occluders.size() != occluders || out->scene.cells.size() != cells ||
        out->scene.portals.size() != portals || out->scene.triangles.size() > 2 * liveTriangles + 1024)
        return nullptr;
    // Paged nodes inside an expired tile are gone with it.
    out->pagedNodes.erase(std::remove_if(out->pagedNodes.begin(), out->pagedNodes.end(),
                                         [&](const PagedNodeRecord& record) { return out->removed(record.placeholder); }),
                          out->pagedNodes.end());
    for (ChildRange& range : out->childRanges)
    {
        std::sort(range.ids.begin(), range.ids.end());
        range.first = range.ids.empty() ? 0 : range.ids.front(); // an empty range is entered, as before
        range.end = range.ids.empty() ? 0 : range.ids.back() + 1;
    }
    std::sort(removed.begin(), removed.end());
    if (!removed.empty())
        out->changes.push_back({core::SceneChange::Kind::Removed, removed});
    if (!inserted.empty())
        out->changes.push_back({core::SceneChange::Kind::Inserted, inserted});
    warnOversizedTiles(*out, &previous);
    out->replaces = &previous;
    assignTileKeys(*out);
    return out;
}
} // namespace osgVis
