// SPDX-License-Identifier: MIT
// The top-down map of the report's pictures: each object's footprint in the colour of what the view
// did with it, the frustum's outline and the eye.
//
//   y
//   ^   [2: behind the eye, outside]          . eye at (0,-20), looking along +y, 60° fov
//   |             [1: behind 0, culled]
//   |             [0: drawn]
//   +-----------------------> x
#include <TopDownMap.h>

#include <osgVis/core/scene/Scene.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace osgVis;

namespace
{
std::array<int, 3> pixelAt(const osg::Image& image, const core::Scene& scene, double x, double y)
{
    // The map spans the scene's bounds grown by 2 % of the larger side, aspect kept.
    core::Aabb bounds = scene.bounds();
    const double margin = 0.02 * std::max(bounds.extent().x, bounds.extent().y);
    const double scale = std::min(double(image.s() - 1) / (bounds.extent().x + 2 * margin),
                                  double(image.t() - 1) / (bounds.extent().y + 2 * margin));
    const int px = int((x - bounds.min.x + margin) * scale), py = int((y - bounds.min.y + margin) * scale);
    const unsigned char* p = image.data(px, py);
    return {p[0], p[1], p[2]};
}
} // namespace

TEST(TopDownMap, ColoursDrawnCulledAndOutsideObjectsAndShowsTheFrustum)
{
    core::Scene scene;
    scene.addObject(core::Aabb(core::Vec3(-2, 0, 0), core::Vec3(2, 2, 3)), 12);   // 0: in view, drawn
    scene.addObject(core::Aabb(core::Vec3(-2, 10, 0), core::Vec3(2, 12, 1)), 12); // 1: behind 0, culled
    scene.addObject(core::Aabb(core::Vec3(-30, -40, 0), core::Vec3(-26, -36, 1)), 12); // 2: behind the eye
    core::VisibleSet drawn(scene.objects.size());
    drawn.set(0);
    const core::Mat4 view = glm::lookAt(core::Vec3(0, -20, 1.5), core::Vec3(0, 0, 1.5), core::Vec3(0, 0, 1));
    const core::Mat4 projection = glm::perspective(glm::radians(60.0), 1.0, 0.1, 100.0);
    const apps::TopDownMapColours colours;
    const osg::ref_ptr<osg::Image> map = apps::drawTopDownMap(scene, drawn, view, projection, 200, colours);
    ASSERT_TRUE(map.valid());
    EXPECT_EQ(map->t(), 200);
    EXPECT_GT(map->s(), 100); // wider than tall? the scene is 32 x 52: narrower, but not a sliver
    const auto colour = [](const unsigned char c[3]) { return std::array<int, 3>{c[0], c[1], c[2]}; };
    EXPECT_EQ(pixelAt(*map, scene, 0, 1), colour(colours.drawn));
    EXPECT_EQ(pixelAt(*map, scene, 0, 11), colour(colours.culled));
    EXPECT_EQ(pixelAt(*map, scene, -28, -38), colour(colours.outside));
    EXPECT_EQ(pixelAt(*map, scene, 0, -20), colour(colours.eye));
    EXPECT_EQ(pixelAt(*map, scene, 15, 0), colour(colours.background));
    std::size_t frustumPixels = 0;
    for (int y = 0; y < map->t(); ++y)
        for (int x = 0; x < map->s(); ++x)
            frustumPixels += std::array<int, 3>{map->data(x, y)[0], map->data(x, y)[1], map->data(x, y)[2]} ==
                             colour(colours.frustum);
    EXPECT_GT(frustumPixels, 100u) << "the frustum's side edges run from the eye to the edge of the map";
}
