// SPDX-License-Identifier: MIT
#pragma once
// Internal: what the extraction and the placement of a drawable (DrawablePlacement.cpp) share to
// read positions: finiteness, the bounds of points under a matrix, and a triangle collector.
#include <osgVis/core/scene/Scene.h>

#include <osg/BoundingBox>
#include <osg/Matrixd>
#include <osg/Vec3d>
#include <osg/Vec4d>

#include <cmath>
#include <cstdint>
#include <vector>

namespace osgVis
{
inline bool finite(const osg::Vec3d& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

inline core::Vec3 toCore(const osg::Vec3d& v)
{
    return {v.x(), v.y(), v.z()};
}

// World bounds of a point set; non-finite input is remembered, never added.
struct BoundsAccumulator
{
    explicit BoundsAccumulator(const osg::Matrixd& toRoot) : world(toRoot) {}

    osg::Matrixd world;
    core::Aabb bounds;
    bool nonFinite = false;

    void add(const osg::Vec3d& local)
    {
        const osg::Vec3d p = local * world;
        if (!finite(local) || !finite(p))
            nonFinite = true;
        else
            bounds.expand(toCore(p));
    }
    void addHomogeneous(const osg::Vec4d& v)
    {
        if (v.w() == 0.0 || !std::isfinite(v.w()))
            nonFinite = true; // a point at infinity has no bounds
        else
            add(osg::Vec3d(v.x(), v.y(), v.z()) / v.w());
    }
    void addBox(const osg::BoundingBox& box)
    {
        if (box.valid())
            for (unsigned i = 0; i < 8; ++i)
                add(box.corner(i));
    }
};

// Counts a drawable's triangles and optionally keeps them in world space.
struct TriangleCollector
{
    osg::Matrixd world;
    std::vector<core::Triangle>* out = nullptr; // null: count only
    std::uint32_t count = 0;

    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c)
    {
        ++count;
        if (!out)
            return;
        const osg::Vec3d wa = osg::Vec3d(a) * world, wb = osg::Vec3d(b) * world, wc = osg::Vec3d(c) * world;
        // note: a triangle with a non-finite corner is never stored (it would poison occluder tests);
        // its object is flagged always visible by the bounds pass.
        if (!finite(wa) || !finite(wb) || !finite(wc))
            return;
        out->push_back({core::Vec3f(wa.x(), wa.y(), wa.z()), core::Vec3f(wb.x(), wb.y(), wb.z()),
                        core::Vec3f(wc.x(), wc.y(), wc.z())});
    }
};
} // namespace osgVis
