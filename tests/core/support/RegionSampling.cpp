// SPDX-License-Identifier: MIT
#include "RegionSampling.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

using namespace osgVis::core;

namespace osgVis::test
{
Mat4 perspective(double fovyDegrees, double aspect)
{
    return glm::perspective(glm::radians(fovyDegrees), aspect, Near, 1000.0);
}

View lookFrom(const Vec3& eye, const Vec3& direction, const Vec3& up, double fovy, std::uint32_t width,
              std::uint32_t height)
{
    return makeView(glm::lookAt(eye, eye + direction, up), perspective(fovy, double(width) / height), 0.0, width,
                    height);
}

View lookThroughCorner(const Vec3& eye, const Vec3& target, double fovy, std::uint32_t width, std::uint32_t height,
                       double nearPlane, double fraction, std::uint32_t depthBits)
{
    const double aspect = double(width) / height, t = std::tan(glm::radians(fovy) / 2.0);
    // The eye-space ray turned onto the direction of the target.
    const Vec3 from = glm::normalize(Vec3(fraction * aspect * t, fraction * t, -1.0));
    const Vec3 to = glm::normalize(target - eye);
    const Vec3 axis = glm::cross(from, to);
    const double angle = std::atan2(glm::length(axis), glm::dot(from, to));
    const Mat4 eyeToWorld = glm::translate(Mat4(1.0), eye) * glm::rotate(Mat4(1.0), angle, glm::normalize(axis));
    View view = makeView(glm::inverse(eyeToWorld), glm::perspective(glm::radians(fovy), aspect, nearPlane, 1000.0), 0.0,
                         width, height);
    view.depthBits = depthBits;
    return view;
}

std::vector<View> cubeFaces(const Vec3& eye)
{
    const Vec3 directions[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::vector<View> views;
    for (const Vec3& d : directions)
        views.push_back(lookFrom(eye, d, std::abs(d.z) > 0.5 ? Vec3(0, 1, 0) : Vec3(0, 0, 1), 90.0, 64, 64));
    return views;
}

ViewRegion regionAround(const Vec3& center, const Vec3& halfExtent)
{
    ViewRegion region;
    region.eyes = Aabb(center - halfExtent, center + halfExtent);
    region.minNearDistance = 0.5 * Near;
    region.maxNearReach = 2.0 * Near * std::sqrt(3.0); // a 90° square view's reach is √3·near
    return region;
}

std::string missedFromRegion(const RayCastVisibility& rays, const Scene& scene, const ViewRegion& region,
                             const VisibleSet& answer, int randomEyes)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<Vec3> eyes{region.center()};
    for (int k = 0; k < 8; ++k)
        eyes.push_back(region.center() + Vec3((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0) *
                                             region.halfExtent() * 0.999);
    for (int k = 0; k < randomEyes; ++k)
        eyes.push_back(region.center() + Vec3(unit(random), unit(random), unit(random)) * region.halfExtent());
    std::ostringstream missed;
    RayCastOptions options;
    options.samplesPerAxis = 2;
    for (const Vec3& eye : eyes)
        for (const View& face : cubeFaces(eye))
        {
            EXPECT_TRUE(region.holds(face));
            const RayCastResult seen = rays.cast(face, options);
            for (ObjectId id : seen.ids())
                if (!answer.test(id))
                    missed << scene.objects[id].name << " from (" << eye.x << ", " << eye.y << ", " << eye.z << ")\n";
        }
    return missed.str();
}
} // namespace osgVis::test
