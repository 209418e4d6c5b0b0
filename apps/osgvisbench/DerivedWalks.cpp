// SPDX-License-Identifier: MIT
#include "DerivedWalks.h"

#include <algorithm>
#include <cmath>

namespace osgVis::bench
{
namespace
{
constexpr std::size_t MinimumPacedFrames = 30;

// Index of walk position `step` when walking back and forth over keys 0..last.
std::size_t bouncedIndex(std::size_t step, std::size_t last)
{
    if (last == 0)
        return 0;
    const std::size_t period = 2 * last;
    const std::size_t phase = step % period;
    return phase <= last ? phase : period - phase;
}

double frameTime(const core::Walk& walk, std::size_t frame)
{
    const std::size_t n = walk.keys.size();
    if (frame < n)
        return walk.keys[frame].time;
    const double span = walk.keys.back().time - walk.keys.front().time;
    const double interval = n > 1 && span > 0.0 ? span / double(n - 1) : 1.0 / 30.0;
    return walk.keys.back().time + double(frame - n + 1) * interval;
}

core::WalkKey faceKey(const core::WalkKey& key, const core::Vec3& direction, const core::Vec3& up)
{
    core::WalkKey face = key;
    face.center = key.eye + direction;
    face.up = up;
    return face;
}
} // namespace

core::Walk subsampledWalk(const core::Walk& walk, unsigned count)
{
    const std::size_t available = walk.keys.size();
    if (count == 0 || count >= available)
        return walk;
    core::Walk sampled = walk;
    sampled.keys.clear();
    for (unsigned i = 0; i < count; ++i)
    {
        const double position = count == 1 ? 0.0 : double(i) * double(available - 1) / double(count - 1);
        sampled.keys.push_back(walk.keys[std::size_t(std::llround(position))]);
    }
    return sampled;
}

core::Walk cubeFaceWalk(const core::Walk& walk)
{
    core::Walk cube = walk;
    cube.projection.kind = core::WalkProjection::Kind::Perspective;
    cube.projection.fovY = 90.0;
    cube.width = cube.height = walk.height;
    cube.keys.clear();
    for (const core::WalkKey& key : walk.keys)
    {
        const core::Vec3 forward = glm::normalize(key.center - key.eye);
        // An up vector along the line of sight has no sideways part; any perpendicular one will do.
        core::Vec3 side = glm::cross(forward, key.up);
        if (glm::length(side) < 1e-9)
            side = glm::cross(forward, std::abs(forward.z) < 0.9 ? core::Vec3(0, 0, 1) : core::Vec3(1, 0, 0));
        const core::Vec3 right = glm::normalize(side);
        const core::Vec3 up = glm::cross(right, forward);
        cube.keys.push_back(faceKey(key, forward, up));
        cube.keys.push_back(faceKey(key, -forward, up));
        cube.keys.push_back(faceKey(key, -right, up));
        cube.keys.push_back(faceKey(key, right, up));
        cube.keys.push_back(faceKey(key, up, -forward));
        cube.keys.push_back(faceKey(key, -up, forward));
    }
    return cube;
}

core::Walk pacedWalk(const core::Walk& walk, unsigned speed)
{
    core::Walk paced = walk;
    paced.keys.clear();
    const std::size_t n = walk.keys.size();
    if (n == 0 || speed == 0)
        return paced;
    const std::size_t onePass = (n - 1) / speed + 1;
    const std::size_t frames = std::max(onePass, std::min(MinimumPacedFrames, n));
    for (std::size_t frame = 0; frame < frames; ++frame)
    {
        core::WalkKey key = walk.keys[bouncedIndex(frame * speed, n - 1)];
        key.time = frameTime(walk, frame);
        paced.keys.push_back(key);
    }
    return paced;
}
} // namespace osgVis::bench
