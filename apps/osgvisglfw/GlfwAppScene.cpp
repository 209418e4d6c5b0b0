// SPDX-License-Identifier: MIT
#include "GlfwAppScene.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/gen/BoxGeometry.h>

#include <osg/Geode>
#include <osgDB/ReadFile>

#include <filesystem>

namespace osgVis::glfwapp
{
const char* const OsgMode = "osg";

osg::ref_ptr<osg::Node> demoScene()
{
    // Seen from the side (the trackball's home is far out on -y at about mid-wall height):
    //
    //   z            wall (y 0..0.5, x -10..10, z 0..6)
    //   ^             ██
    //   |  [front]    ██   [hidden] [hidden]
    //   +-------------██----------------------> y
    struct Box
    {
        osg::Vec3 lo, hi;
        osg::Vec4 colour;
        const char* name;
    };
    const osg::Vec4 grey(0.6f, 0.6f, 0.6f, 1.f);
    const Box boxes[] = {
        {{-10.f, 0.f, 0.f}, {10.f, 0.5f, 6.f}, grey, "wall"},
        {{-7.f, -5.f, 0.f}, {-5.f, -3.f, 2.f}, {0.9f, 0.3f, 0.2f, 1.f}, "front left"},
        {{4.f, -4.f, 0.f}, {6.f, -2.f, 3.f}, {0.2f, 0.7f, 0.3f, 1.f}, "front right"},
        {{-5.f, 3.f, 0.f}, {-3.f, 5.f, 2.f}, {0.9f, 0.8f, 0.2f, 1.f}, "hidden 1"},
        {{-1.f, 5.f, 0.f}, {1.f, 7.f, 3.f}, {0.3f, 0.4f, 0.9f, 1.f}, "hidden 2"},
        {{3.f, 2.f, 0.f}, {5.f, 4.f, 1.5f}, {0.8f, 0.3f, 0.8f, 1.f}, "hidden 3"},
        {{-1.f, 7.5f, 0.f}, {2.f, 9.5f, 2.5f}, {0.3f, 0.8f, 0.8f, 1.f}, "hidden 4"},
    };
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    scene->setName("osgvisglfw demo");
    for (const Box& box : boxes)
    {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->setName(box.name);
        geode->addDrawable(gen::boxGeometry(box.lo, box.hi, box.colour, box.name));
        scene->addChild(geode);
    }
    // The boxes carry no normals: flat colours read better than uniform lighting.
    scene->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    return scene;
}

osg::ref_ptr<osg::Node> readModel(const std::string& path)
{
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw SceneError("cannot read model '" + path + "': no such file");
    osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(path);
    if (!model)
        throw SceneError("cannot read model '" + path +
                         "': no OpenSceneGraph plugin could load it");
    if (!model->getBound().valid())
        throw SceneError("model '" + path + "' holds nothing to draw (empty bounds)");
    return model;
}

CulledScene cullWithMode(osg::Node* model, const std::string& mode)
{
    if (mode == OsgMode)
        return {model, nullptr};
    osg::ref_ptr<VisibilityGroup> group = new VisibilityGroup;
    try
    {
        group->setModes(mode);
    }
    catch (const core::ModuleLoadError&)
    {
        throw; // a plugin was found but is unusable: its message names the file and the reason
    }
    catch (const core::UnknownModeError&)
    {
        std::string known = OsgMode;
        for (const std::string& name : core::moduleNames())
            known += ", " + name;
        throw core::UnknownModeError("unknown mode '" + mode + "'; modes: " + known +
                                     " (chain modules with +, e.g. frustum+octree; a plugin osgvis_module_<name>.so on OSGVIS_MODULE_PATH "
                                     "or in lib/osgvis-modules is a mode too)");
    }
    group->addChild(model);
    return {group, group};
}
} // namespace osgVis::glfwapp
