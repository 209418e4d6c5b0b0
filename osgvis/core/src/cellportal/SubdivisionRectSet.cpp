// SPDX-License-Identifier: MIT
// Rectangle-set algebra for cell subdivision: union area by a sweep over u with a segment tree over
// v (coverage counts), and subtraction on the grid of all rectangle edges, whose free grid cells are
// merged into maximal row runs and those into vertical stacks of equal runs.
#include "SubdivisionRectSet.h"

#include <algorithm>
#include <map>
#include <utility>

namespace osgVis::core
{
namespace
{
// Segment tree over the elementary v intervals: covered length under a coverage count.
class CoverageTree
{
public:
    explicit CoverageTree(std::vector<double> edges)
        : _edges(std::move(edges)), _count(4 * _edges.size(), 0), _length(4 * _edges.size(), 0.0)
    {
    }

    void add(double lo, double hi, int delta)
    {
        const std::size_t a = std::size_t(std::lower_bound(_edges.begin(), _edges.end(), lo) - _edges.begin());
        const std::size_t b = std::size_t(std::lower_bound(_edges.begin(), _edges.end(), hi) - _edges.begin());
        if (a < b)
            update(1, 0, _edges.size() - 1, a, b, delta);
    }
    double covered() const { return _length[1]; }

private:
    // Node covers elementary intervals [lo, hi) (edges lo .. hi).
    void update(std::size_t node, std::size_t lo, std::size_t hi, std::size_t a, std::size_t b, int delta)
    {
        if (b <= lo || hi <= a)
            return;
        if (a <= lo && hi <= b)
            _count[node] += delta;
        else
        {
            const std::size_t mid = (lo + hi) / 2;
            update(2 * node, lo, mid, a, b, delta);
            update(2 * node + 1, mid, hi, a, b, delta);
        }
        if (_count[node] > 0)
            _length[node] = _edges[hi] - _edges[lo];
        else if (hi - lo == 1)
            _length[node] = 0.0;
        else
            _length[node] = _length[2 * node] + _length[2 * node + 1];
    }

    std::vector<double> _edges;
    std::vector<int> _count;
    std::vector<double> _length;
};

// Sorted grid lines from `lo` to `hi`: `cuts` inside, lines closer than `tolerance` to the previous
// kept one dropped, the last line moved onto `hi`. Empty when the span is not wider than tolerance.
std::vector<double> gridLines(double lo, double hi, std::vector<double> cuts, double tolerance)
{
    std::vector<double> lines;
    if (!(hi - lo > tolerance))
        return lines;
    std::sort(cuts.begin(), cuts.end());
    lines.push_back(lo);
    for (double c : cuts)
    {
        if (c > lo && c < hi && c - lines.back() > tolerance)
            lines.push_back(c);
    }
    if (hi - lines.back() > tolerance)
        lines.push_back(hi);
    else
        lines.back() = hi; // note: the first line is lo and hi - lo > tolerance, so size stays >= 2
    return lines;
}

// Index range [first, last) of the grid intervals inside [lo, hi] grown by tolerance.
std::pair<std::size_t, std::size_t> coveredIntervals(const std::vector<double>& lines, double lo, double hi,
                                                     double tolerance)
{
    const auto first = std::lower_bound(lines.begin(), lines.end(), lo - tolerance);
    const auto end = std::upper_bound(lines.begin(), lines.end(), hi + tolerance);
    const std::size_t a = std::size_t(first - lines.begin());
    const std::size_t b = end == lines.begin() ? 0 : std::size_t(end - lines.begin()) - 1;
    return {a, std::max(a, b)};
}
} // namespace

double unionArea(const std::vector<AxialRect>& rects)
{
    struct Event
    {
        double u;
        int delta;
        double vMin, vMax;
    };
    std::vector<Event> events;
    std::vector<double> vEdges;
    for (const AxialRect& r : rects)
    {
        if (r.empty())
            continue;
        events.push_back({r.uMin, +1, r.vMin, r.vMax});
        events.push_back({r.uMax, -1, r.vMin, r.vMax});
        vEdges.push_back(r.vMin);
        vEdges.push_back(r.vMax);
    }
    if (events.empty())
        return 0.0;
    std::sort(vEdges.begin(), vEdges.end());
    vEdges.erase(std::unique(vEdges.begin(), vEdges.end()), vEdges.end());
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.u < b.u; });

    CoverageTree tree(std::move(vEdges));
    double area = 0.0;
    double lastU = events.front().u;
    for (const Event& e : events)
    {
        area += tree.covered() * (e.u - lastU);
        lastU = e.u;
        tree.add(e.vMin, e.vMax, e.delta);
    }
    return area;
}

std::vector<AxialRect> subtractRects(const AxialRect& region, const std::vector<AxialRect>& holes, double tolerance)
{
    std::vector<double> uCuts, vCuts;
    for (const AxialRect& h : holes)
    {
        uCuts.push_back(h.uMin);
        uCuts.push_back(h.uMax);
        vCuts.push_back(h.vMin);
        vCuts.push_back(h.vMax);
    }
    const std::vector<double> us = gridLines(region.uMin, region.uMax, std::move(uCuts), tolerance);
    const std::vector<double> vs = gridLines(region.vMin, region.vMax, std::move(vCuts), tolerance);
    std::vector<AxialRect> out;
    if (us.size() < 2 || vs.size() < 2)
        return out;

    const std::size_t nu = us.size() - 1, nv = vs.size() - 1;
    std::vector<char> covered(nu * nv, 0);
    for (const AxialRect& h : holes)
    {
        const auto [i0, i1] = coveredIntervals(us, h.uMin, h.uMax, tolerance);
        const auto [j0, j1] = coveredIntervals(vs, h.vMin, h.vMax, tolerance);
        for (std::size_t j = j0; j < j1; ++j)
            std::fill(covered.begin() + std::ptrdiff_t(j * nu + i0), covered.begin() + std::ptrdiff_t(j * nu + i1), 1);
    }

    auto emit = [&](std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1)
    {
        AxialRect r = region;
        r.uMin = us[i0];
        r.uMax = us[i1];
        r.vMin = vs[j0];
        r.vMax = vs[j1];
        out.push_back(r);
    };
    // Open stacks of equal row runs: (i0, i1) → first row.
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> open;
    for (std::size_t j = 0; j <= nv; ++j)
    {
        std::map<std::pair<std::size_t, std::size_t>, std::size_t> next;
        if (j < nv)
        {
            for (std::size_t i = 0; i < nu;)
            {
                if (covered[j * nu + i])
                {
                    ++i;
                    continue;
                }
                std::size_t end = i;
                while (end < nu && !covered[j * nu + end])
                    ++end;
                const auto run = std::make_pair(i, end);
                const auto it = open.find(run);
                next.emplace(run, it == open.end() ? j : it->second);
                if (it != open.end())
                    open.erase(it);
                i = end;
            }
        }
        for (const auto& [run, firstRow] : open)
            emit(run.first, run.second, firstRow, j);
        open = std::move(next);
    }
    std::sort(out.begin(), out.end(), [](const AxialRect& a, const AxialRect& b)
              { return a.vMin != b.vMin ? a.vMin < b.vMin : a.uMin < b.uMin; });
    return out;
}
} // namespace osgVis::core
