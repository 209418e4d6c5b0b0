// SPDX-License-Identifier: MIT
#pragma once
// Internal: the mask module's state, shared by its query (MaskModule.cpp) and its scene, built and
// changed (MaskScene.cpp).
#include <osgVis/core/mask/MaskModule.h>

#include "MaskOccluderGroups.h"
#include "MaskOccluderSelection.h"
#include "MaskProjection.h"

#include <osgVis/core/mask/MaskRasterizer.h>
#include <osgVis/core/occluders/OccluderBuilder.h>
#include <osgVis/core/occluders/OccluderSelector.h>
#include <osgVis/core/spatial/SceneHierarchyChoice.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace osgVis::core
{
struct MaskModule::Impl
{
    const Scene* scene = nullptr;
    MaskKdTree tree; // empty while the renderer's hierarchy serves
    // The renderer's hierarchy when it serves instead of the tree, as recorded at setScene. Each
    // box is judged on its own, so siblings may come in any order.
    SceneHierarchyChoice sceneHierarchy{false};
    // Marks on the renderer's hierarchy: its index's objects()[first, end) hidden until `until` (a
    // node's subtree, or one object).
    struct RangeMark
    {
        std::uint32_t first, end;
        double until;
    };
    std::vector<RangeMark> rangeMarks;
    bool hasObjects() const
    {
        return sceneHierarchy.walks() ? !sceneHierarchy.index().objects().empty() : !tree.empty();
    }
    std::vector<OccluderPolygon> polygons;
    std::vector<std::vector<std::uint32_t>> polygonsOf; // per object (a union of several: each of them)
    std::vector<std::uint32_t> selectedIn;              // per polygon: critical frame that selected it last
    std::uint32_t criticalCount = 0;
    std::vector<std::uint32_t> statedPolygons;          // stated occluders without an owner object
    std::vector<std::uint8_t> usable;                   // per object: may be an occluder
    std::vector<std::uint8_t> moving;                   // per object: dynamic or moved: tested every frame
    std::vector<std::uint8_t> present;
    std::vector<ObjectId> movingIds;

    // Files polygon i under its owner, or under every object of a union.
    void addToOwners(std::uint32_t i)
    {
        const OccluderPolygon& polygon = polygons[i];
        if (polygon.parts.empty())
        {
            if (polygon.owner < polygonsOf.size())
                polygonsOf[polygon.owner].push_back(i);
            return;
        }
        for (ObjectId part : polygon.parts)
            if (part < polygonsOf.size())
                polygonsOf[part].push_back(i);
    }

    OcclusionMask mask;
    MaskRasterScratch scratch;
    MaskGroups groups;
    MaskProjection projection; // of the latest critical frame

    struct CriticalFrame
    {
        Vec3 eye{0.0};
        double time = 0.0;
        double deltaMin = 0.0, deltaMax = 0.0; // over the marks it wrote
        std::vector<ObjectId> occluders;
    };
    // Critical frames whose stamps may still be alive, oldest first. Slots of expired frames are
    // reused, so their occluder lists keep their buffers (a warm critical frame allocates nothing).
    class CriticalFrames
    {
    public:
        bool empty() const { return _count == 0; }
        const CriticalFrame& front() const { return _slots[_first]; }
        void popFront() { ++_first, --_count; }
        void clear() { _first = _count = 0; }
        const CriticalFrame* begin() const { return _slots.data() + _first; }
        const CriticalFrame* end() const { return begin() + _count; }
        CriticalFrame& pushBack()
        {
            if (_first + _count == _slots.size())
            {
                if (_first == 0)
                    _slots.emplace_back();
                else // swaps move whole buffers: nothing is allocated or freed
                    std::rotate(_slots.begin(), _slots.begin() + _first, _slots.end()), _first = 0;
            }
            return _slots[_first + _count++];
        }

    private:
        std::vector<CriticalFrame> _slots;
        std::size_t _first = 0, _count = 0;
    };
    CriticalFrames alive;
    // Buffers of the critical frame, kept between frames.
    MaskSelectionScratch selection;
    std::vector<ObjectId> occluders, restingOn;
    std::vector<std::uint32_t> selected, nodeStack;
    std::vector<std::pair<double, std::uint32_t>> rankedPolygons;
    std::uint64_t markBudget = 0;               // work units marking may spend this critical frame
    std::vector<std::uint32_t> groupOrder;      // the order groups are rasterized in
    bool haveMask = false;
    View criticalView;
    Vec3 criticalDirection{0.0};
    double delta = 0.0, validUntil = 0.0, criticalAfter = 0.0;
    double shift = 0.0;     // Δ in mask pixels
    double maskShift = 0.0; // what targets grow by: Δ for `mask`, 0 for `mask-approx`
    // δ per 8 × 8 pixel tile: the least δ of the groups whose rectangle reaches the tile, so a
    // target hidden by pixels there stays hidden for eyes that far away.
    static constexpr std::uint32_t kTile = 8;
    std::uint32_t tilesX = 0, tilesY = 0;
    std::vector<double> tileDelta;
    // Marks of the latest critical frame: (stamp, objects), for the time of the next one.
    std::vector<std::pair<double, std::uint32_t>> stamps;
    bool occluderGone = false;

    Statistics statistics;
    DebugRecord* debug = nullptr;

    void forgetMarks()
    {
        tree.clearMarks();
        rangeMarks.clear();
        alive.clear();
        haveMask = false;
    }
};
} // namespace osgVis::core
