// SPDX-License-Identifier: MIT
#include "BuildingTool.h"

#include <osgVis/gen/BoxGeometry.h>

#include <osg/Geode>
#include <osg/Geometry>

#include <cmath>
#include <limits>

namespace osgVis::viewer
{
namespace
{
constexpr double footprint = 6.0, height = 10.0;


bool namedBuilding(const std::string& name)
{
    return name == "building" || name == "dropped building";
}

bool namedGround(const std::string& name)
{
    return name == "street" || name == "pavement";
}

struct Eye
{
    osg::Vec3d position, forward;
};

Eye eyeOf(const osg::Matrixd& view)
{
    const osg::Matrixd toWorld = osg::Matrixd::inverse(view);
    const osg::Vec3d position = toWorld.getTrans();
    osg::Vec3d forward = osg::Vec3d(0, 0, -1) * toWorld - position;
    forward.normalize();
    return {position, forward};
}
} // namespace

BuildingTool::BuildingTool(osg::Node& model, std::function<void()> onChange)
    : _model(&model), _onChange(std::move(onChange))
{
    ExtractionOptions options;
    options.keepTriangles = false;
    const core::Aabb bounds = extractScene(model, options)->scene.bounds();
    _groundZ = bounds.empty() ? 0.0 : bounds.min.z;
    if (osg::Group* group = model.asGroup())
    {
        _dropped = new osg::Group;
        _dropped->setName("dropped buildings");
        group->addChild(_dropped);
    }
}

osg::Node* BuildingTool::dropAhead(const osg::Matrixd& view, double ahead)
{
    if (!_dropped)
        return nullptr;
    const Eye eye = eyeOf(view);
    osg::Vec3d direction(eye.forward.x(), eye.forward.y(), 0.0);
    if (direction.normalize() == 0.0)
        direction.set(0.0, 1.0, 0.0); // looking straight down or up: drop it to the north
    const osg::Vec3d centre = eye.position + direction * (ahead + 0.5 * footprint);
    const osg::Vec3 lo(float(centre.x() - 0.5 * footprint), float(centre.y() - 0.5 * footprint), float(_groundZ));
    const osg::Vec3 hi(float(centre.x() + 0.5 * footprint), float(centre.y() + 0.5 * footprint),
                       float(_groundZ + height));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->setName("dropped building");
    geode->addDrawable(gen::boxGeometry(lo, hi, osg::Vec4(0.3f, 0.5f, 0.9f, 1.f), "dropped building"));
    _dropped->addChild(geode);
    if (_onChange)
        _onChange();
    return geode.get();
}

std::string BuildingTool::removeNearestCentre(const osg::Matrixd& view)
{
    ExtractionOptions options;
    options.keepTriangles = false;
    const osg::ref_ptr<ExtractedScene> scene = extractScene(*_model, options);
    bool anyBuilding = false;
    for (const core::SceneObject& object : scene->scene.objects)
        anyBuilding = anyBuilding || namedBuilding(object.name);

    const Eye eye = eyeOf(view);
    core::ObjectId best = core::InvalidObject;
    double bestAngle = std::numeric_limits<double>::max();
    for (const core::SceneObject& object : scene->scene.objects)
    {
        if (object.bounds.empty() || !object.bounds.finite() || namedGround(object.name) ||
            (anyBuilding && !namedBuilding(object.name)))
            continue;
        const core::Vec3 c = object.bounds.center();
        osg::Vec3d toCentre = osg::Vec3d(c.x, c.y, c.z) - eye.position;
        if (toCentre.normalize() == 0.0 || toCentre * eye.forward <= 0.0)
            continue; // behind the eye
        const double angle = std::acos(std::min(1.0, toCentre * eye.forward));
        if (angle < bestAngle)
        {
            bestAngle = angle;
            best = object.id;
        }
    }
    if (best == core::InvalidObject)
        return {};
    const ObjectRef& ref = scene->refs[best];
    osg::Geode* geode = ref.path.size() >= 2 ? ref.path[ref.path.size() - 2]->asGeode() : nullptr;
    if (!geode || !geode->removeDrawable(ref.drawable.get()))
        return {};
    if (_onChange)
        _onChange();
    return scene->scene.objects[best].name;
}
} // namespace osgVis::viewer
