// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Line-stabbing geometry of cell-and-portal visibility (Teller & Séquin) for axial portals. Every
/// test is conservative: it may answer "stabbable"/"meets" for a configuration no line realises,
/// never the reverse. Tolerances are in world units.
#include <osgVis/core/geometry/AxialRect.h>
#include <osgVis/core/geometry/Plane.h>

#include <cstddef>
#include <vector>

namespace osgVis::core
{
/// A portal crossed in one direction: towards +axis when `positive`, else towards -axis.
struct OrientedPortal
{
    AxialRect rect;
    bool positive = true;
};

/// False only when no oriented line crosses portals[0..n) in this order, each in its direction
/// (touching a portal's boundary counts as crossing it, within `tolerance`).
/// note: the AND of necessary conditions: crossing order against every pair's planes, Teller's
/// exact 2-D test in each coordinate-plane projection, the Plücker LP (quadric relaxed), and the
/// last portal against the separating-plane funnel of the earlier ones (a bake extending
/// sequences one portal at a time checks every prefix so). A few microseconds for 3-6 portals.
/// Every function here adds a rounding slack of about 1e-9 x the input's size to `tolerance`
/// (so 0 still accepts lines that exactly touch an edge) and allocates nothing once warm except
/// portalFunnel; all may run on several threads at once.
bool portalSequenceStabbable(const OrientedPortal* portals, std::size_t count, double tolerance);

/// A convex region (intersection of half-spaces, kept side >= 0) that contains every point lying
/// beyond the last portal on a line that crosses the whole sequence in order.
struct PortalFunnel
{
    std::vector<Plane> planes;
};
PortalFunnel portalFunnel(const OrientedPortal* portals, std::size_t count);

/// Whether `box` has a point inside every plane of `funnel` (within tolerance). Exact for convex
/// regions (a small LP), so tighter than testing the box against each plane alone.
bool boxMeetsFunnel(const Aabb& box, const PortalFunnel& funnel, double tolerance);

/// Run time: is there a sightline from `eye` through portals[0..n) in order, inside the half-spaces
/// `viewPlanes` (planes through the eye, e.g. the side planes of a perspective frustum)? A small LP
/// over the point where the sightline crosses the last portal.
bool eyeSeesThroughPortals(const Vec3& eye, const OrientedPortal* portals, std::size_t count,
                           const std::vector<Plane>& viewPlanes, double tolerance);
/// Is some point of `box` reached by a sightline from `eye` through portals[0..n) (n may be 0) that
/// stays inside `viewPlanes`? Same LP with the point ranging over the box.
bool eyeSeesBoxThroughPortals(const Vec3& eye, const OrientedPortal* portals, std::size_t count,
                              const std::vector<Plane>& viewPlanes, const Aabb& box, double tolerance);
} // namespace osgVis::core
