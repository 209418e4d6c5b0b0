// SPDX-License-Identifier: MIT
// Area-angle occluder choice over an octree of eye cells (after Coorg & Teller's dynamic
// selection): per cell, the polygons that can look large enough from somewhere inside it.
#include <osgVis/core/occluders/OccluderSelector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace osgVis::core
{
namespace
{
// Caps on the tree so that large, dense scenes cannot exhaust memory: at most this many cells, and
// list entries over all cells at most max(MinListBudget, ListBudgetPerPolygon × polygons). The
// longest lists split first, so the budget goes where select() would scan the most.
constexpr std::size_t MaxCells = std::size_t(1) << 16;
constexpr std::size_t MinListBudget = std::size_t(1) << 20;
constexpr std::size_t ListBudgetPerPolygon = 16;

// Rounding in the bound must never drop a polygon that reaches the threshold exactly.
constexpr double BoundSlack = 1.0 + 1e-9;

// Largest areaAngle `polygon` can have from any eye in `box`. With D from the eye to the centroid,
// A·|N·D|/|D|³ ≤ A·min(1/r², h/r³), r the smallest |D| over the box (box-to-centroid distance)
// and h the largest |N·D| there (reached at a corner, as N·D is linear in the eye).
double areaAngleBound(const OccluderPolygon& polygon, const Aabb& box)
{
    const Vec3& c = polygon.centroid;
    const Vec3& n = polygon.plane.normal;
    const Vec3 nearest = glm::clamp(c, box.min, box.max);
    const double r2 = glm::dot(c - nearest, c - nearest);

    // N·D = N·c − N·eye; its range over the box comes from the corners picked by N's signs.
    const Vec3 low(n.x >= 0.0 ? box.min.x : box.max.x, n.y >= 0.0 ? box.min.y : box.max.y,
                   n.z >= 0.0 ? box.min.z : box.max.z);
    const Vec3 high(n.x >= 0.0 ? box.max.x : box.min.x, n.y >= 0.0 ? box.max.y : box.min.y,
                    n.z >= 0.0 ? box.max.z : box.min.z);
    const double nc = glm::dot(n, c);
    const double mostBehind = nc - glm::dot(n, low);   // largest N·D (eye furthest behind)
    const double mostInFront = glm::dot(n, high) - nc; // largest −N·D (eye furthest in front)
    // A one-sided polygon counts only from the side its normal points to (N·D < 0).
    const double h = polygon.oneSided ? std::max(mostInFront, 0.0) : std::max({mostBehind, mostInFront, 0.0});
    if (!(h > 0.0))
        return 0.0;
    if (!(r2 > 0.0))
        return std::numeric_limits<double>::infinity();
    const double r = std::sqrt(r2);
    return polygon.area * std::min(1.0 / r2, h / (r2 * r)) * BoundSlack;
}

const std::vector<std::uint32_t>& emptyList()
{
    static const std::vector<std::uint32_t> empty;
    return empty;
}
} // namespace

double areaAngle(const OccluderPolygon& polygon, const Vec3& eye)
{
    const Vec3 d = polygon.centroid - eye;
    const double distance2 = glm::dot(d, d);
    if (!(distance2 > 0.0) || polygon.plane.distance(eye) == 0.0)
        return 0.0;
    const double facing = glm::dot(polygon.plane.normal, d);
    // N·D < 0: the eye is on the side the normal points to, the only side a one-sided polygon hides from.
    if (polygon.oneSided && !(facing < 0.0))
        return 0.0;
    const double value = polygon.area * std::abs(facing) / (distance2 * std::sqrt(distance2));
    return std::isfinite(value) ? value : 0.0;
}

void OccluderSelector::build(const std::vector<OccluderPolygon>& polygons, const Aabb& region,
                             const OccluderSelectorOptions& options)
{
    _polygons = &polygons;
    _threshold = options.threshold;
    _cells.clear();

    // The root lists every polygon: it also serves eyes outside the region, where no bound over
    // the region's box would hold.
    Cell root;
    root.bounds = region;
    root.polygons.resize(polygons.size());
    for (std::uint32_t i = 0; i < polygons.size(); ++i)
        root.polygons[i] = i;
    _cells.push_back(std::move(root));
    if (region.empty() || !region.finite())
        return;

    const std::size_t listBudget = std::max(MinListBudget, ListBudgetPerPolygon * polygons.size());
    std::size_t listed = polygons.size();
    // Longest list first; equal lengths by cell index, so the tree is the same on every run.
    struct Pending
    {
        std::size_t size;
        std::uint32_t cell, depth;
        bool operator<(const Pending& o) const { return size != o.size ? size < o.size : cell > o.cell; }
    };
    std::priority_queue<Pending> pending;
    pending.push({polygons.size(), 0u, 0u});
    std::vector<std::uint32_t> childLists[8];
    while (!pending.empty())
    {
        const auto [parentSize, index, depth] = pending.top();
        pending.pop();
        // Children never list more than their parent, so 8 × parent bounds what a split adds.
        if (parentSize <= options.maxLeafPolygons || depth >= options.maxDepth || _cells.size() + 8 > MaxCells ||
            listed + 8 * parentSize > listBudget)
            continue;

        const Aabb parent = _cells[index].bounds;
        const Vec3 mid = parent.center();
        Aabb childBounds[8];
        std::size_t childEntries = 0;
        for (int child = 0; child < 8; ++child)
        {
            const Vec3 lo((child & 1) ? mid.x : parent.min.x, (child & 2) ? mid.y : parent.min.y,
                          (child & 4) ? mid.z : parent.min.z);
            const Vec3 hi((child & 1) ? parent.max.x : mid.x, (child & 2) ? parent.max.y : mid.y,
                          (child & 4) ? parent.max.z : mid.z);
            childBounds[child] = Aabb(lo, hi);
            childLists[child].clear();
            for (std::uint32_t p : _cells[index].polygons)
            {
                if (areaAngleBound(polygons[p], childBounds[child]) >= _threshold)
                    childLists[child].push_back(p);
            }
            childEntries += childLists[child].size();
        }
        // A split that leaves every child with the parent's whole list only costs memory.
        const bool helps = std::any_of(std::begin(childLists), std::end(childLists),
                                       [&](const auto& list) { return list.size() < parentSize; });
        if (!helps)
            continue;

        listed += childEntries;
        const std::uint32_t firstChild = std::uint32_t(_cells.size());
        _cells[index].firstChild = firstChild;
        for (int child = 0; child < 8; ++child)
        {
            Cell cell;
            cell.bounds = childBounds[child];
            cell.polygons = childLists[child];
            _cells.push_back(std::move(cell));
            pending.push({childLists[child].size(), firstChild + std::uint32_t(child), depth + 1});
        }
    }
    sortLeafLists();
}

// Each leaf's list, best bound first: a query stops where the bounds fall below what it already has.
// The root keeps index order and no bounds (it serves eyes outside the region, where none holds).
void OccluderSelector::sortLeafLists()
{
    std::vector<std::pair<double, std::uint32_t>> ranked;
    for (std::size_t index = 1; index < _cells.size(); ++index)
    {
        Cell& cell = _cells[index];
        if (cell.firstChild != 0)
            continue;
        ranked.clear();
        for (std::uint32_t p : cell.polygons)
            ranked.push_back({-areaAngleBound((*_polygons)[p], cell.bounds), p});
        std::sort(ranked.begin(), ranked.end());
        cell.metricBounds.clear();
        for (std::size_t i = 0; i < ranked.size(); ++i)
        {
            cell.polygons[i] = ranked[i].second;
            cell.metricBounds.push_back(-ranked[i].first);
        }
    }
}

std::uint32_t OccluderSelector::leafOf(const Vec3& eye) const
{
    if (_cells.empty() || !_cells[0].bounds.contains(eye))
        return 0;
    std::uint32_t index = 0;
    while (_cells[index].firstChild != 0)
    {
        // Same split as build(): the upper half of each axis takes the midpoint itself.
        const Vec3 mid = _cells[index].bounds.center();
        const std::uint32_t child =
            (eye.x >= mid.x ? 1u : 0u) | (eye.y >= mid.y ? 2u : 0u) | (eye.z >= mid.z ? 4u : 0u);
        index = _cells[index].firstChild + child;
    }
    return index;
}

const std::vector<std::uint32_t>& OccluderSelector::potentialOccluders(std::uint32_t leaf) const
{
    return leaf < _cells.size() ? _cells[leaf].polygons : emptyList();
}

const std::vector<double>& OccluderSelector::potentialOccluderBounds(std::uint32_t leaf) const
{
    static const std::vector<double> none;
    return leaf < _cells.size() ? _cells[leaf].metricBounds : none;
}

const Aabb& OccluderSelector::leafBounds(std::uint32_t leaf) const
{
    static const Aabb empty;
    return leaf < _cells.size() ? _cells[leaf].bounds : empty;
}

void OccluderSelector::select(const Vec3& eye, std::uint32_t k, std::vector<std::uint32_t>& out) const
{
    out.clear();
    if (k == 0 || !_polygons || _cells.empty())
        return;
    const std::vector<OccluderPolygon>& polygons = *_polygons;
    // Metrics of the chosen few live on the stack when they fit; beyond that they are recomputed,
    // which keeps select() free of allocation and of shared scratch for any k.
    constexpr std::uint32_t CachedMetrics = 64;
    double cached[CachedMetrics];
    auto metricAt = [&](std::size_t slot)
    { return slot < CachedMetrics ? cached[slot] : areaAngle(polygons[out[slot]], eye); };

    const Cell& cell = _cells[leafOf(eye)];
    for (std::size_t entry = 0; entry < cell.polygons.size(); ++entry)
    {
        // No polygon further down the list can reach the threshold or beat the worst chosen one.
        if (!cell.metricBounds.empty() && (cell.metricBounds[entry] < _threshold ||
                                           (out.size() == k && cell.metricBounds[entry] < metricAt(k - 1))))
            break;
        const std::uint32_t p = cell.polygons[entry];
        const double metric = areaAngle(polygons[p], eye);
        if (!(metric >= _threshold))
            continue;
        // Better means a larger metric, or an equal one and a lower index.
        auto better = [&](double m, std::uint32_t i, std::size_t slot)
        { return m > metricAt(slot) || (m == metricAt(slot) && i < out[slot]); };
        if (out.size() == k && !better(metric, p, k - 1))
            continue;
        std::size_t slot = out.size() < k ? out.size() : k - 1;
        if (out.size() < k)
            out.push_back(p);
        // Shift worse entries down one place.
        while (slot > 0 && better(metric, p, slot - 1))
        {
            out[slot] = out[slot - 1];
            if (slot < CachedMetrics)
                cached[slot] = metricAt(slot - 1);
            --slot;
        }
        out[slot] = p;
        if (slot < CachedMetrics)
            cached[slot] = metric;
    }
}
} // namespace osgVis::core
