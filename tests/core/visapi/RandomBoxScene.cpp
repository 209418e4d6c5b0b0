// SPDX-License-Identifier: MIT
#include "RandomBoxScene.h"

#include "BoxScenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <random>
#include <string>

namespace osgVis::test
{
core::Scene randomBoxScene(unsigned seed, int count)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> position(-100.0, 100.0), size(0.1, 10.0);
    core::Scene scene;
    for (int i = 0; i < count; ++i)
    {
        const core::Vec3 lo(position(random), position(random), position(random));
        const core::Vec3 hi = lo + core::Vec3(size(random), size(random), size(random));
        addBox(scene, lo, hi, "box" + std::to_string(i));
    }
    return scene;
}

std::vector<core::View> randomViews(unsigned seed, int count)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> eye(-120.0, 120.0), target(-50.0, 50.0), fov(30.0, 90.0), far(50.0, 300.0);
    std::vector<core::View> views;
    for (int i = 0; i < count; ++i)
    {
        const core::Vec3 from(eye(random), eye(random), eye(random));
        const core::Vec3 to(target(random), target(random), target(random));
        const core::Mat4 view = glm::lookAt(from, to, core::Vec3(0.0, 0.0, 1.0));
        const core::Mat4 projection = glm::perspective(glm::radians(fov(random)), 4.0 / 3.0, 0.1, far(random));
        views.push_back(core::makeView(view, projection));
    }
    return views;
}
} // namespace osgVis::test
