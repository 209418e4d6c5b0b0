// SPDX-License-Identifier: MIT
#include "OccluderReport.h"

#include <osgVis/core/occluders/OccluderBuilder.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <set>

namespace osgVis::apps
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
} // namespace

OccluderReport reportOccluders(const ExtractedScene& extracted)
{
    const core::Scene& scene = extracted.scene;
    OccluderReport out;
    out.objects = scene.objects.size();
    out.triangles = scene.totalTriangles();
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
    return out;
}

void writeOccluderReport(std::ostream& out, const OccluderReport& r)
{
    out << "  " << r.objects << " objects, " << r.triangles << " triangles; " << r.occluderObjects << " objects give "
        << r.occluderPolygons << " occluder polygons (welded, coplanar triangles merged)\n"
        << "  objects that are no occluder, by reason:" << (r.notOccluders.empty() ? " none" : "") << "\n";
    for (const auto& [reason, count] : r.notOccluders)
        out << "    " << count << "  " << reason << "\n";
    out << "  objects whose bounds span more than half the model's diagonal: " << r.hugeBounds << "\n";
}
} // namespace osgVis::apps
