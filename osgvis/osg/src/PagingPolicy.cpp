// SPDX-License-Identifier: MIT
#include "PagingPolicy.h"

#include "Extraction.h"

#include <osg/Geometry>
#include <osg/NodeVisitor>
#include <osg/PagedLOD>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace osgVis
{
namespace
{
double distanceToBox(const osg::Vec3d& eye, const core::Aabb& box)
{
    if (box.empty())
        return 0.0;
    double squared = 0.0;
    for (int axis = 0; axis < 3; ++axis)
    {
        const double below = box.min[axis] - eye[axis], above = eye[axis] - box.max[axis];
        const double gap = std::max({below, above, 0.0});
        squared += gap * gap;
    }
    return std::sqrt(squared);
}

// The box's extent on screen, in normalized device coordinates; the whole screen when it reaches
// behind the eye.
struct ScreenRect
{
    double x0 = -1, y0 = -1, x1 = 1, y1 = 1;
    bool overlaps(const ScreenRect& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

ScreenRect screenRect(const core::Aabb& box, const osg::Matrixd& rootToClip)
{
    ScreenRect rect{2, 2, -2, -2};
    for (unsigned corner = 0; corner < 8; ++corner)
    {
        const osg::Vec4d p = osg::Vec4d(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                                        corner & 4 ? box.max.z : box.min.z, 1.0) * rootToClip;
        if (p.w() <= 1e-9)
            return ScreenRect{};
        rect.x0 = std::min(rect.x0, p.x() / p.w());
        rect.x1 = std::max(rect.x1, p.x() / p.w());
        rect.y0 = std::min(rect.y0, p.y() / p.w());
        rect.y1 = std::max(rect.y1, p.y() / p.w());
    }
    return rect;
}

// Whether the segment a + t·d, t in [0, 1], meets the box (slabs).
bool segmentMeetsBox(const osg::Vec3d& a, const osg::Vec3d& d, const core::Aabb& box)
{
    double enter = 0.0, leave = 1.0;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (std::abs(d[axis]) < 1e-12)
        {
            if (a[axis] < box.min[axis] || a[axis] > box.max[axis])
                return false;
            continue;
        }
        double t0 = (box.min[axis] - a[axis]) / d[axis], t1 = (box.max[axis] - a[axis]) / d[axis];
        if (t0 > t1)
            std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
        if (enter > leave)
            return false;
    }
    return true;
}

// The bytes a loaded tile's geometry holds in memory: its arrays and index lists, counted once per
// use (what a budget of kept tiles is about; textures and GL copies are not seen here).
struct GeometryBytes : osg::NodeVisitor
{
    GeometryBytes() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Geometry& geometry) override
    {
        osg::Geometry::ArrayList arrays;
        geometry.getArrayList(arrays);
        for (const osg::Array* array : arrays)
            bytes += array ? array->getTotalDataSize() : 0;
        for (const osg::ref_ptr<osg::PrimitiveSet>& primitives : geometry.getPrimitiveSetList())
            if (const osg::DrawElements* elements = primitives ? primitives->getDrawElements() : nullptr)
                bytes += elements->getTotalDataSize();
    }
    std::uint64_t bytes = 0;
};

std::uint64_t loadedBytes(osg::Group& node)
{
    GeometryBytes counter;
    for (unsigned child = 0; child < node.getNumChildren(); ++child)
        node.getChild(child)->accept(counter);
    return counter.bytes;
}

// What PagedLOD::traverse would have stamped had the cull entered it.
void renewStamps(osg::PagedLOD& node, const osg::FrameStamp& frameStamp)
{
    node.setFrameNumberOfLastTraversal(frameStamp.getFrameNumber());
    for (unsigned child = 0; child < node.getNumChildren(); ++child)
    {
        node.setTimeStamp(child, frameStamp.getReferenceTime());
        node.setFrameNumber(child, frameStamp.getFrameNumber());
    }
}
} // namespace

PagingFigures applyPagingPolicy(const PagingOptions& options, const ExtractedScene& scene, core::VisibleSet& visible,
                                const osg::Matrixd& rootToEye, const osg::Matrixd& projection,
                                const osg::FrameStamp* frameStamp, std::size_t residentBudget,
                                std::vector<unsigned>& lastVisible)
{
    const osg::Vec3d eye = osg::Matrixd::inverse(rootToEye).getTrans();
    const osg::Matrixd rootToClip = rootToEye * projection;
    PagingFigures figures;
    if (scene.pagedNodes.empty())
        return figures;
    const unsigned frame = frameStamp ? frameStamp->getFrameNumber() : 0u;
    if (lastVisible.size() < scene.scene.objects.size())
        lastVisible.resize(scene.scene.objects.size(), ~0u);

    std::vector<std::pair<double, core::ObjectId>> waiting; // visible, nothing loaded: would request
    std::vector<std::pair<unsigned, osg::PagedLOD*>> recent; // hidden, loaded, seen lately: frames since
    unsigned visibleLoaded = 0;
    for (const PagedNodeRecord& record : scene.pagedNodes)
    {
        const core::ObjectId id = record.placeholder;
        osg::Group& node = *scene.refs[id].paged;
        if (visible.test(id))
        {
            lastVisible[id] = frame;
            if (node.getNumChildren() == 0)
                waiting.emplace_back(distanceToBox(eye, scene.scene.objects[id].bounds), id);
            else
                ++visibleLoaded;
            continue;
        }
        auto* paged = dynamic_cast<osg::PagedLOD*>(&node);
        if (paged && frameStamp && paged->getNumChildren() > 0 && lastVisible[id] != ~0u &&
            frame - lastVisible[id] <= options.keepFrames)
            recent.emplace_back(frame - lastVisible[id], paged);
    }
    // The pager's own budget of loaded paged nodes holds, and the bytes budget when set: the most
    // recently seen are kept first, each in turn while it fits (a large tile seen lately does not
    // keep smaller ones out).
    const std::size_t room = residentBudget > visibleLoaded ? residentBudget - visibleLoaded : 0;
    if (recent.size() > room || options.keepBytes != 0)
    {
        std::sort(recent.begin(), recent.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::size_t kept = 0;
        std::uint64_t bytes = 0;
        for (std::size_t i = 0; i < recent.size() && kept < room; ++i)
        {
            if (options.keepBytes != 0)
            {
                const std::uint64_t size = loadedBytes(*recent[i].second);
                if (bytes + size > options.keepBytes)
                    continue;
                bytes += size;
            }
            recent[kept++] = recent[i];
        }
        recent.resize(kept);
    }
    for (const auto& kept : recent)
        renewStamps(*kept.second, *frameStamp);
    figures.keptFresh = unsigned(recent.size());
    // note: a node with no child loaded draws nothing, so leaving it out this frame hides nothing;
    // it only delays its request behind those of nearer tiles that may hide it once loaded. A tile
    // no nearer waiting tile covers on screen is asked for at once.
    if (options.requestsPerFrame == 0 || waiting.size() <= options.requestsPerFrame)
        return figures;
    std::sort(waiting.begin(), waiting.end());
    std::vector<ScreenRect> nearer;
    nearer.reserve(waiting.size());
    unsigned covered = 0; // requested although a nearer waiting tile covers them
    for (const auto& [distance, id] : waiting)
    {
        const ScreenRect rect = screenRect(scene.scene.objects[id].bounds, rootToClip);
        const bool behindNearer =
            std::any_of(nearer.begin(), nearer.end(), [&](const ScreenRect& r) { return r.overlaps(rect); });
        nearer.push_back(rect);
        if (!behindNearer)
            continue;
        if (covered < options.requestsPerFrame)
            ++covered;
        else
        {
            visible.clear(id);
            ++figures.deferred;
        }
    }
    return figures;
}
unsigned prefetchAhead(const ExtractedScene& scene, const core::VisibleSet& visible, const osg::Vec3d& eye,
                       const osg::Vec3d& step, unsigned frames, const core::VisibleSet* seenAhead,
                       osg::NodeVisitor::DatabaseRequestHandler& pager, const osg::FrameStamp* frameStamp)
{
    if (frames == 0 || step.length2() == 0.0 || !frameStamp)
        return 0;
    const osg::Vec3d ahead = step * double(frames);
    unsigned requested = 0;
    for (const PagedNodeRecord& record : scene.pagedNodes)
    {
        const core::ObjectId id = record.placeholder;
        auto* paged = dynamic_cast<osg::PagedLOD*>(scene.refs[id].paged.get());
        // note: a visible one is entered, and asks for itself at its own priority
        if (!paged || visible.test(id) || paged->getNumChildren() != 0 || paged->getNumFileNames() == 0 ||
            !((seenAhead && seenAhead->test(id)) || segmentMeetsBox(eye, ahead, scene.scene.objects[id].bounds)))
            continue;
        osg::NodePath path = scene.refs[id].path; // ends at the node the tile merges into
        pager.requestNodeFile(tileFile(*paged, 0), path, -1.0f, frameStamp, paged->getDatabaseRequest(0),
                              paged->getDatabaseOptions());
        ++requested;
    }
    return requested;
}
} // namespace osgVis
