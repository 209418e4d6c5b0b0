// SPDX-License-Identifier: MIT
#include "PlanarUnion.h"

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
namespace
{
// An input edge oriented left to right (a.x < b.x), with the ids of its ends.
struct Edge
{
    Point2 a, b;
    std::uint32_t ida, idb;
};

double yAt(const Edge& e, double x)
{
    if (x <= e.a.x)
        return e.a.y;
    if (x >= e.b.x)
        return e.b.y;
    return e.a.y + (x - e.a.x) / (e.b.x - e.a.x) * (e.b.y - e.a.y);
}

// The point of `e` at x, named by the input vertex it is, or by its place on the edge.
UnionCorner cornerAt(const Edge& e, double x)
{
    UnionCorner c;
    if (x == e.a.x)
    {
        c.point = e.a;
        c.id = e.ida;
        return c;
    }
    if (x == e.b.x)
    {
        c.point = e.b;
        c.id = e.idb;
        return c;
    }
    c.t = (x - e.a.x) / (e.b.x - e.a.x);
    c.point = {x, e.a.y + c.t * (e.b.y - e.a.y)};
    c.from = e.ida;
    c.to = e.idb;
    return c;
}

struct Chains
{
    std::vector<Edge> lower, upper; // the convex input's lower and upper boundary, left to right
    double minX = 0.0, maxX = 0.0;
};

// One input's interval across a slab.
struct Span
{
    const Edge *lo, *hi;
    double lo0, lo1, loM, hi0, hi1, hiM;
    std::uint32_t source;
};

// A run of trapezoids whose lower and upper boundaries each stay one straight segment.
struct Chain
{
    double x0 = 0.0, x1 = 0.0;
    const Edge *firstLo = nullptr, *firstHi = nullptr, *lastLo = nullptr, *lastHi = nullptr;
    double L0 = 0.0, H0 = 0.0, L1 = 0.0, H1 = 0.0;
    std::vector<Point2> loJoints, hiJoints; // where the runs of trapezoids meet
    std::vector<std::uint32_t> sources;
};

void mergeSources(std::vector<std::uint32_t>& into, const std::vector<std::uint32_t>& from)
{
    std::vector<std::uint32_t> merged;
    merged.reserve(into.size() + from.size());
    std::set_union(into.begin(), into.end(), from.begin(), from.end(), std::back_inserter(merged));
    into.swap(merged);
}

// Whether every joint lies within `tolerance` of the segment from `start` to `end`.
bool jointsOnChord(const std::vector<Point2>& joints, const Point2& start, const Point2& end, double tolerance)
{
    for (const Point2& j : joints)
    {
        const double y = start.y + (end.y - start.y) * (j.x - start.x) / (end.x - start.x);
        if (!(std::abs(y - j.y) <= tolerance))
            return false;
    }
    return true;
}

UnionPiece pieceOf(const Chain& chain)
{
    UnionPiece piece;
    const UnionCorner corners[4] = {cornerAt(*chain.firstLo, chain.x0), cornerAt(*chain.lastLo, chain.x1),
                                    cornerAt(*chain.lastHi, chain.x1), cornerAt(*chain.firstHi, chain.x0)};
    for (const UnionCorner& c : corners)
    {
        // A pointed end (the interval closed to a point) gives the same point twice.
        if (!piece.corners.empty() && piece.corners.back().point == c.point)
        {
            if (c.id != NoUnionId)
                piece.corners.back() = c;
            continue;
        }
        piece.corners.push_back(c);
    }
    if (piece.corners.size() > 1 && piece.corners.front().point == piece.corners.back().point)
        piece.corners.pop_back();
    piece.sources = chain.sources;
    Outline2 outline;
    for (const UnionCorner& c : piece.corners)
        outline.push_back(c.point);
    piece.area = signedArea(outline);
    return piece;
}

// Each convex input splits into its lower chain (edges running +x, counter-clockwise) and
// upper chain (running -x); vertical edges bound no slab's interval. Every vertex's x goes to
// `xs`, and the vertices' bounds widen [lo, hi].
std::vector<Chains> splitIntoChains(const std::vector<UnionInput>& inputs, std::vector<double>& xs, Point2& lo,
                                    Point2& hi)
{
    std::vector<Chains> chains(inputs.size());
    for (std::size_t k = 0; k < inputs.size(); ++k)
    {
        const UnionInput& in = inputs[k];
        Chains& c = chains[k];
        c.minX = 1e300;
        c.maxX = -1e300;
        const std::size_t n = in.points.size();
        for (std::size_t i = 0; i < n; ++i)
        {
            const Point2 &p = in.points[i], &q = in.points[(i + 1) % n];
            const std::uint32_t ip = in.ids[i], iq = in.ids[(i + 1) % n];
            if (p.x < q.x)
                c.lower.push_back({p, q, ip, iq});
            else if (p.x > q.x)
                c.upper.push_back({q, p, iq, ip});
            c.minX = std::min(c.minX, p.x);
            c.maxX = std::max(c.maxX, p.x);
            xs.push_back(p.x);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const auto byX = [](const Edge& e, const Edge& f) { return e.a.x < f.a.x; };
        std::sort(c.lower.begin(), c.lower.end(), byX);
        std::sort(c.upper.begin(), c.upper.end(), byX);
    }
    return chains;
}

// Where edges of different inputs cross, the union's boundary changes edge: a slab boundary
// there too, so within every slab no two edges cross and the union of intervals is exact.
void addCrossings(const std::vector<Chains>& chains, std::vector<double>& xs)
{
    std::vector<const Edge*> edges;
    std::vector<std::uint32_t> edgeInput;
    for (std::uint32_t k = 0; k < chains.size(); ++k)
        for (const std::vector<Edge>* chain : {&chains[k].lower, &chains[k].upper})
            for (const Edge& e : *chain)
            {
                edges.push_back(&e);
                edgeInput.push_back(k);
            }
    for (std::size_t i = 0; i < edges.size(); ++i)
        for (std::size_t j = i + 1; j < edges.size(); ++j)
        {
            const Edge &e = *edges[i], &f = *edges[j];
            if (edgeInput[i] == edgeInput[j] || e.b.x <= f.a.x || f.b.x <= e.a.x)
                continue;
            const double x0 = std::max(e.a.x, f.a.x), x1 = std::min(e.b.x, f.b.x);
            const double d0 = yAt(e, x0) - yAt(f, x0), d1 = yAt(e, x1) - yAt(f, x1);
            if ((d0 < 0.0 && d1 > 0.0) || (d0 > 0.0 && d1 < 0.0))
            {
                const double x = x0 + (x1 - x0) * (d0 / (d0 - d1));
                if (x > x0 && x < x1)
                    xs.push_back(x);
            }
        }
}

const Edge* spanningEdge(const std::vector<Edge>& edges, double x0, double x1)
{
    for (const Edge& e : edges)
        if (e.a.x <= x0 && e.b.x >= x1)
            return &e;
    return nullptr;
}

// The active inputs' intervals across the slab [x0, x1] (xm its middle), those that do not close
// there, sorted bottom to top.
void slabSpans(const std::vector<Chains>& chains, const std::vector<std::uint32_t>& active, double x0, double x1,
               double xm, std::vector<Span>& spans)
{
    spans.clear();
    for (std::uint32_t k : active)
    {
        const Edge* l = spanningEdge(chains[k].lower, x0, x1);
        const Edge* h = spanningEdge(chains[k].upper, x0, x1);
        if (!l || !h)
            continue;
        Span span{l, h, yAt(*l, x0), yAt(*l, x1), yAt(*l, xm), yAt(*h, x0), yAt(*h, x1), yAt(*h, xm), k};
        if (span.hiM > span.loM)
            spans.push_back(span);
    }
    std::sort(spans.begin(), spans.end(),
              [](const Span& a, const Span& b) {
                  return a.loM < b.loM ||
                         (a.loM == b.loM && (a.hiM < b.hiM || (a.hiM == b.hiM && a.source < b.source)));
              });
}

// Join the intervals that overlap (or come within the gap) across the whole slab: each
// joins one already in the group at both ends, so the union is one interval at every x.
// Returns the end of the group starting at spans[i]; `top` is its highest interval (at the middle)
// and `sources` gets the group's inputs.
std::size_t joinedGroupEnd(const std::vector<Span>& spans, std::size_t i, double gap, const Span*& top,
                           std::vector<std::uint32_t>& sources)
{
    std::size_t j = i + 1;
    for (; j < spans.size(); ++j)
    {
        const Span& s2 = spans[j];
        bool joins = false;
        for (std::size_t m = i; m < j && !joins; ++m)
            joins = s2.lo0 <= spans[m].hi0 + gap && s2.lo1 <= spans[m].hi1 + gap;
        if (!joins)
            break;
        sources.push_back(s2.source);
        if (s2.hiM > top->hiM)
            top = &s2;
    }
    return j;
}

// A joined interval across the slab [x0, x1]: from lower edge `lo` (L0 at x0, L1 at x1) up to
// upper edge `hi` (H0, H1).
struct Trapezoid
{
    double x0, x1;
    const Edge *lo, *hi;
    double L0, L1, H0, H1;
};

// Continue a run from the previous slab when the sides meet and both boundaries stay
// straight through every joint: the run of `open` that continues into `t`, its joints updated,
// or null.
Chain* continuedRun(std::vector<Chain>& open, const Trapezoid& t, double tolerance)
{
    for (Chain& c : open)
    {
        if (c.x1 != t.x0 || !(std::abs(c.L1 - t.L0) <= tolerance) || !(std::abs(c.H1 - t.H0) <= tolerance))
            continue;
        const Point2 loStart(c.x0, c.L0), hiStart(c.x0, c.H0), loEnd(t.x1, t.L1), hiEnd(t.x1, t.H1);
        std::vector<Point2> loJoints = c.loJoints, hiJoints = c.hiJoints;
        loJoints.emplace_back(t.x0, c.L1);
        hiJoints.emplace_back(t.x0, c.H1);
        if (!jointsOnChord(loJoints, loStart, loEnd, tolerance) || !jointsOnChord(hiJoints, hiStart, hiEnd, tolerance))
            continue;
        c.loJoints.swap(loJoints);
        c.hiJoints.swap(hiJoints);
        return &c;
    }
    return nullptr;
}

Chain startedRun(const Trapezoid& t, std::vector<std::uint32_t>& sources)
{
    Chain c;
    c.x0 = t.x0;
    c.x1 = t.x1;
    c.firstLo = c.lastLo = t.lo;
    c.firstHi = c.lastHi = t.hi;
    c.L0 = t.L0;
    c.H0 = t.H0;
    c.L1 = t.L1;
    c.H1 = t.H1;
    c.sources = std::move(sources);
    return c;
}

// The trapezoids of the slab [x0, x1] from its sorted `spans`, each continuing a run of `open`
// (which is then marked taken) or starting one, into `next`.
void joinSlab(const std::vector<Span>& spans, double x0, double x1, double gap, double tolerance,
              std::vector<Chain>& open, std::vector<Chain>& next)
{
    for (std::size_t i = 0; i < spans.size();)
    {
        const Span& first = spans[i];
        const Span* top = &first;
        std::vector<std::uint32_t> sources{first.source};
        i = joinedGroupEnd(spans, i, gap, top, sources);
        // The lowest lower edge and the highest upper edge (at the middle) are each an edge of
        // the union's interval's inputs, so the trapezoid between them lies in the union.
        const double L0 = first.lo0, L1 = first.lo1, H0 = top->hi0, H1 = top->hi1;
        if (!(H0 >= L0) || !(H1 >= L1) || !((H0 - L0) + (H1 - L1) > 0.0))
            continue;
        std::sort(sources.begin(), sources.end());
        sources.erase(std::unique(sources.begin(), sources.end()), sources.end());

        const Trapezoid trapezoid{x0, x1, first.lo, top->hi, L0, L1, H0, H1};
        Chain* extended = continuedRun(open, trapezoid, tolerance);
        if (extended)
        {
            extended->x1 = x1;
            extended->lastLo = first.lo;
            extended->lastHi = top->hi;
            extended->L1 = L1;
            extended->H1 = H1;
            mergeSources(extended->sources, sources);
            next.push_back(std::move(*extended));
            extended->x1 = -1e300; // taken: not continued twice
            continue;
        }
        next.push_back(startedRun(trapezoid, sources));
    }
}

// The runs of trapezoids of every slab between consecutive `xs`, sweeping left to right with the
// inputs whose x-range covers the slab.
std::vector<Chain> sweepSlabs(const std::vector<Chains>& chains, const std::vector<double>& xs, double gap,
                              double tolerance)
{
    std::vector<Chain> done, open, next;
    std::vector<Span> spans;
    std::vector<std::uint32_t> order(chains.size());
    for (std::uint32_t k = 0; k < order.size(); ++k)
        order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b)
              { return chains[a].minX < chains[b].minX || (chains[a].minX == chains[b].minX && a < b); });
    std::vector<std::uint32_t> active;
    std::size_t nextInput = 0;
    for (std::size_t s = 0; s + 1 < xs.size(); ++s)
    {
        const double x0 = xs[s], x1 = xs[s + 1], xm = 0.5 * (x0 + x1);
        while (nextInput < order.size() && chains[order[nextInput]].minX <= x0)
            active.push_back(order[nextInput++]);
        active.erase(
            std::remove_if(active.begin(), active.end(), [&](std::uint32_t k) { return chains[k].maxX <= x0; }),
            active.end());

        slabSpans(chains, active, x0, x1, xm, spans);
        next.clear();
        joinSlab(spans, x0, x1, gap, tolerance, open, next);
        for (Chain& c : open)
            if (c.x1 != -1e300)
                done.push_back(std::move(c));
        open.swap(next);
    }
    for (Chain& c : open)
        done.push_back(std::move(c));
    return done;
}

