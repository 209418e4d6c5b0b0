// SPDX-License-Identifier: MIT
// The oracle lives beside the application's own viewer in one process (the bench does this): it must
// not disturb that viewer's context or its drawables, and must not inherit its culling.

#include "OracleTestScenes.h"

#include <osgVis/oracle/IdBufferOracle.h>
#include <osgVis/oracle/OffscreenContext.h>

#include <osg/Material>
#include <osgUtil/CullVisitor>
#include <osgViewer/Viewer>

#include <gtest/gtest.h>

using namespace oracletest;
using osgVis::oracle::IdBufferOracle;
using osgVis::oracle::OracleSettings;

namespace
{
// The application: a single-threaded pbuffer viewer drawing the scene into an image.
struct ApplicationViewer
{
    osg::ref_ptr<osgViewer::Viewer> viewer = new osgViewer::Viewer;
    osg::ref_ptr<osg::Image> image = new osg::Image;

    ApplicationViewer(osg::Node* scene, const Camera& camera)
    {
        viewer->getCamera()->setGraphicsContext(osgVis::oracle::createOffscreenContext(64, 64).get());
        viewer->getCamera()->setViewport(0, 0, 64, 64);
        viewer->getCamera()->setClearColor(osg::Vec4(0, 0, 1, 1));
        viewer->getCamera()->setViewMatrix(camera.view);
        viewer->getCamera()->setProjectionMatrix(camera.projection);
        viewer->getCamera()->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
        image->allocateImage(64, 64, 1, GL_RGBA, GL_UNSIGNED_BYTE);
        viewer->getCamera()->attach(osg::Camera::COLOR_BUFFER, image.get());
        viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
        viewer->setUseConfigureAffinity(false);
        viewer->setSceneData(scene);
        viewer->realize();
    }

    osg::Vec4 centre()
    {
        viewer->frame();
        return image->getColor(32, 32);
    }
};

// Culls every geode: stands for an application's visibility-culling CullVisitor prototype.
class CullEverything : public osgUtil::CullVisitor
{
public:
    CullVisitor* clone() const override { return new CullEverything(*this); }
    void apply(osg::Geode&) override {}
};
} // namespace

TEST(OracleCoexistence, ApplicationViewerKeepsRenderingTheSharedDrawables)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(inGeode(makeBox({0, 0, 0}, {3, 3, 1}, "red")));
    osg::ref_ptr<osg::Material> red = new osg::Material;
    red->setEmission(osg::Material::FRONT_AND_BACK, osg::Vec4(1, 0, 0, 1));
    red->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    red->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    root->getOrCreateStateSet()->setAttribute(red.get());
    const Camera camera = lookDownZ(20, 40, 1, 100);

    ApplicationViewer application(root.get(), camera);
    const osg::Vec4 before = application.centre();
    EXPECT_GT(before.r(), 0.9f);
    EXPECT_LT(before.b(), 0.1f);

    OracleSettings settings;
    settings.width = settings.height = 128;
    for (int round = 0; round < 2; ++round)
    {
        IdBufferOracle oracle(root.get(), settings);
        for (int frame = 0; frame < 3; ++frame)
        {
            EXPECT_EQ(oracle.visible(camera.view, camera.projection).visible, (std::vector<std::uint32_t>{0}));
            EXPECT_EQ(application.centre(), before) << "round " << round << " frame " << frame;
        }
    }
    // The oracles are gone (their contexts closed); the application still draws the shared box.
    EXPECT_EQ(application.centre(), before);
}

TEST(OracleCoexistence, IgnoresTheApplicationsCullVisitorPrototype)
{
    osg::ref_ptr<osgUtil::CullVisitor> saved = osgUtil::CullVisitor::prototype();
    osgUtil::CullVisitor::prototype() = new CullEverything;
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(inGeode(makeBox({0, 0, 0}, {1, 1, 1}, "box")));
    OracleSettings settings;
    settings.width = settings.height = 64;
    std::vector<std::uint32_t> visible;
    {
        IdBufferOracle oracle(root.get(), settings);
        const Camera camera = lookDownZ(20, 40, 1, 100);
        visible = oracle.visible(camera.view, camera.projection).visible;
    }
    osgUtil::CullVisitor::prototype() = saved;
    EXPECT_EQ(visible, (std::vector<std::uint32_t>{0}));
}
