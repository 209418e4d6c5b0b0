// SPDX-License-Identifier: MIT
#pragma once
// The critical frame's camera as the mask sees it: world → eye → mask coordinates, the depth plane
// of an occluder polygon over the mask, the clip planes that bound what gets rasterized, and the
// image-shift bound that turns the shrinkage Δ into the eye's freedom δ (docs/mask.md).
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/mask/MaskRasterizer.h>
#include <osgVis/core/geometry/Plane.h>
#include <osgVis/core/scene/View.h>

#include <array>
#include <optional>

namespace osgVis::core
{
struct MaskRect
{
    double x0, y0, x1, y1; // mask coordinates
    double nearestDepth;   // smallest view depth of the box
};

class MaskProjection
{
public:
    // False for views the mask cannot serve (orthographic, a projection that is not a GL
    // perspective, a degenerate viewport). The frame maps to frameWidth × frameHeight mask pixels,
    // surrounded by a border of `border` pixels on every side (the mask is that much larger), and
    // occluders are clipped `clipMargin` pixels beyond the frame.
    bool set(const View& view, std::uint32_t frameWidth, std::uint32_t frameHeight, std::uint32_t border,
             double clipMargin);

    // The whole mask, border included.
    std::uint32_t width() const { return _frameWidth + 2 * _border; }
    std::uint32_t height() const { return _frameHeight + 2 * _border; }
    // The frame inside the mask: [border, border + frameWidth] × [border, border + frameHeight].
    std::uint32_t border() const { return _border; }
    std::uint32_t frameWidth() const { return _frameWidth; }
    std::uint32_t frameHeight() const { return _frameHeight; }
    double nearPlane() const { return _near; }
    // Largest image shift, in mask pixels, of a point at view depth z when the eye moves by δ with
    // its orientation kept, anywhere inside the frame grown by the margin:
    //   shift ≤ f·δ·√(1 + u² + w²) / (z − δ), u, w the normalized image coordinates.
    // Returns the δ for which that shift equals `pixels` at depth `z`.
    double deltaFor(double pixels, double z) const;

    Vec3 toEye(const Vec3& world) const;
    double viewDepth(const Vec3& world) const { return -toEye(world).z; }
    // Eye space → mask coordinates (depth must be > 0).
    glm::dvec2 toMask(const Vec3& eye) const;
    // Depth plane over the mask of the eye-space plane n·p + d = 0 (d ≠ 0).
    DepthPlane depthPlane(const Vec3& n, double d) const;
    // Eye-space planes (distance ≥ 0 inside): view depth ≥ `nearDepth`, and the four sides of the
    // frame grown by the margin.
    std::array<Plane, 5> clipPlanes(double nearDepth) const;
    // The box's rectangle in mask coordinates and its nearest view depth; nothing when a corner
    // lies nearer than half the near plane (the projection of such a box is not bounded).
    std::optional<MaskRect> project(const Aabb& box) const;

private:
    Mat4 _view{1.0};
    double _p00 = 1, _p02 = 0, _p11 = 1, _p12 = 0;
    double _near = 0.1;
    std::uint32_t _frameWidth = 0, _frameHeight = 0, _border = 0;
    double _marginNdcX = 0, _marginNdcY = 0;
    double _fMax = 1, _shiftFactor = 1; // f in mask pixels per unit of u/w; √(1 + r²) at the grown corners
};
} // namespace osgVis::core
