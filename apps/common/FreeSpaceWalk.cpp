// SPDX-License-Identifier: MIT
#include "FreeSpaceWalk.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

namespace osgVis::apps
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double WalkableCos = 0.82; // cos 35°: a floor, a ramp or stairs, not a wall
constexpr unsigned HorizontalDirections = 16;

struct FloorPoint
{
    core::Vec3 point;
    double ceiling = 0.0; // free room straight up; infinity when open
};

// Random points on the upward-facing triangles, area-weighted.
std::vector<FloorPoint> sampleFloor(const RayScene& rays, unsigned count, std::mt19937_64& random, double lift)
{
    const std::vector<core::Triangle>& triangles = rays.scene().triangles;
    std::vector<double> cumulative;
    std::vector<std::uint32_t> walkable;
    double total = 0.0;
    for (std::uint32_t i = 0; i < triangles.size(); ++i)
    {
        const core::Triangle& t = triangles[i];
        const core::Vec3 n = glm::cross(core::Vec3(t.b - t.a), core::Vec3(t.c - t.a));
        const double area2 = glm::length(n);
        if (!rays.usable(i) || !(area2 > 0.0) || !std::isfinite(area2) || n.z < WalkableCos * area2)
            continue;
        total += area2;
        cumulative.push_back(total);
        walkable.push_back(i);
    }
    std::vector<FloorPoint> points;
    if (walkable.empty())
        return points;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (unsigned k = 0; k < count; ++k)
    {
        const double pick = unit(random) * total;
        const std::size_t j = std::min<std::size_t>(
            std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(), walkable.size() - 1);
        const core::Triangle& t = triangles[walkable[j]];
        double u = unit(random), v = unit(random);
        if (u + v > 1.0)
            u = 1.0 - u, v = 1.0 - v;
        FloorPoint floor;
        floor.point = core::Vec3(t.a) + u * core::Vec3(t.b - t.a) + v * core::Vec3(t.c - t.a) + core::Vec3(0, 0, lift);
        floor.ceiling = rays.nearest(floor.point, core::Vec3(0, 0, 1)).distance;
        points.push_back(floor);
    }
    return points;
}

// Sets `indoors` when the height comes from the model's ceilings.
double chooseEyeHeight(const std::vector<FloorPoint>& floor, double horizontalSize, FreeSpaceWalkReport& report,
                       bool& indoors)
{
    std::vector<double> ceilings;
    for (const FloorPoint& f : floor)
        if (std::isfinite(f.ceiling) && f.ceiling > 0.0)
            ceilings.push_back(f.ceiling);
    report.withCeiling = unsigned(ceilings.size());
    std::ostringstream rule;
    if (ceilings.size() * 4 >= floor.size() && !ceilings.empty())
    {
        std::nth_element(ceilings.begin(), ceilings.begin() + ceilings.size() / 2, ceilings.end());
        const double median = ceilings[ceilings.size() / 2];
        rule << "0.55 x the median of " << ceilings.size() << " ceiling clearances (" << median << ")";
        report.eyeHeightRule = rule.str();
        indoors = true;
        return 0.55 * median;
    }
    if (1.7 <= 0.1 * horizontalSize)
    {
        report.eyeHeightRule = "1.7 units (open sky above most floor points; metres assumed)";
        return 1.7;
    }
    rule << "a tenth of the model's horizontal size (open sky above, model smaller than 17 units)";
    report.eyeHeightRule = rule.str();
    return 0.1 * horizontalSize;
}

// Free distance along each of the 16 horizontal directions from an eye.
std::vector<double> freeDistances(const RayScene& rays, const core::Vec3& eye)
{
    std::vector<double> distances(HorizontalDirections);
    for (unsigned d = 0; d < HorizontalDirections; ++d)
    {
        const double azimuth = 2.0 * Pi * d / HorizontalDirections;
        distances[d] = rays.nearest(eye, core::Vec3(std::cos(azimuth), std::sin(azimuth), 0.0)).distance;
    }
    return distances;
}

