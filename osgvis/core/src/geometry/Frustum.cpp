// SPDX-License-Identifier: MIT
// Plane extraction after Gribb & Hartmann, "Fast Extraction of Viewing Frustum Planes from the
// World-View-Projection Matrix" (2001); box test with the p-/n-vertex of each plane.
#include <osgVis/core/geometry/Frustum.h>

namespace osgVis::core
{
namespace
{
// Row i of a column-major GLM matrix (m[col][row]).
Vec4 row(const Mat4& m, int i)
{
    return {m[0][i], m[1][i], m[2][i], m[3][i]};
}

Plane planeFrom(const Vec4& v)
{
    Plane p(Vec3(v), v.w);
    p.normalize();
    return p;
}

// Corner of the box furthest along the normal (p-vertex) and furthest against it (n-vertex).
void extremeCorners(const Aabb& box, const Vec3& normal, Vec3& positive, Vec3& negative)
{
    for (int i = 0; i < 3; ++i)
    {
        const bool up = normal[i] >= 0.0;
        positive[i] = up ? box.max[i] : box.min[i];
        negative[i] = up ? box.min[i] : box.max[i];
    }
}
} // namespace

Frustum Frustum::fromMatrix(const Mat4& viewProjection)
{
    const Vec4 r0 = row(viewProjection, 0);
    const Vec4 r1 = row(viewProjection, 1);
    const Vec4 r2 = row(viewProjection, 2);
    const Vec4 r3 = row(viewProjection, 3);
    Frustum f;
    f._planes[LEFT] = planeFrom(r3 + r0);
    f._planes[RIGHT] = planeFrom(r3 - r0);
    f._planes[BOTTOM] = planeFrom(r3 + r1);
    f._planes[TOP] = planeFrom(r3 - r1);
    f._planes[NEAR] = planeFrom(r3 + r2);
    f._planes[FAR] = planeFrom(r3 - r2);
    return f;
}

Containment Frustum::classify(const Aabb& box) const
{
    unsigned mask = 0x3Fu;
    return classify(box, mask);
}

Containment Frustum::classify(const Aabb& box, unsigned& planeMask) const
{
    for (int i = 0; i < 6; ++i)
    {
        const unsigned bit = 1u << i;
        if (!(planeMask & bit))
            continue;
        const Plane& p = _planes[i];
        Vec3 positive, negative;
        extremeCorners(box, p.normal, positive, negative);
        // note: written so that NaN distances never yield Outside (conservative).
        if (p.distance(positive) < 0.0)
            return Containment::Outside;
        if (p.distance(negative) >= 0.0)
            planeMask &= ~bit;
    }
    return planeMask == 0 ? Containment::Inside : Containment::Intersects;
}

bool Frustum::contains(const Vec3& point) const
{
    for (const Plane& p : _planes)
    {
        if (p.distance(point) < 0.0)
            return false;
    }
    return true;
}
} // namespace osgVis::core
