// SPDX-License-Identifier: MIT
#include <osgVis/core/occluders/OccluderDependents.h>

#include <algorithm>

namespace osgVis::core
{
namespace
{
// Calls visit(object, polygon) once for every object a polygon rests on.
template <class Visit>
void forEachRest(const std::vector<OccluderPolygon>& polygons, std::size_t objectCount, Visit visit)
{
    for (std::uint32_t p = 0; p < polygons.size(); ++p)
    {
        if (polygons[p].owner < objectCount)
            visit(polygons[p].owner, p);
        for (ObjectId part : polygons[p].parts)
            if (part < objectCount && part != polygons[p].owner)
                visit(part, p);
    }
}
} // namespace

void OccluderDependents::build(const std::vector<OccluderPolygon>& polygons, std::size_t objectCount)
{
    _first.assign(objectCount + 1, 0);
    forEachRest(polygons, objectCount, [&](ObjectId id, std::uint32_t) { ++_first[id + 1]; });
    for (std::size_t id = 0; id < objectCount; ++id)
        _first[id + 1] += _first[id];
    _polygons.resize(_first[objectCount]);
    std::vector<std::uint32_t> next(_first.begin(), _first.end() - 1);
    forEachRest(polygons, objectCount, [&](ObjectId id, std::uint32_t p) { _polygons[next[id]++] = p; });
    _disabled.assign(polygons.size(), 0);
}

void OccluderDependents::disableAll(ObjectId id)
{
    if (_first.empty() || id >= _first.size() - 1)
        return;
    for (std::uint32_t i = _first[id]; i < _first[id + 1]; ++i)
        _disabled[_polygons[i]] = 1;
}

bool sameOccluderCandidates(const std::vector<OccluderCandidate>& a, const std::vector<OccluderCandidate>& b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const OccluderCandidate& x, const OccluderCandidate& y)
                      { return x.owner == y.owner && x.polygon.vertices() == y.polygon.vertices(); });
}
} // namespace osgVis::core
