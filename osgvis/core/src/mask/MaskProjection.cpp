// SPDX-License-Identifier: MIT
#include "MaskProjection.h"

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
bool MaskProjection::set(const View& view, std::uint32_t frameWidth, std::uint32_t frameHeight, std::uint32_t border,
                         double clipMargin)
{
    const Mat4& p = view.projectionMatrix;
    // GLM is column-major: p[column][row]. A GL perspective has the last row (0, 0, -1, 0) and no
    // translation in x/y; anything else (orthographic, projective tricks) gets no mask.
    const bool perspective = p[0][3] == 0.0 && p[1][3] == 0.0 && p[2][3] == -1.0 && p[3][3] == 0.0 &&
                             p[3][0] == 0.0 && p[3][1] == 0.0 && p[0][1] == 0.0 && p[1][0] == 0.0;
    if (view.orthographic || !perspective || frameWidth == 0 || frameHeight == 0 || p[0][0] <= 0.0 || p[1][1] <= 0.0)
        return false;
    _view = view.viewMatrix;
    _p00 = p[0][0];
    _p11 = p[1][1];
    _p02 = p[2][0];
    _p12 = p[2][1];
    const double p22 = p[2][2], p32 = p[3][2];
    _near = p22 != 1.0 ? p32 / (p22 - 1.0) : 0.0;
    if (!(_near > 0.0) || !std::isfinite(_near))
        return false;
    _frameWidth = frameWidth;
    _frameHeight = frameHeight;
    _border = border;
    _marginNdcX = 2.0 * clipMargin / frameWidth;
    _marginNdcY = 2.0 * clipMargin / frameHeight;
    const double fx = _p00 * frameWidth * 0.5, fy = _p11 * frameHeight * 0.5;
    _fMax = std::max(fx, fy);
    const double uMax = (1.0 + _marginNdcX + std::abs(_p02)) / _p00;
    const double wMax = (1.0 + _marginNdcY + std::abs(_p12)) / _p11;
    _shiftFactor = std::sqrt(1.0 + uMax * uMax + wMax * wMax);
    return true;
}

double MaskProjection::deltaFor(double pixels, double z) const
{
    // f·δ·s / (z − δ) = pixels  ⇔  δ = pixels·z / (f·s + pixels)
    if (!(pixels > 0.0) || !(z > 0.0))
        return 0.0;
    return pixels * z / (_fMax * _shiftFactor + pixels);
}

Vec3 MaskProjection::toEye(const Vec3& world) const
{
    return Vec3(_view * Vec4(world, 1.0));
}

glm::dvec2 MaskProjection::toMask(const Vec3& eye) const
{
    const double z = -eye.z;
    const double u = eye.x / z, w = eye.y / z;
    const double ndcX = _p00 * u - _p02, ndcY = _p11 * w - _p12;
    return {(ndcX + 1.0) * 0.5 * _frameWidth + _border, (ndcY + 1.0) * 0.5 * _frameHeight + _border};
}

DepthPlane MaskProjection::depthPlane(const Vec3& n, double d) const
{
    // A point at view depth z seen at image coordinates (u, w) is z·(u, w, −1); on the plane
    // z·(n.x·u + n.y·w − n.z) = −d, so 1/z = −(n.x·u + n.y·w − n.z)/d, and u, w are affine in the
    // mask coordinates: u = (2(x − border)/W − 1 + p02)/p00.
    const double au = 2.0 / (_frameWidth * _p00), bu = (_p02 - 1.0) / _p00 - au * _border;
    const double aw = 2.0 / (_frameHeight * _p11), bw = (_p12 - 1.0) / _p11 - aw * _border;
    DepthPlane plane;
    plane.inverse = true;
    plane.a = -n.x * au / d;
    plane.b = -n.y * aw / d;
    plane.c = -(n.x * bu + n.y * bw - n.z) / d;
    return plane;
}

std::array<Plane, 5> MaskProjection::clipPlanes(double nearDepth) const
{
    // In eye space, x_ndc ≤ 1 + m  ⇔  (1 + m)(−z) − (p00·x + p02·z) ≥ 0, and so on.
    const double mx = 1.0 + _marginNdcX, my = 1.0 + _marginNdcY;
    return {Plane({0.0, 0.0, -1.0}, -nearDepth), Plane({-_p00, 0.0, -mx - _p02}, 0.0),
            Plane({_p00, 0.0, _p02 - mx}, 0.0), Plane({0.0, -_p11, -my - _p12}, 0.0),
            Plane({0.0, _p11, _p12 - my}, 0.0)};
}

std::optional<MaskRect> MaskProjection::project(const Aabb& box) const
{
    MaskRect rect{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                  std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest(),
                  std::numeric_limits<double>::max()};
    // The corners in eye space from one transformed corner and the three transformed edges.
    const Vec3 base = toEye(box.min), extent = box.max - box.min;
    const Vec3 edges[3] = {Vec3(_view[0]) * extent.x, Vec3(_view[1]) * extent.y, Vec3(_view[2]) * extent.z};
    for (int i = 0; i < 8; ++i)
    {
        const Vec3 eye = base + ((i & 1) ? edges[0] : Vec3(0.0)) + ((i & 2) ? edges[1] : Vec3(0.0)) +
                         ((i & 4) ? edges[2] : Vec3(0.0));
        const double z = -eye.z;
        if (!(z > 0.5 * _near))
            return std::nullopt;
        const glm::dvec2 m = toMask(eye);
        rect.x0 = std::min(rect.x0, m.x);
        rect.y0 = std::min(rect.y0, m.y);
        rect.x1 = std::max(rect.x1, m.x);
        rect.y1 = std::max(rect.y1, m.y);
        rect.nearestDepth = std::min(rect.nearestDepth, z);
    }
    return rect;
}
} // namespace osgVis::core
