// SPDX-License-Identifier: MIT
#include "BoxScenes.h"

#include <glm/gtc/matrix_transform.hpp>

namespace osgVis::test
{
using namespace core;

std::vector<Triangle> boxTriangles(const Vec3& lo, const Vec3& hi)
{
    const Aabb box(lo, hi);
    const auto p = [&](int i) { return Vec3f(box.corner(i)); };
    // Counter-clockwise seen from outside.
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::vector<Triangle> t;
    for (const auto& q : quads)
    {
        t.push_back({p(q[0]), p(q[1]), p(q[2])});
        t.push_back({p(q[0]), p(q[2]), p(q[3])});
    }
    return t;
}

Aabb boundsOf(const std::vector<Triangle>& triangles)
{
    Aabb bounds;
    for (const Triangle& t : triangles)
        for (const Vec3f& v : {t.a, t.b, t.c})
            bounds.expand(Vec3(v));
    return bounds;
}

ObjectId addTriangles(Scene& scene, const std::vector<Triangle>& triangles, const std::string& name,
                      std::uint32_t flags)
{
    const ObjectId id = scene.addObject(boundsOf(triangles), std::uint32_t(triangles.size()), flags, name);
    scene.objects[id].firstTriangle = std::uint32_t(scene.triangles.size());
    scene.triangles.insert(scene.triangles.end(), triangles.begin(), triangles.end());
    return id;
}

ObjectId addBox(Scene& scene, const Vec3& lo, const Vec3& hi, const std::string& name,
                std::uint32_t flags)
{
    return addTriangles(scene, boxTriangles(lo, hi), name, flags);
}

void addRoomRowShell(core::Scene& s, int rooms)
{
    const double length = 4.0 * rooms;
    addBox(s, {-0.2, -0.2, -0.2}, {length + 0.2, 4.2, 0.0}, "floor");
    addBox(s, {-0.2, -0.2, 3.0}, {length + 0.2, 4.2, 3.2}, "ceiling");
    addBox(s, {-0.2, -0.2, 0.0}, {length + 0.2, 0.0, 3.0}, "south wall");
    addBox(s, {-0.2, 4.0, 0.0}, {length + 0.2, 4.2, 3.0}, "north wall");
    addBox(s, {-0.2, 0.0, 0.0}, {0.0, 4.0, 3.0}, "west wall");
    addBox(s, {length, 0.0, 0.0}, {length + 0.2, 4.0, 3.0}, "east wall");
}

City makeCity()
{
    City city;
    for (int bx = 0; bx < 6; ++bx)
        for (int by = 0; by < 6; ++by)
            for (int q = 0; q < 4; ++q)
            {
                const double x0 = bx * 30.0 + (q & 1) * 12.0, y0 = by * 30.0 + (q >> 1) * 12.0;
                const double height = 8.0 + double((bx * 7 + by * 13 + q * 5) % 11) * 2.5;
                city.buildings.push_back(addBox(city.scene, {x0, y0, 0.0}, {x0 + 8.0, y0 + 8.0, height},
                                                "building " + std::to_string(bx) + "," + std::to_string(by) +
                                                    "," + std::to_string(q)));
            }
    for (int street = 0; street < 6; ++street)
        for (int k = 0; k < 18; ++k)
        {
            const double x = street * 30.0 - 9.0 + (k % 2) * 8.0, y = k * 10.0 + 3.0;
            addBox(city.scene, {x, y, 0.0}, {x + 1.0, y + 1.0, 1.5}, "kiosk " + std::to_string(street) + "," +
                                                                         std::to_string(k));
        }
    return city;
}


std::vector<core::View> cityStreetViews()
{
    const core::Mat4 projection = glm::perspective(glm::radians(60.0), 4.0 / 3.0, 0.1, 1000.0);
    std::vector<core::View> views;
    for (int f = 0; f < 6; ++f)
    {
        const double yaw = glm::radians(-20.0 + 8.0 * f);
        const core::Vec3 eye(85.0, -8.0 + 25.0 * f, 1.7);
        views.push_back(core::makeView(
            glm::lookAt(eye, eye + core::Vec3(std::sin(yaw), std::cos(yaw), -0.02), core::Vec3(0, 0, 1)), projection,
            0.0, 320, 240));
    }
    return views;
}
} // namespace osgVis::test
