// SPDX-License-Identifier: MIT
#include "BoxCover.h"

#include <algorithm>

namespace osgVis::core
{
bool boxCoveredBy(const Aabb& box, const std::vector<Aabb>& boxes)
{
    if (box.empty())
        return true;
    std::vector<double> cuts[3];
    for (int a = 0; a < 3; ++a)
    {
        cuts[a] = {box.min[a], box.max[a]};
        for (const Aabb& b : boxes)
            for (double c : {b.min[a], b.max[a]})
                if (c > box.min[a] && c < box.max[a])
                    cuts[a].push_back(c);
        std::sort(cuts[a].begin(), cuts[a].end());
        cuts[a].erase(std::unique(cuts[a].begin(), cuts[a].end()), cuts[a].end());
    }
    // A box flat along an axis has one piece there, at its coordinate.
    auto centres = [&](int a)
    {
        std::vector<double> out;
        for (std::size_t i = 0; i + 1 < cuts[a].size(); ++i)
            out.push_back(0.5 * (cuts[a][i] + cuts[a][i + 1]));
        if (out.empty())
            out.push_back(cuts[a].front());
        return out;
    };
    const std::vector<double> xs = centres(0), ys = centres(1), zs = centres(2);
    for (double x : xs)
        for (double y : ys)
            for (double z : zs)
            {
                const Vec3 p(x, y, z);
                if (std::none_of(boxes.begin(), boxes.end(), [&](const Aabb& b) { return b.contains(p); }))
                    return false;
            }
    return true;
}
} // namespace osgVis::core
