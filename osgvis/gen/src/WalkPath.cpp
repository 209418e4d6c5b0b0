// SPDX-License-Identifier: MIT
#include "WalkPath.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace osgVis::gen
{
namespace
{
// Dense sampling step of the curve (metres); views interpolate linearly between samples.
constexpr double sampleSpacing = 0.02;

// Barry–Goldman evaluation of the Catmull–Rom segment p1..p2 with knots t0..t3 at parameter t.
osg::Vec3d catmullRom(const osg::Vec3d p[4], const double k[4], double t)
{
    auto lerp = [](const osg::Vec3d& a, const osg::Vec3d& b, double ta, double tb, double t)
    { return a * ((tb - t) / (tb - ta)) + b * ((t - ta) / (tb - ta)); };
    const osg::Vec3d a1 = lerp(p[0], p[1], k[0], k[1], t);
    const osg::Vec3d a2 = lerp(p[1], p[2], k[1], k[2], t);
    const osg::Vec3d a3 = lerp(p[2], p[3], k[2], k[3], t);
    const osg::Vec3d b1 = lerp(a1, a2, k[0], k[2], t);
    const osg::Vec3d b2 = lerp(a2, a3, k[1], k[3], t);
    return lerp(b1, b2, k[1], k[2], t);
}
// Catmull–Rom bows a long leg between short ones (the tangents at its ends point across it). Knots a
// third of the shortest neighbouring leg in from each end make the middle of every leg a piece whose
// four control points are collinear, hence straight; the curve turns only near the waypoints.
std::vector<osg::Vec3d> withStraightLegs(const std::vector<osg::Vec3d>& w)
{
    auto legLength = [&](std::size_t i) { return (w[i + 1] - w[i]).length(); };
    std::vector<osg::Vec3d> result{w.front()};
    for (std::size_t i = 0; i + 1 < w.size(); ++i)
    {
        const double length = legLength(i);
        double shortest = length;
        if (i > 0)
            shortest = std::min(shortest, legLength(i - 1));
        if (i + 2 < w.size())
            shortest = std::min(shortest, legLength(i + 1));
        const osg::Vec3d dir = (w[i + 1] - w[i]) / length;
        result.push_back(w[i] + dir * (shortest / 3.0));
        result.push_back(w[i + 1] - dir * (shortest / 3.0));
        result.push_back(w[i + 1]);
    }
    return result;
}
} // namespace

SmoothPath::SmoothPath(const std::vector<osg::Vec3d>& waypoints)
{
    std::vector<osg::Vec3d> w;
    for (const osg::Vec3d& p : waypoints)
        if (w.empty() || (p - w.back()).length() > 1e-9)
            w.push_back(p);
    if (w.size() < 2)
        throw std::invalid_argument("a walk needs two distinct waypoints");
    w = withStraightLegs(w);
    // Phantom end points continue the first and last legs straight.
    w.insert(w.begin(), w[0] * 2.0 - w[1]);
    w.push_back(w[w.size() - 1] * 2.0 - w[w.size() - 2]);

    _points.push_back(w[1]);
    _arc.push_back(0.0);
    for (std::size_t i = 1; i + 2 < w.size(); ++i)
    {
        const osg::Vec3d p[4] = {w[i - 1], w[i], w[i + 1], w[i + 2]};
        double k[4] = {0.0};
        for (int j = 1; j < 4; ++j)
            k[j] = k[j - 1] + std::sqrt((p[j] - p[j - 1]).length()); // centripetal: alpha = 1/2
        const int steps = std::max(4, int(std::ceil((p[2] - p[1]).length() / sampleSpacing)));
        for (int s = 1; s <= steps; ++s)
        {
            const osg::Vec3d q = s == steps ? p[2] : catmullRom(p, k, k[1] + (k[2] - k[1]) * s / steps);
            _arc.push_back(_arc.back() + (q - _points.back()).length());
            _points.push_back(q);
        }
    }
}

osg::Vec3d SmoothPath::at(double s) const
{
    const std::size_t n = _points.size();
    if (s <= 0.0)
    {
        osg::Vec3d dir = _points[1] - _points[0];
        dir.normalize();
        return _points[0] + dir * s;
    }
    if (s >= _arc.back())
    {
        osg::Vec3d dir = _points[n - 1] - _points[n - 2];
        dir.normalize();
        return _points[n - 1] + dir * (s - _arc.back());
    }
    const auto i = std::size_t(std::upper_bound(_arc.begin(), _arc.end(), s) - _arc.begin());
    const double span = _arc[i] - _arc[i - 1];
    const double f = span > 0.0 ? (s - _arc[i - 1]) / span : 0.0;
    return _points[i - 1] * (1.0 - f) + _points[i] * f;
}

std::vector<core::WalkKey> walkAlong(std::vector<osg::Vec3d> route, const WalkPace& pace)
{
    const double step = pace.speed * pace.timeStep;
    const std::vector<osg::Vec3d> outbound = route;
    for (bool back = true; SmoothPath(route).length() < step * double(pace.minViews - 1); back = !back)
    {
        // Back the way it came, then out again: the walk turns on the spot at each end.
        if (back)
            route.insert(route.end(), outbound.rbegin() + 1, outbound.rend());
        else
            route.insert(route.end(), outbound.begin() + 1, outbound.end());
    }
    const SmoothPath path(route);
    const auto views = std::min(pace.maxViews, std::size_t(std::floor(path.length() / step)) + 1);

    std::vector<core::WalkKey> keys;
    keys.reserve(views);
    osg::Vec3d heading(1.0, 0.0, 0.0);
    for (std::size_t i = 0; i < views; ++i)
    {
        const double s = step * double(i);
        const osg::Vec3d eye = path.at(s);
        osg::Vec3d ahead = path.at(s + pace.lookAhead) - eye;
        ahead.z() = 0.0;
        // note: where the walk turns on the spot the point ahead passes through the eye; keep the
        // last heading there rather than looking along a zero vector.
        if (ahead.normalize() > 1e-3)
            heading = ahead;
        keys.push_back(lookAt(pace.timeStep * double(i), eye, eye + heading));
    }
    return keys;
}

core::WalkKey lookAt(double time, const osg::Vec3d& eye, const osg::Vec3d& centre)
{
    core::WalkKey key;
    key.time = time;
    key.eye = toCore(eye);
    key.center = toCore(centre);
    key.up = core::Vec3(0.0, 0.0, 1.0);
    return key;
}

core::Walk perspectiveWalk(std::vector<core::WalkKey> keys, double zNear, double zFar)
{
    core::Walk walk;
    walk.projection.kind = core::WalkProjection::Kind::Perspective;
    walk.projection.fovY = 60.0;
    walk.projection.zNear = zNear;
    walk.projection.zFar = zFar;
    walk.width = 1280;
    walk.height = 1024;
    walk.keys = std::move(keys);
    return walk;
}

double farPlaneFor(const osg::BoundingBoxd& sceneBounds)
{
    const double diagonal = (sceneBounds._max - sceneBounds._min).length();
    return std::ceil(diagonal * 1.1 + 10.0);
}
} // namespace osgVis::gen
