// SPDX-License-Identifier: MIT
#pragma once
// Walks through waypoints: a centripetal Catmull–Rom curve (it neither overshoots nor loops where
// waypoints are unevenly spaced, so a path through a door stays in the door) sampled at a constant
// speed and a fixed time step, looking a little ahead along the path.
#include <osgVis/core/scene/Walk.h>

#include <osg/BoundingBox>
#include <osg/Vec3d>

#include <cstddef>
#include <vector>

namespace osgVis::gen
{
class SmoothPath
{
public:
    // Consecutive duplicate waypoints are dropped; at least two distinct ones are required.
    explicit SmoothPath(const std::vector<osg::Vec3d>& waypoints);

    double length() const { return _arc.back(); }
    // Point at arc length s; beyond either end the path continues straight along its end tangent.
    osg::Vec3d at(double s) const;

private:
    std::vector<osg::Vec3d> _points; // dense polyline on the curve
    std::vector<double> _arc;        // cumulative arc length at each point
};

struct WalkPace
{
    double speed = 1.4;     // metres per second
    double timeStep = 0.1;  // seconds between views
    double lookAhead = 2.0; // metres along the path to the point looked at
    std::size_t minViews = 200;
    std::size_t maxViews = 1000;
};

// Keys at t = 0, timeStep, … along the path. A route too short for `minViews` is walked back and forth;
// one too long is cut at `maxViews`.
std::vector<core::WalkKey> walkAlong(std::vector<osg::Vec3d> route, const WalkPace& pace);

inline core::Vec3 toCore(const osg::Vec3d& v)
{
    return {v.x(), v.y(), v.z()};
}

// One view at time t from `eye` towards `centre`, z up.
core::WalkKey lookAt(double time, const osg::Vec3d& eye, const osg::Vec3d& centre);

// Perspective walk (60° fovY, 1280 × 1024) with the given clip planes.
core::Walk perspectiveWalk(std::vector<core::WalkKey> keys, double zNear, double zFar);

// Far plane for a walk inside `sceneBounds`: beyond every point of the scene from every eye inside it.
double farPlaneFor(const osg::BoundingBoxd& sceneBounds);
} // namespace osgVis::gen