// Views nobody tuned: per station `gazesPerStation` keys, each eye moved by up to a fifth of the eye
// height along every axis (inside the room the eye finder checked: a quarter eye height to any
// wall, an eye height to the floor, 1.25 to the ceiling), looking in a direction uniform on the
// sphere.
std::vector<core::WalkKey> randomGazeKeys(const std::vector<core::Vec3>& stations, double eyeHeight,
                                          const FreeSpaceWalkOptions& options, std::mt19937_64& random)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0), turn(0.0, 2.0 * Pi);
    std::vector<core::WalkKey> keys;
    double time = 0.0;
    for (const core::Vec3& station : stations)
        for (unsigned g = 0; g < std::max(1u, options.gazesPerStation); ++g)
        {
            core::WalkKey key;
            key.time = time;
            key.eye = station + 0.2 * eyeHeight * core::Vec3(unit(random), unit(random), unit(random));
            const double z = unit(random), azimuth = turn(random), r = std::sqrt(std::max(0.0, 1.0 - z * z));
            const core::Vec3 direction(r * std::cos(azimuth), r * std::sin(azimuth), z);
            key.center = key.eye + eyeHeight * direction;
            key.up = std::abs(z) > 0.99 ? core::Vec3(0, 1, 0) : core::Vec3(0, 0, 1);
            keys.push_back(key);
            time += options.secondsPerKey;
        }
    return keys;
}

// Up to `count` directions (indices of the 16), freest first, at least 60 degrees apart, each with
// at least `least` free ahead (the freest one whatever it has).
std::vector<unsigned> freestDirections(const std::vector<double>& distances, unsigned count, double least)
{
    std::vector<unsigned> order(distances.size());
    for (unsigned d = 0; d < order.size(); ++d)
        order[d] = d;
    std::stable_sort(order.begin(), order.end(), [&](unsigned a, unsigned b) { return distances[a] > distances[b]; });
    std::vector<unsigned> chosen;
    const unsigned minSeparation = (HorizontalDirections + 5) / 6; // 60° in steps of 22.5°, rounded up
    for (unsigned d : order)
    {
        bool apart = true;
        for (unsigned c : chosen)
        {
            const unsigned gap = (d + HorizontalDirections - c) % HorizontalDirections;
            apart = apart && std::min(gap, HorizontalDirections - gap) >= minSeparation;
        }
        if (apart && (chosen.empty() || distances[d] >= least))
            chosen.push_back(d);
        if (chosen.size() == count)
            break;
    }
    return chosen;
}

// Farthest-point sampling, then a nearest-neighbour tour from the first station.
std::vector<core::Vec3> spreadStations(const std::vector<core::Vec3>& eyes, unsigned count)
{
    std::vector<core::Vec3> stations;
    if (eyes.empty())
        return stations;
    std::vector<double> nearest(eyes.size(), std::numeric_limits<double>::infinity());
    std::size_t next = 0;
    while (stations.size() < std::min<std::size_t>(count, eyes.size()))
    {
        stations.push_back(eyes[next]);
        double farthest = -1.0;
        for (std::size_t i = 0; i < eyes.size(); ++i)
        {
            nearest[i] = std::min(nearest[i], glm::length(eyes[i] - stations.back()));
            if (nearest[i] > farthest)
                farthest = nearest[i], next = i;
        }
        if (farthest <= 0.0)
            break;
    }
    std::vector<core::Vec3> tour{stations.front()};
    std::vector<bool> visited(stations.size(), false);
    visited[0] = true;
    for (std::size_t step = 1; step < stations.size(); ++step)
    {
        std::size_t best = 0;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < stations.size(); ++i)
            if (!visited[i] && glm::length(stations[i] - tour.back()) < bestDistance)
                bestDistance = glm::length(stations[i] - tour.back()), best = i;
        visited[best] = true;
        tour.push_back(stations[best]);
    }
    return tour;
}
} // namespace

