// SPDX-License-Identifier: MIT
// A program outside the osgVis tree: wraps a box in a VisibilityGroup and lists the culling modes.
#include <osg/Geode>
#include <osg/Shape>
#include <osg/ShapeDrawable>
#include <osgVis/VisibilityGroup>
#include <osgVis/core/api/ModuleRegistry.h>

#include <iostream>

int main()
{
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup;
    group->setModes("frustum");
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(new osg::ShapeDrawable(new osg::Box(osg::Vec3(), 1.0f)));
    group->addChild(geode);
    std::cout << "modes:";
    for (const auto& name : osgVis::core::moduleNames())
        std::cout << ' ' << name;
    std::cout << "\nchildren: " << group->getNumChildren() << " (" << group->getModes() << ")\n";
    std::cout << "consumer ok\n";
    return group->getNumChildren() == 1 ? 0 : 1;
}