// The piece covering `a` and `b` whose outline is `hull` (indices into a's corners, then b's);
// `outline` gets its points.
UnionPiece joinedPiece(const UnionPiece& a, const UnionPiece& b, const std::vector<std::size_t>& hull,
                       Outline2& outline)
{
    UnionPiece merged;
    for (std::size_t k : hull)
    {
        const UnionCorner& c = k < a.corners.size() ? a.corners[k] : b.corners[k - a.corners.size()];
        merged.corners.push_back(c);
        outline.push_back(c.point);
    }
    merged.sources = a.sources;
    mergeSources(merged.sources, b.sources);
    merged.area = signedArea(outline);
    return merged;
}

// Pieces whose union is exactly convex join, largest first, until none can.
void joinConvexPieces(std::vector<UnionPiece>& pieces, std::size_t maxCorners)
{
    std::vector<Outline2> outlines(pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i)
        for (const UnionCorner& c : pieces[i].corners)
            outlines[i].push_back(c.point);
    for (bool joined = true; joined;)
    {
        joined = false;
        for (std::size_t i = 0; i < pieces.size(); ++i)
            for (std::size_t j = i + 1; j < pieces.size(); ++j)
            {
                const std::vector<std::size_t> hull = convexUnionIndices(outlines[i], outlines[j], maxCorners);
                if (hull.empty())
                    continue;
                Outline2 outline;
                UnionPiece merged = joinedPiece(pieces[i], pieces[j], hull, outline);
                pieces[i] = std::move(merged);
                outlines[i] = std::move(outline);
                pieces.erase(pieces.begin() + std::ptrdiff_t(j));
                outlines.erase(outlines.begin() + std::ptrdiff_t(j));
                --j;
                joined = true;
            }
    }
}
} // namespace

std::vector<UnionPiece> planarUnion(const std::vector<UnionInput>& inputs, const PlanarUnionOptions& options)
{
    if (inputs.empty() || inputs.size() > options.maxInputs)
        return {};

    std::vector<double> xs;
    Point2 lo(1e300), hi(-1e300);
    const std::vector<Chains> chains = splitIntoChains(inputs, xs, lo, hi);
    addCrossings(chains, xs);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    const double extent = glm::length(hi - lo);
    // Rounding of the slab arithmetic, far below any raster's resolution; the gap is the caller's.
    const double tolerance = options.gap + 1e-12 * extent;

    // The runs point at the chains' edges, so `chains` outlives them.
    const std::vector<Chain> done = sweepSlabs(chains, xs, options.gap, tolerance);
    std::vector<UnionPiece> pieces;
    for (const Chain& c : done)
    {
        UnionPiece piece = pieceOf(c);
        if (piece.corners.size() >= 3 && piece.area > 0.0)
            pieces.push_back(std::move(piece));
    }
    joinConvexPieces(pieces, options.maxCorners);
    return pieces;
}
} // namespace osgVis::core
