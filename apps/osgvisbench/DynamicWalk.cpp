// SPDX-License-Identifier: MIT
#include "DynamicWalk.h"

#include <osgVis/gen/BoxGeometry.h>

#include <osg/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

namespace osgVis::bench
{
namespace
{
constexpr std::size_t carCount = 12;
constexpr double carSpacingSeconds = 2.0; // cars drive this far apart along the walk
constexpr double carLateral = 2.5;        // metres right of the walk line
constexpr std::size_t buildingsPerWave = 3;


// The walk key at time t (the last key not after t), wrapping around the walk's duration.
const core::WalkKey& keyAt(const std::vector<core::WalkKey>& keys, double t)
{
    const double duration = keys.back().time - keys.front().time;
    if (duration > 0.0)
        t = keys.front().time + std::fmod(t - keys.front().time, duration);
    const auto after = std::upper_bound(keys.begin(), keys.end(), t,
                                        [](double time, const core::WalkKey& key) { return time < key.time; });
    return after == keys.begin() ? keys.front() : *(after - 1);
}
} // namespace

DynamicWalk::DynamicWalk(osg::Group& root, const ExtractedScene& model, const core::Walk& streets, std::size_t frames,
                         std::uint32_t seed)
    : _root(&root), _traffic(new osg::Group), _dropped(new osg::Group), _streets(streets.keys), _frames(frames)
{
    _traffic->setName("dynamic traffic");
    _dropped->setName("dropped buildings");
    const core::Aabb bounds = model.scene.bounds();
    _groundZ = bounds.empty() ? 0.0 : bounds.min.z;
    for (std::size_t i = 0; i < carCount && !_streets.empty(); ++i)
    {
        osg::ref_ptr<osg::MatrixTransform> car = new osg::MatrixTransform;
        car->setName("car");
        car->setDataVariance(osg::Object::DYNAMIC); // the extraction flags its box OBJECT_DYNAMIC
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(gen::boxGeometry({-2.f, -1.f, 0.f}, {2.f, 1.f, 1.5f}, {0.8f, 0.1f, 0.1f, 1.f}, "car"));
        car->addChild(geode);
        _traffic->addChild(car);
        _cars.push_back(car);
    }
    planBuildings(model, seed);
    reset();
}

void DynamicWalk::planBuildings(const ExtractedScene& model, std::uint32_t seed)
{
    std::vector<core::ObjectId> buildings;
    for (const core::SceneObject& object : model.scene.objects)
        if (object.name == "building" && !object.bounds.empty())
            buildings.push_back(object.id);
    if (buildings.empty())
        for (const core::SceneObject& object : model.scene.objects)
            if (!object.bounds.empty() && object.bounds.finite())
                buildings.push_back(object.id);
    std::mt19937 rng(seed ^ 0xd1a6u);
    std::shuffle(buildings.begin(), buildings.end(), rng);
    std::uniform_real_distribution<double> height(5.0, 20.0);

    // The first shuffled buildings carry the drops, the next ones are deleted: a dropped box never
    // stands on a deleted building.
    std::size_t next = 0;
    for (auto& wave : _drops)
        for (std::size_t i = 0; i < buildingsPerWave && next < buildings.size(); ++i, ++next)
        {
            const core::Aabb& base = model.scene.objects[buildings[next]].bounds;
            const core::Vec3 c = base.center(), e = base.extent() * 0.25;
            const float top = float(base.max.z);
            osg::ref_ptr<osg::Geode> geode = new osg::Geode;
            geode->addDrawable(gen::boxGeometry(osg::Vec3(float(c.x - e.x), float(c.y - e.y), top),
                                           osg::Vec3(float(c.x + e.x), float(c.y + e.y), top + float(height(rng))),
                                           {0.3f, 0.5f, 0.9f, 1.f}, "dropped building"));
            wave.push_back(geode);
        }
    for (auto& wave : _removals)
        for (std::size_t i = 0; i < buildingsPerWave && next < buildings.size(); ++i, ++next)
        {
            const ObjectRef& ref = model.refs[buildings[next]];
            osg::Geode* geode = ref.path.size() >= 2 ? ref.path[ref.path.size() - 2]->asGeode() : nullptr;
            if (geode)
                wave.push_back({geode, ref.drawable});
        }
}

void DynamicWalk::reset()
{
    _dropped->removeChildren(0, _dropped->getNumChildren());
    for (const auto& wave : _removals)
        for (const Removal& removal : wave)
            if (!removal.geode->containsDrawable(removal.drawable.get()))
                removal.geode->addDrawable(removal.drawable.get());
    if (!_root->containsNode(_traffic.get()))
        _root->addChild(_traffic);
    if (!_root->containsNode(_dropped.get()))
        _root->addChild(_dropped);
    placeCars(0);
    _next = 1;
    _counts = {};
}

void DynamicWalk::placeCars(std::size_t frame)
{
    if (_streets.empty() || _frames == 0)
        return;
    // Frame f sits at the same fraction of the streets' walk as of the bench's frames.
    const double start = _streets.front().time, duration = _streets.back().time - start;
    const double t = start + duration * double(frame) / double(_frames);
    for (std::size_t i = 0; i < _cars.size(); ++i)
    {
        const core::WalkKey& key = keyAt(_streets, t + carSpacingSeconds * double(i + 1));
        const core::Vec3 forward = key.center - key.eye;
        const double heading = std::atan2(forward.y, forward.x);
        const double side = i % 2 == 0 ? -carLateral : carLateral;
        const osg::Vec3d place(key.eye.x + side * std::sin(heading), key.eye.y - side * std::cos(heading), _groundZ);
        _cars[i]->setMatrix(osg::Matrixd::rotate(heading, osg::Vec3d(0, 0, 1)) * osg::Matrixd::translate(place));
    }
}

bool DynamicWalk::advanceTo(std::size_t frame)
{
    bool changed = false;
    for (; _next <= frame; ++_next)
    {
        placeCars(_next);
        _counts.carMoves += _cars.size();
        changed = changed || !_cars.empty();
        for (std::size_t wave = 0; wave < 2; ++wave)
        {
            if (_next == _frames * (wave + 1) / 4)
                for (const osg::ref_ptr<osg::Node>& building : _drops[wave])
                {
                    _dropped->addChild(building);
                    ++_counts.buildingsDropped;
                    changed = true;
                }
            if (_next == _frames * (wave + 1) / 3)
                for (const Removal& removal : _removals[wave])
                {
                    removal.geode->removeDrawable(removal.drawable.get());
                    ++_counts.buildingsRemoved;
                    changed = true;
                }
        }
    }
    return changed;
}
} // namespace osgVis::bench
