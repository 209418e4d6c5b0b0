// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// View frustum as six inward-facing planes, built from a view-projection matrix (OpenGL clip
/// conventions: -w <= x,y,z <= w). Works for perspective, off-centre and orthographic projections.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/geometry/Plane.h>

#include <array>

namespace osgVis::core
{
enum class Containment
{
    Outside,
    Intersects,
    Inside
};

class Frustum
{
public:
    enum PlaneIndex
    {
        LEFT,
        RIGHT,
        BOTTOM,
        TOP,
        NEAR,
        FAR
    };

    Frustum() = default;
    /// viewProjection = projection * view (column vectors, GLM convention).
    static Frustum fromMatrix(const Mat4& viewProjection);

    const std::array<Plane, 6>& planes() const { return _planes; }
    const Plane& plane(int i) const { return _planes[i]; }

    /// Conservative: Outside only when the box lies entirely outside one plane.
    Containment classify(const Aabb& box) const;
    /// Same test restricted to the planes whose bit is set in `planeMask`; clears bits of planes the
    /// box is fully inside (hierarchical plane masking). Returns Outside/Intersects/Inside.
    Containment classify(const Aabb& box, unsigned& planeMask) const;
    bool contains(const Vec3& p) const;

private:
    std::array<Plane, 6> _planes{};
};
} // namespace osgVis::core
