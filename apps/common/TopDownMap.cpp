// SPDX-License-Identifier: MIT
#include "TopDownMap.h"

#include <osgVis/core/geometry/Frustum.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace osgVis::apps
{
namespace
{
class Canvas
{
public:
    Canvas(osg::Image& image, const core::Aabb& bounds) : _image(image), _bounds(bounds)
    {
        const core::Vec3 extent = bounds.extent();
        _scale = std::min(double(image.s() - 1) / std::max(extent.x, 1e-9), double(image.t() - 1) / std::max(extent.y, 1e-9));
    }

    double px(double x) const { return (x - _bounds.min.x) * _scale; }
    double py(double y) const { return (y - _bounds.min.y) * _scale; }

    void fill(const unsigned char colour[3])
    {
        for (int y = 0; y < _image.t(); ++y)
            for (int x = 0; x < _image.s(); ++x)
                set(x, y, colour);
    }
    // World rectangle [x0,x1]×[y0,y1], at least one pixel.
    void rect(double x0, double y0, double x1, double y1, const unsigned char colour[3])
    {
        const int a = int(std::floor(px(x0))), b = std::max(a, int(std::floor(px(x1))));
        const int c = int(std::floor(py(y0))), d = std::max(c, int(std::floor(py(y1))));
        for (int y = std::max(c, 0); y <= std::min(d, _image.t() - 1); ++y)
            for (int x = std::max(a, 0); x <= std::min(b, _image.s() - 1); ++x)
                set(x, y, colour);
    }
    // World segment, one pixel wide: clipped to the image (Liang-Barsky), then a DDA in pixel space.
    void line(double x0, double y0, double x1, double y1, const unsigned char colour[3])
    {
        double ax = px(x0), ay = py(y0), bx = px(x1), by = py(y1);
        if (!std::isfinite(ax + ay + bx + by))
            return;
        double t0 = 0.0, t1 = 1.0;
        const double dx = bx - ax, dy = by - ay;
        const double p[4] = {-dx, dx, -dy, dy};
        const double q[4] = {ax, _image.s() - 1 - ax, ay, _image.t() - 1 - ay};
        for (int k = 0; k < 4; ++k)
        {
            if (p[k] == 0.0)
            {
                if (q[k] < 0.0)
                    return;
                continue;
            }
            const double r = q[k] / p[k];
            if (p[k] < 0.0)
                t0 = std::max(t0, r);
            else
                t1 = std::min(t1, r);
        }
        if (!(t0 <= t1))
            return;
        bx = ax + t1 * dx, by = ay + t1 * dy, ax += t0 * dx, ay += t0 * dy;
        const int steps = int(std::ceil(std::max(std::abs(bx - ax), std::abs(by - ay)))) + 1;
        for (int i = 0; i <= steps; ++i)
        {
            const double t = double(i) / steps;
            const int x = int(std::floor(ax + t * (bx - ax))), y = int(std::floor(ay + t * (by - ay)));
            if (x >= 0 && y >= 0 && x < _image.s() && y < _image.t())
                set(x, y, colour);
        }
    }
    void dot(double x, double y, int radius, const unsigned char colour[3])
    {
        const int cx = int(std::floor(px(x))), cy = int(std::floor(py(y)));
        for (int dy = -radius; dy <= radius; ++dy)
            for (int dx = -radius; dx <= radius; ++dx)
                if (dx * dx + dy * dy <= radius * radius && cx + dx >= 0 && cy + dy >= 0 && cx + dx < _image.s() &&
                    cy + dy < _image.t())
                    set(cx + dx, cy + dy, colour);
    }

private:
    void set(int x, int y, const unsigned char colour[3])
    {
        unsigned char* p = _image.data(x, y);
        p[0] = colour[0], p[1] = colour[1], p[2] = colour[2];
    }

    osg::Image& _image;
    core::Aabb _bounds;
    double _scale = 1.0;
};

// The frustum's eight corners in world space (near then far, counter-clockwise).
std::array<core::Vec3, 8> frustumCorners(const core::Mat4& view, const core::Mat4& projection)
{
    const core::Mat4 inverse = glm::inverse(projection * view);
    std::array<core::Vec3, 8> corners;
    const double ndc[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int depth = 0; depth < 2; ++depth)
        for (int i = 0; i < 4; ++i)
        {
            const glm::dvec4 p = inverse * glm::dvec4(ndc[i][0], ndc[i][1], depth ? 1.0 : -1.0, 1.0);
            corners[4 * depth + i] = core::Vec3(p) / p.w;
        }
    return corners;
}
} // namespace

osg::ref_ptr<osg::Image> drawTopDownMap(const core::Scene& scene, const core::VisibleSet& drawn, const core::Mat4& view,
                                        const core::Mat4& projection, unsigned height, const TopDownMapColours& colours)
{
    core::Aabb bounds = scene.bounds();
    const core::Vec3 extent = bounds.extent();
    const double margin = 0.02 * std::max(extent.x, extent.y);
    bounds.min -= core::Vec3(margin, margin, 0.0);
    bounds.max += core::Vec3(margin, margin, 0.0);
    const double aspect = std::max(bounds.extent().x, 1e-9) / std::max(bounds.extent().y, 1e-9);
    const unsigned width = std::clamp(unsigned(std::lround(height * aspect)), 1u, 4u * height);

    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(int(width), int(height), 1, GL_RGB, GL_UNSIGNED_BYTE);
    Canvas canvas(*image, bounds);
    canvas.fill(colours.background);

    const core::Frustum frustum = core::Frustum::fromMatrix(projection * view);
    std::vector<core::ObjectId> order(scene.objects.size());
    std::iota(order.begin(), order.end(), 0u);
    // Larger footprints first, so walls, furniture and buildings show over the floors, ceilings and
    // streets they stand on.
    const auto footprint = [&](core::ObjectId id)
    {
        const core::Vec3 e = scene.objects[id].bounds.extent();
        return e.x * e.y;
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](core::ObjectId a, core::ObjectId b) { return footprint(a) > footprint(b); });
    for (const core::ObjectId id : order)
    {
        const core::Aabb& box = scene.objects[id].bounds;
        if (box.empty() || !std::isfinite(box.min.x + box.max.x + box.min.y + box.max.y))
            continue;
        const unsigned char* colour = drawn.test(id) ? colours.drawn
                                      : frustum.classify(box) == core::Containment::Outside ? colours.outside
                                                                                            : colours.culled;
        canvas.rect(box.min.x, box.min.y, box.max.x, box.max.y, colour);
    }

    const std::array<core::Vec3, 8> corners = frustumCorners(view, projection);
    // Outline on the ground: the near and far quads' edges and the four side edges, flattened.
    for (int i = 0; i < 4; ++i)
    {
        const int j = (i + 1) % 4;
        canvas.line(corners[i].x, corners[i].y, corners[j].x, corners[j].y, colours.frustum);
        canvas.line(corners[4 + i].x, corners[4 + i].y, corners[4 + j].x, corners[4 + j].y, colours.frustum);
        canvas.line(corners[i].x, corners[i].y, corners[4 + i].x, corners[4 + i].y, colours.frustum);
    }
    const core::Vec3 eye = core::Vec3(glm::inverse(view)[3]);
    canvas.dot(eye.x, eye.y, std::max(2, int(height / 100)), colours.eye);
    return image;
}
} // namespace osgVis::apps
