// SPDX-License-Identifier: MIT
#include "SerializerScenes.h"

#include "../../osg/TestScenes.h"

#include <osgVis/Cell>
#include <osgVis/Occluder>
#include <osgVis/Portal>

#include <string>

namespace osgVis::test
{
namespace
{
osg::ref_ptr<osg::Geometry> namedBox(const std::string& name, const osg::Vec3& min, const osg::Vec3& max,
                                     const osg::Vec4& colour = osg::Vec4(1, 1, 1, 1))
{
    osg::ref_ptr<osg::Geometry> box = makeBox(min, max, colour);
    box->setName(name);
    return box;
}
} // namespace

osg::ref_ptr<VisibilityGroup> makeRoundTripScene()
{
    osg::ref_ptr<VisibilityGroup> root = new VisibilityGroup("frustum+octree");
    root->setName("root");
    core::AsyncOptions async;
    async.lookAheadFrames = 7;
    async.slack = 0.25;
    root->setAsync(true, async);
    ExtractionOptions extraction;
    extraction.keepTriangles = false;
    root->setExtractionOptions(extraction);

    osg::ref_ptr<Occluder> screen = new Occluder;
    screen->setName("screen");
    screen->addPolygon({{-1, 5, 0}, {1, 5, 0}, {1, 5, 2}, {-1, 5, 2}});
    screen->addPolygon({{2, 6, 0}, {3.5, 6, 0}, {2.75, 6, 1.125}});
    screen->addChild(namedBox("screen-box", {-1, 5, 0}, {1, 5.125, 2}));
    root->addChild(screen);

    osg::ref_ptr<Cell> left = new Cell;
    left->setName("left");
    left->setBounds(osg::BoundingBoxd(-4, -2, 0, 0, 2, 3));
    left->addChild(namedBox("left-box", {-3, -1, 0}, {-2, 0, 1}));
    root->addChild(left);

    osg::ref_ptr<Cell> right = new Cell;
    right->setName("right");
    right->setBounds(osg::BoundingBoxd(0, -2, 0, 4, 2, 3));
    right->addChild(namedBox("right-box", {2, 0, 0}, {3, 1, 1}));
    root->addChild(right);

    osg::ref_ptr<Portal> door = new Portal;
    door->setName("door");
    door->setPolygon({{0, -0.5, 0}, {0, 0.5, 0}, {0, 0.5, 2.125}, {0, -0.5, 2.125}});
    door->setCells("left", "right");
    root->addChild(door);

    root->addChild(namedBox("free-box", {-0.5, -6, 0}, {0.5, -5, 1}));
    return root;
}

osg::ref_ptr<VisibilityGroup> makeDemoScene()
{
    osg::ref_ptr<VisibilityGroup> root = new VisibilityGroup("frustum+octree");
    root->setName("osgvis-demo");

    osg::ref_ptr<Occluder> wall = new Occluder;
    wall->setName("wall");
    // Its face towards -Y, counter-clockwise seen from there (x right, z up).
    wall->addPolygon({{-8, 0, -8}, {8, 0, -8}, {8, 0, 8}, {-8, 0, 8}});
    wall->addChild(namedBox("wall-slab", {-8, 0, -8}, {8, 0.25, 8}));
    root->addChild(wall);

    for (int i = 0; i < 10; ++i)
    {
        const float x = -4.75f + float(i);
        // note: a colour of its own keeps each box one object in osgviewer, whose optimizer merges
        // geometries that look alike.
        const osg::Vec4 colour(0.25f + 0.075f * float(i), 0.5f, 1.0f - 0.075f * float(i), 1.0f);
        root->addChild(namedBox("box-" + std::to_string(i), {x, 5, 0}, {x + 0.5f, 5.5f, 0.5f}, colour));
    }
    return root;
}
} // namespace osgVis::test
