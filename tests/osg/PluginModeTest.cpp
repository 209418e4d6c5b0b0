// SPDX-License-Identifier: MIT
// A plugin module (lib/osgvis-modules/osgvis_module_cfrustum.so) as a VisibilityGroup's mode: found
// by name with nothing rebuilt, it answers what the built-in frustum module answers, in a chain too;
// a broken plugin is refused with its file and reason. Bare cull visitors, no GL.
//
//   □ x=-10   □ x=-20      ◉ eye at the origin       □ x=+10   □ x=+20
//   views look down -x and +x; the boxes behind the eye are culled
#include "TestScenes.h"

#include <osgVis/ViewCuller>
#include <osgVis/VisibilityGroup>
#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/visapi.h>

#include <osg/Geode>

#include <gtest/gtest.h>

#include <cstdlib>

using osgVis::core::ObjectId;
using osgVis::test::makeBox;

namespace
{
osg::ref_ptr<osgVis::VisibilityGroup> fourBoxes(const std::string& modes)
{
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup(modes);
    for (float x : {-10.f, -20.f, 10.f, 20.f})
    {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(makeBox(osg::Vec3(x - 1, -1, -1), osg::Vec3(x + 1, 1, 1)));
        group->addChild(geode);
    }
    return group;
}

std::vector<ObjectId> visibleLookingAlongX(osgVis::VisibilityGroup& group, double direction)
{
    osg::ref_ptr<osgUtil::CullVisitor> view = new osgUtil::CullVisitor;
    view->setIdentifier(new osgUtil::CullVisitor::Identifier);
    const auto answer = group.getViewCuller()->cull(
        *view, group, osg::Matrixd::lookAt(osg::Vec3d(0, 0, 0), osg::Vec3d(direction, 0, 0), osg::Vec3d(0, 0, 1)),
        osg::Matrixd::perspective(40.0, 1.0, 0.5, 100.0));
    return answer.visible ? answer.visible->ids() : std::vector<ObjectId>{};
}
} // namespace

TEST(PluginMode, VisibilityGroupCullsWithAPluginModule)
{
    for (const char* modes : {"cfrustum", "frustum+cfrustum", "cfrustum,frustum"})
    {
        osg::ref_ptr<osgVis::VisibilityGroup> group = fourBoxes(modes);
        EXPECT_EQ(visibleLookingAlongX(*group, -1), (std::vector<ObjectId>{0, 1})) << modes;
        EXPECT_EQ(visibleLookingAlongX(*group, +1), (std::vector<ObjectId>{2, 3})) << modes;
    }
}

TEST(PluginMode, BrokenPluginIsRefusedWithItsFileAndReason)
{
    setenv("OSGVIS_MODULE_PATH", OSGVIS_BROKEN_MODULE_DIR, 1);
    try
    {
        fourBoxes("frustum+broken-version");
        ADD_FAILURE() << "no exception";
    }
    catch (const osgVis::core::ModuleLoadError& e)
    {
        EXPECT_EQ(std::string(e.what()), "mode 'broken-version': plugin " OSGVIS_BROKEN_MODULE_DIR
                                         "/osgvis_module_broken-version.so: built against visapi 2.0, this "
                                         "osgVis has 1." +
                                             std::to_string(OSGVIS_VISAPI_VERSION_MINOR));
    }
    unsetenv("OSGVIS_MODULE_PATH");
}
