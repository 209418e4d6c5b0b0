// SPDX-License-Identifier: MIT
#include "OracleTestScenes.h"

#include <osg/BlendFunc>
#include <osg/StateSet>

#include <algorithm>

namespace oracletest
{
osg::ref_ptr<osg::Geometry> makeBox(const osg::Vec3& c, const osg::Vec3& h, const std::string& name)
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (int i = 0; i < 8; ++i)
        v->push_back(c + osg::Vec3((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z()));
    // Corner i has bit 0 = +x, bit 1 = +y, bit 2 = +z; faces counter-clockwise seen from outside.
    const GLushort faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    osg::ref_ptr<osg::DrawElementsUShort> triangles = new osg::DrawElementsUShort(GL_TRIANGLES);
    for (const auto& f : faces)
        for (GLushort i : {f[0], f[1], f[2], f[0], f[2], f[3]})
            triangles->push_back(i);
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName(name);
    geometry->setVertexArray(v.get());
    geometry->addPrimitiveSet(triangles.get());
    return geometry;
}

osg::ref_ptr<osg::Geometry> makeQuadZ(float xMin, float xMax, float yMin, float yMax, float z0, bool faceUp,
                                      const std::string& name)
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->push_back(osg::Vec3(xMin, yMin, z0));
    v->push_back(osg::Vec3(xMax, yMin, z0));
    v->push_back(osg::Vec3(xMax, yMax, z0));
    v->push_back(osg::Vec3(xMin, yMax, z0));
    if (!faceUp)
        std::reverse(v->begin(), v->end());
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName(name);
    geometry->setVertexArray(v.get());
    geometry->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4));
    return geometry;
}

osg::ref_ptr<osg::Geode> inGeode(osg::Drawable* drawable)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(drawable);
    return geode;
}

void makeTransparent(osg::Node& node)
{
    osg::StateSet* state = node.getOrCreateStateSet();
    state->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
    state->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
}

Camera lookDownZ(double eyeZ, double fovyDegrees, double zNear, double zFar)
{
    Camera camera;
    camera.view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, eyeZ), osg::Vec3d(0, 0, eyeZ - 1), osg::Vec3d(0, 1, 0));
    camera.projection = osg::Matrixd::perspective(fovyDegrees, 1.0, zNear, zFar);
    return camera;
}

osg::Vec3d worldAtNdc(const Camera& camera, double ndcX, double ndcY, double depth)
{
    const osg::Matrixd ndcToEye = osg::Matrixd::inverse(camera.projection);
    const osg::Vec3d nearEye = osg::Vec3d(ndcX, ndcY, -1.0) * ndcToEye;
    const osg::Vec3d farEye = osg::Vec3d(ndcX, ndcY, 1.0) * ndcToEye;
    const double s = (-depth - nearEye.z()) / (farEye.z() - nearEye.z());
    const osg::Vec3d eye = nearEye + (farEye - nearEye) * s;
    return eye * osg::Matrixd::inverse(camera.view);
}

std::vector<std::string> namesOf(const std::vector<osg::ref_ptr<osg::Drawable>>& drawables,
                                 const std::vector<std::uint32_t>& indices)
{
    std::vector<std::string> names;
    for (std::uint32_t i : indices)
        names.push_back(drawables.at(i)->getName());
    std::sort(names.begin(), names.end());
    return names;
}
} // namespace oracletest
