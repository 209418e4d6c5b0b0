// SPDX-License-Identifier: MIT
// osgvisbench --explain on a model with one object per reason not to occlude: the reasons are named
// with their counts, and the largest never-culled objects are listed.
//
//   top view:   [plain wall]  [blended box]  [alpha-tested box]  [box under an LOD]  [wireframe box]
#include "AppProcess.h"

#include <osg/AlphaFunc>
#include <osg/BlendFunc>
#include <osg/Geode>
#include <osg/LOD>
#include <osg/PolygonMode>
#include <osg/ShapeDrawable>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

using namespace osgVis::test;

namespace
{
osg::ref_ptr<osg::Geode> box(float x)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    const float lo[3] = {x, 0, 0}, hi[3] = {x + 1, 1, 1};
    // Six quads of a unit box, counter-clockwise from outside.
    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {3, 0, 4, 7}};
    const osg::Vec3 p[8] = {{lo[0], lo[1], lo[2]}, {hi[0], lo[1], lo[2]}, {hi[0], hi[1], lo[2]}, {lo[0], hi[1], lo[2]},
                            {lo[0], lo[1], hi[2]}, {hi[0], lo[1], hi[2]}, {hi[0], hi[1], hi[2]}, {lo[0], hi[1], hi[2]}};
    for (const auto& f : faces)
        for (int k = 0; k < 4; ++k)
            v->push_back(p[f[k]]);
    geometry->setVertexArray(v.get());
    geometry->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 24));
    geode->addDrawable(geometry.get());
    return geode;
}
} // namespace

TEST(BenchExplain, NamesWhyObjectsAreNoOccluders)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display (scripts/test.sh provides Xvfb)";
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(box(0));
    osg::ref_ptr<osg::Geode> blended = box(3);
    blended->getOrCreateStateSet()->setAttributeAndModes(new osg::BlendFunc);
    root->addChild(blended);
    osg::ref_ptr<osg::Geode> alpha = box(6);
    alpha->getOrCreateStateSet()->setAttributeAndModes(new osg::AlphaFunc(osg::AlphaFunc::GREATER, 0.5f));
    root->addChild(alpha);
    osg::ref_ptr<osg::LOD> lod = new osg::LOD;
    lod->addChild(box(9), 0.0f, 1e6f);
    root->addChild(lod);
    osg::ref_ptr<osg::Geode> wire = box(12);
    wire->getOrCreateStateSet()->setAttribute(new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::LINE));
    root->addChild(wire);
    const auto dir = scratchDirectory("bench", "explain");
    const std::string model = (dir / "reasons.osgb").string();
    ASSERT_TRUE(osgDB::writeNodeFile(*root, model));

    const AppRun run = runApp(OSGVIS_BENCH_EXE, "--scene '" + model + "' --walk orbit --modes osg,frustum,octree "
                                                "--views 6 --size 160x128 --explain");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string& out = run.output;
    EXPECT_NE(out.find("explain (why culling does or does not work on this model):"), std::string::npos) << out;
    EXPECT_NE(out.find("5 objects, 60 triangles; 1 objects give"), std::string::npos) << out;
    for (const char* reason : {"1  transparent (blending or the transparent bin)", "1  alpha test",
                               "1  under a node that may not draw it every frame", "1  polygon mode lines or points"})
        EXPECT_NE(out.find(reason), std::string::npos) << reason << " in\n" << out;
    EXPECT_NE(out.find("objects whose bounds span more than half the model's diagonal: 0"), std::string::npos) << out;
}
