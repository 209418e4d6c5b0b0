// SPDX-License-Identifier: MIT
#pragma once

// Small scenes and cameras for the oracle tests. Coordinates: the eye looks down -z from +z unless a
// test says otherwise; boxes are axis-aligned, 12 counter-clockwise-outward triangles.

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Group>
#include <osg/Matrixd>

#include <cstdint>
#include <string>
#include <vector>

namespace oracletest
{
osg::ref_ptr<osg::Geometry> makeBox(const osg::Vec3& centre, const osg::Vec3& halfExtents, const std::string& name);
// A single quad in the z = z0 plane; faceUp: counter-clockwise seen from +z.
osg::ref_ptr<osg::Geometry> makeQuadZ(float xMin, float xMax, float yMin, float yMax, float z0, bool faceUp,
                                      const std::string& name);
osg::ref_ptr<osg::Geode> inGeode(osg::Drawable* drawable);
void makeTransparent(osg::Node& node); // blending on + TRANSPARENT_BIN, as applications do it

struct Camera
{
    osg::Matrixd view;
    osg::Matrixd projection;
};
Camera lookDownZ(double eyeZ, double fovyDegrees, double zNear, double zFar); // eye at (0, 0, eyeZ), aspect 1
// World point at NDC (x, y) and eye-space distance `depth` along the view axis (perspective or ortho).
osg::Vec3d worldAtNdc(const Camera& camera, double ndcX, double ndcY, double depth);

// The drawables of an oracle's objects (anything with objects() listing OracleObjects), in its order.
template <typename Oracle> std::vector<osg::ref_ptr<osg::Drawable>> drawablesOf(const Oracle& oracle)
{
    std::vector<osg::ref_ptr<osg::Drawable>> drawables;
    for (const auto& object : oracle.objects())
        drawables.push_back(object.drawable);
    return drawables;
}

// The names of the objects at these indices, sorted, for readable expectations.
std::vector<std::string> namesOf(const std::vector<osg::ref_ptr<osg::Drawable>>& drawables,
                                 const std::vector<std::uint32_t>& indices);
} // namespace oracletest
