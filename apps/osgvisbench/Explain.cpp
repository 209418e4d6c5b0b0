// SPDX-License-Identifier: MIT
#include "Explain.h"

#include <osgVis/core/occluders/OccluderBuilder.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <set>

namespace osgVis::bench
{
namespace
{
double area(const core::Triangle& t)
{
    return 0.5 * glm::length(glm::cross(core::Vec3(t.b - t.a), core::Vec3(t.c - t.a)));
}

// Why an object gives no occluder polygon, in the order the builder's own rules apply.
std::string notOccluderReason(const ExtractedScene& extracted, core::ObjectId id, double minArea)
{
    const core::SceneObject& object = extracted.scene.objects[id];
    if (object.flags & core::OBJECT_ALWAYS_VISIBLE)
        return "always visible (bounds not finite, or placed only at cull time)";
    if (object.flags & core::OBJECT_DYNAMIC)
        return "dynamic (DYNAMIC data variance)";
    if (object.flags & core::OBJECT_TRANSPARENT)
        return "transparent (blending or the transparent bin)";
    if ((object.flags & core::OBJECT_NO_AUTO_OCCLUDER) && !(object.flags & core::OBJECT_OCCLUDER))
    {
        const char* why = whyNotAutomaticOccluder(extracted.refs[id].path);
        return why ? why : "not drawn as a solid surface";
    }
    if ((object.flags & core::OBJECT_CULL_BACK) && (object.flags & core::OBJECT_CULL_FRONT))
        return "both faces culled";
    if (object.triangleCount == 0)
        return "no triangles (lines or points only)";
    double total = 0.0;
    for (std::uint32_t t = object.firstTriangle; t < object.firstTriangle + object.triangleCount; ++t)
        total += area(extracted.scene.triangles[t]);
    if (!(total > 0.0))
        return "degenerate triangles only";
    if (total < minArea)
        return "too small";
    return "no convex coplanar piece large enough (curved, sliver or too small triangles)";
}

std::string neverCulledReason(const core::SceneObject& object, double sceneDiagonal)
{
    if (object.flags & core::OBJECT_ALWAYS_VISIBLE)
        return "always visible (bounds not finite, or placed only at cull time)";
    const double span = glm::length(object.bounds.extent()) / std::max(sceneDiagonal, 1e-300);
    if (span > 0.5)
        return "its bounds span " + std::to_string(int(std::lround(100 * span))) +
               "% of the model's diagonal (one large mesh, or vertices it does not draw)";
    return "never wholly behind the occluders the mode used";
}
} // namespace

Explanation explainScene(const ExtractedScene& extracted, const std::string& mode, const std::vector<core::VisibleSet>& drawn,
                         const std::vector<core::VisibleSet>& hidden)
{
    const core::Scene& scene = extracted.scene;
    Explanation out;
    out.objects = scene.objects.size();
    out.triangles = scene.totalTriangles();
    out.mode = mode;

    const core::OccluderBuildOptions options;
    const std::vector<core::OccluderPolygon> polygons = core::buildOccluderPolygons(scene, options);
    out.occluderPolygons = polygons.size();
    std::set<core::ObjectId> owners;
    for (const core::OccluderPolygon& p : polygons)
        owners.insert(p.owner);
    owners.erase(core::InvalidObject);
    out.occluderObjects = owners.size();
    std::map<std::string, std::size_t> reasons;
    for (const core::SceneObject& object : scene.objects)
        if (!owners.count(object.id))
            ++reasons[notOccluderReason(extracted, object.id, options.minArea)];
    out.notOccluders.assign(reasons.begin(), reasons.end());
    std::sort(out.notOccluders.begin(), out.notOccluders.end(),
              [](const auto& a, const auto& b) { return a.second > b.second; });

    const double diagonal = glm::length(scene.bounds().extent());
    for (const core::SceneObject& object : scene.objects)
        out.hugeBounds += glm::length(object.bounds.extent()) > 0.5 * diagonal;

    for (const core::SceneObject& object : scene.objects)
    {
        std::uint32_t hiddenViews = 0;
        bool everCulled = false;
        for (std::size_t v = 0; v < drawn.size() && v < hidden.size(); ++v)
            if (hidden[v].test(object.id))
            {
                ++hiddenViews;
                everCulled = everCulled || !drawn[v].test(object.id);
            }
        if (hiddenViews == 0 || everCulled)
            continue;
        ++out.neverCulledCount;
        out.neverCulledTriangles += object.triangleCount;
        out.neverCulled.push_back({object.id, object.name, object.triangleCount, hiddenViews,
                                   neverCulledReason(object, diagonal)});
    }
    std::sort(out.neverCulled.begin(), out.neverCulled.end(),
              [](const NeverCulledObject& a, const NeverCulledObject& b)
              { return std::uint64_t(a.triangles) * a.hiddenViews > std::uint64_t(b.triangles) * b.hiddenViews; });
    if (out.neverCulled.size() > 12)
        out.neverCulled.resize(12);
    return out;
}

void writeExplanation(std::ostream& out, const Explanation& e)
{
    out << "\nexplain (why culling does or does not work on this model):\n"
        << "  " << e.objects << " objects, " << e.triangles << " triangles; " << e.occluderObjects
        << " objects give " << e.occluderPolygons << " occluder polygons (welded, coplanar triangles merged)\n"
        << "  objects that are no occluder, by reason:\n";
    for (const auto& [reason, count] : e.notOccluders)
        out << "    " << count << "  " << reason << "\n";
    out << "  objects whose bounds span more than half the model's diagonal: " << e.hugeBounds << "\n";
    if (e.mode.empty())
    {
        out << "  no mode culled anything behind an occluder on this walk\n";
        return;
    }
    out << "  " << e.mode << " never culled " << e.neverCulledCount << " objects (" << e.neverCulledTriangles
        << " triangles) that the oracle found hidden in the frustum in some view"
        << (e.neverCulled.empty() ? "" : "; the largest (triangles x views hidden):") << "\n";
    for (const NeverCulledObject& o : e.neverCulled)
        out << "    #" << o.id << (o.name.empty() ? "" : " '" + o.name + "'") << ": " << o.triangles << " triangles, hidden in "
            << o.hiddenViews << " views: " << o.why << "\n";
}
} // namespace osgVis::bench
