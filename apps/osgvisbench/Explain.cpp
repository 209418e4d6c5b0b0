// SPDX-License-Identifier: MIT
#include "Explain.h"

#include <algorithm>
#include <cmath>
#include <ostream>

namespace osgVis::bench
{
namespace
{
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
    out.occluders = apps::reportOccluders(extracted);
    out.mode = mode;
    const double diagonal = glm::length(scene.bounds().extent());

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
    out << "\nexplain (why culling does or does not work on this model):\n";
    apps::writeOccluderReport(out, e.occluders);
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