core::Walk makeFreeSpaceWalk(const RayScene& rays, const FreeSpaceWalkOptions& options, FreeSpaceWalkReport* report)
{
    FreeSpaceWalkReport local;
    FreeSpaceWalkReport& r = report ? *report : local;
    r = FreeSpaceWalkReport{};
    const core::Aabb bounds = rays.bounds();
    if (bounds.empty())
        throw FreeSpaceWalkError("the model has no finite bounds");
    const core::Vec3 extent = bounds.extent();
    const double horizontalSize = std::max(extent.x, extent.y);
    const double diagonal = glm::length(extent);
    std::mt19937_64 random(options.seed);

    const std::vector<FloorPoint> floor = sampleFloor(rays, options.candidates, random, 1e-5 * diagonal);
    r.candidates = unsigned(floor.size());
    if (floor.empty())
        throw FreeSpaceWalkError("the model has no upward-facing surface to stand on");
    bool indoors = false;
    r.eyeHeight = chooseEyeHeight(floor, horizontalSize, r, indoors);

    std::vector<core::Vec3> eyes;
    for (const FloorPoint& f : floor)
    {
        if (indoors && !std::isfinite(f.ceiling))
        {
            ++r.openSky;
            continue;
        }
        if (f.ceiling < 1.25 * r.eyeHeight)
        {
            ++r.lowCeiling;
            continue;
        }
        const core::Vec3 eye = f.point + core::Vec3(0, 0, r.eyeHeight);
        // note: an eye is taken only when it is clearly outside (at most a quarter of the rays meet a
        // back face), so that another sampling of directions cannot find it inside: levels have
        // open edges and missing faces (a BSP compiler drops the faces nobody can see).
        const double back = backFaceFraction(rays, eye);
        if (back > 0.25)
        {
            ++(back > 0.5 ? r.insideSolid : r.doubtful);
            continue;
        }
        const std::vector<double> around = freeDistances(rays, eye);
        if (*std::min_element(around.begin(), around.end()) < 0.25 * r.eyeHeight)
        {
            ++r.nearWall;
            continue;
        }
        eyes.push_back(eye);
    }
    r.eyes = unsigned(eyes.size());
    if (eyes.empty())
        throw FreeSpaceWalkError("no floor point has room for an eye outside solid geometry");

    const std::vector<core::Vec3> stations = spreadStations(eyes, options.stations);
    r.stations = unsigned(stations.size());
    core::Walk walk;
    walk.width = options.width;
    walk.height = options.height;
    walk.projection.kind = core::WalkProjection::Kind::Perspective;
    walk.projection.fovY = options.fovYDegrees;
    // From an eye inside the bounds every point of the model lies within one diagonal.
    walk.projection.zFar = 1.05 * diagonal + r.eyeHeight;
    walk.projection.zNear = std::max(walk.projection.zFar * 1e-5, 0.05 * r.eyeHeight);
    double time = 0.0;
    if (options.randomGaze)
    {
        walk.keys = randomGazeKeys(stations, r.eyeHeight, options, random);
        return walk;
    }
    for (const core::Vec3& eye : stations)
    {
        const std::vector<double> distances = freeDistances(rays, eye);
        for (unsigned d : freestDirections(distances, std::max(1u, options.gazesPerStation), r.eyeHeight))
        {
            const double azimuth = 2.0 * Pi * d / HorizontalDirections;
            core::WalkKey key;
            key.time = time;
            key.eye = eye;
            key.center = eye + r.eyeHeight * core::Vec3(std::cos(azimuth), std::sin(azimuth), 0.0);
            key.up = core::Vec3(0, 0, 1);
            walk.keys.push_back(key);
            time += options.secondsPerKey;
        }
    }
    return walk;
}
} // namespace osgVis::apps
