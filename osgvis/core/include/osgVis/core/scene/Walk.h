// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Walk paths: a timed sequence of viewpoints with one fixed projection, stored as text
/// (format documented in docs/walk-format.md).
#include <osgVis/core/geometry/Math.h>

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace osgVis::core
{
struct WalkError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

struct WalkProjection
{
    enum class Kind
    {
        Perspective, ///< fovY (degrees), aspect from the viewport
        Frustum,     ///< off-centre: left/right/bottom/top at the near plane
        Ortho        ///< left/right/bottom/top in eye units
    };
    Kind kind = Kind::Perspective;
    double fovY = 60.0;
    double left = -1, right = 1, bottom = -1, top = 1;
    double zNear = 0.1, zFar = 1000.0; ///< fixed for the whole walk

    Mat4 matrix(double aspect) const;
};

struct WalkKey
{
    double time = 0.0; ///< seconds
    Vec3 eye{0.0};
    Vec3 center{0.0, 1.0, 0.0}; ///< point looked at
    Vec3 up{0.0, 0.0, 1.0};

    Mat4 viewMatrix() const;
};

struct Walk
{
    WalkProjection projection;
    unsigned width = 1280, height = 1024;
    std::vector<WalkKey> keys;

    double aspect() const { return double(width) / double(height); }
    /// Throws WalkError with "<source>:<line>: message" on malformed input.
    static Walk parse(std::istream& in, const std::string& sourceName = "<walk>");
    static Walk load(const std::string& path);
    void write(std::ostream& out) const;
    void save(const std::string& path) const;
};
} // namespace osgVis::core
