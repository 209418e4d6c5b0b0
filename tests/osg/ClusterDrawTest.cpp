// SPDX-License-Identifier: MIT
// Drawing only the visible clusters (docs/clusters.md): under every OSG threading model, with a
// CompositeViewer of two views (two cull threads at once with CullThreadPerCameraDrawThreadPerContext,
// a draw overlapping the next cull with DrawThreadPerContext), a clustered drawable of every
// primitive kind draws exactly the plain graph's pixels while clusters are culled; so does
// osgVis::CullVisitor, display-listed and VBO input, and a drawable with a user's draw callback
// (which stays whole). Needs a display (Xvfb).
//
//   top view: one Geometry holds a wall across x in [-12, 12] at y = 10 and, behind it at y = 25,
//   eight upright patches of every primitive kind, plus one patch before the wall at y = 0.
//   View "front" walks towards the wall from y = -20 (the patches behind are hidden); view "side"
//   stands at x = 40 looking along -x past the wall's end (it sees them).
#include "ClusterScenes.h"
#include "TestScenes.h"

#include <osgVis/CullVisitor>
#include <osgVis/Statistics>
#include <osgVis/VisibilityGroup>

#include <osg/Geode>
#include <osg/Image>
#include <osgViewer/CompositeViewer>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdlib>

using namespace osgVis::test;

namespace
{
constexpr unsigned Width = 128, Height = 96, Frames = 8;

std::vector<Patch> patches()
{
    std::vector<Patch> out{{{-12, 10, 0}, {24, 0, 0}, {0, 0, 12}, 24, {0.8f, 0.8f, 0.8f, 1}, PatchKind::Triangles}};
    const PatchKind kinds[] = {PatchKind::Triangles, PatchKind::TrianglesShort, PatchKind::Strips, PatchKind::Quads,
                               PatchKind::Fans,      PatchKind::QuadStrips,     PatchKind::ArrayTriangles};
    for (int i = 0; i < 8; ++i)
        out.push_back({{-10.f + 2.5f * i, 25, 0}, {1, 0, 0}, {0, 0, 2}, 12, {0.2f + 0.1f * i, 0.3f, 1, 1}, kinds[i % 7]});
    out.push_back({{-1, 0, 0}, {2, 0, 0}, {0, 0, 1}, 12, {1, 0.3f, 0.2f, 1}, PatchKind::Fans});
    return out;
}

osgVis::ExtractionOptions clusterOptions()
{
    osgVis::ExtractionOptions options;
    options.clusterThreshold = 1000;
    options.clusterTriangles = 128;
    return options;
}

osg::ref_ptr<osg::Group> content(osg::Group* group, osg::Drawable* mesh)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(mesh);
    group->addChild(geode);
    return group;
}

osg::Matrixd viewAt(unsigned view, unsigned frame)
{
    if (view == 0)
        return osg::Matrixd::lookAt(osg::Vec3d(0.3 * frame, -20.0 + 0.5 * frame, 1.7),
                                    osg::Vec3d(0.3 * frame, 0.0 + 0.5 * frame, 1.5), osg::Vec3d(0, 0, 1));
    return osg::Matrixd::lookAt(osg::Vec3d(40.0 - 0.4 * frame, 18, 1.7), osg::Vec3d(0, 18 + 0.1 * frame, 1.2),
                                osg::Vec3d(0, 0, 1));
}

struct Result
{
    std::array<osg::ref_ptr<osg::Image>, 2> images;
    std::array<double, 2> visible{-1, -1}, objects{-1, -1}, clusters{-1, -1};
};

// `cullVisitorModes`: non-empty to cull with osgVis::CullVisitor (installed on both views) instead.
Result render(osg::Node* scene, osgViewer::ViewerBase::ThreadingModel threading,
              const std::string& cullVisitorModes = {})
{
    osgViewer::CompositeViewer viewer;
    viewer.setThreadingModel(threading);
    std::array<osg::ref_ptr<CaptureImage>, 2> captures;
    for (unsigned v = 0; v < 2; ++v)
    {
        osg::ref_ptr<osgViewer::View> view = new osgViewer::View;
        osg::Camera* camera = view->getCamera();
        captures[v] = setUpCapturingCamera(*camera, Width, Height);
        if (!captures[v])
            return {};
        camera->setProjectionMatrixAsPerspective(60.0, double(Width) / Height, 0.1, 200.0);
        camera->getStats()->collectStats("rendering", true);
        if (!cullVisitorModes.empty())
            osgVis::CullVisitor::installOn(*view, cullVisitorModes);
        view->setSceneData(scene);
        viewer.addView(view);
    }
    viewer.realize();
    for (unsigned frame = 0; frame < Frames; ++frame)
    {
        for (unsigned v = 0; v < 2; ++v)
            viewer.getView(v)->getCamera()->setViewMatrix(viewAt(v, frame));
        viewer.frame(0.1 * frame);
    }
    viewer.stopThreading();

    Result result;
    const unsigned last = viewer.getFrameStamp()->getFrameNumber();
    for (unsigned v = 0; v < 2; ++v)
    {
        result.images[v] = captures[v]->image;
        osg::Stats* stats = viewer.getView(v)->getCamera()->getStats();
        stats->getAttribute(last, osgVis::STATS_VISIBLE, result.visible[v]);
        stats->getAttribute(last, osgVis::STATS_OBJECTS, result.objects[v]);
        stats->getAttribute(last, osgVis::STATS_CLUSTERS, result.clusters[v]);
    }
    return result;
}

const osgViewer::ViewerBase::ThreadingModel AllModels[] = {
    osgViewer::ViewerBase::SingleThreaded, osgViewer::ViewerBase::CullDrawThreadPerContext,
    osgViewer::ViewerBase::DrawThreadPerContext, osgViewer::ViewerBase::CullThreadPerCameraDrawThreadPerContext};
} // namespace

TEST(ClusterDraw, TwoViewsDrawThePlainGraphsPixelsUnderEveryThreadingModel)
{
    const Result reference =
        render(content(new osg::Group, makePatchedMesh(patches())).get(), osgViewer::ViewerBase::SingleThreaded);
    if (!reference.images[0] || !reference.images[0]->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    ASSERT_GT(litPixels(*reference.images[0]), Width * Height / 20);
    ASSERT_GT(litPixels(*reference.images[1]), Width * Height / 50);

    for (const bool vbo : {false, true}) // the user's drawable display-listed (OSG's default), or on VBOs
    {
        for (const char* modes : {"frustum", "frustum+octree"})
            for (const auto threading : AllModels)
            {
                // note: a fresh drawable per viewer, as GL objects of a closed context are not reused
                osg::ref_ptr<osg::Geometry> mesh = makePatchedMesh(patches());
                mesh->setUseDisplayList(!vbo);
                mesh->setUseVertexBufferObjects(vbo);
                SCOPED_TRACE(std::string(modes) + (vbo ? " vbo" : " display list") + ", threading model " +
                             std::to_string(int(threading)));
                osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup(modes);
                group->setExtractionOptions(clusterOptions());
                const Result culled = render(content(group.get(), mesh.get()).get(), threading);
                for (unsigned v = 0; v < 2; ++v)
                {
                    ASSERT_TRUE(culled.images[v] && culled.images[v]->data());
                    EXPECT_TRUE(samePixels(*reference.images[v], *culled.images[v])) << "view " << v;
                    EXPECT_GT(culled.visible[v], 0.0) << "view " << v;
                    EXPECT_EQ(culled.clusters[v], culled.visible[v]) << "view " << v; // every object is a cluster
                }
                EXPECT_GE(culled.objects[0], 50.0); // clusters, not one drawable
                // Not vacuous: the wall hides the row behind it (32 clusters) from the front view's
                // octree, so that view draws part of the one drawable. (Frustum culling keeps all:
                // then the drawable draws whole, as OSG draws it.)
                if (std::string(modes) == "frustum+octree")
                {
                    EXPECT_LE(culled.visible[0], culled.objects[0] - 32.0);
                }
            }
    }
}

TEST(ClusterDraw, CullVisitorDrawsThePlainGraphsPixels)
{
    const Result reference =
        render(content(new osg::Group, makePatchedMesh(patches())).get(), osgViewer::ViewerBase::SingleThreaded);
    if (!reference.images[0] || !reference.images[0]->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    // osgVis::CullVisitor extracts with the default options; the environment lowers the threshold
    // below the mesh's 3744 triangles (clusters of up to 512).
    ::setenv("OSGVIS_CLUSTER_THRESHOLD", "1000", 1);
    for (const auto threading :
         {osgViewer::ViewerBase::SingleThreaded, osgViewer::ViewerBase::CullThreadPerCameraDrawThreadPerContext})
    {
        SCOPED_TRACE("threading model " + std::to_string(int(threading)));
        const Result culled =
            render(content(new osg::Group, makePatchedMesh(patches())).get(), threading, "frustum+octree");
        for (unsigned v = 0; v < 2; ++v)
        {
            ASSERT_TRUE(culled.images[v] && culled.images[v]->data());
            EXPECT_TRUE(samePixels(*reference.images[v], *culled.images[v])) << "view " << v;
            EXPECT_GT(culled.objects[v], 1.0) << "view " << v;
        }
        EXPECT_LT(culled.visible[0], culled.objects[0]);
    }
    ::unsetenv("OSGVIS_CLUSTER_THRESHOLD");
}

TEST(ClusterDraw, DrawableWithUserDrawCallbackStaysWholeAndIsDrawnByIt)
{
    struct CountingDraw : osg::Drawable::DrawCallback
    {
        mutable std::atomic<unsigned> calls{0};
        void drawImplementation(osg::RenderInfo& info, const osg::Drawable* drawable) const override
        {
            ++calls;
            drawable->drawImplementation(info);
        }
    };
    const Result reference =
        render(content(new osg::Group, makePatchedMesh(patches())).get(), osgViewer::ViewerBase::SingleThreaded);
    if (!reference.images[0] || !reference.images[0]->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    osg::ref_ptr<osg::Geometry> mesh = makePatchedMesh(patches());
    osg::ref_ptr<CountingDraw> callback = new CountingDraw;
    mesh->setDrawCallback(callback.get());
    mesh->setUseDisplayList(false); // the callback runs every frame
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("frustum+octree");
    group->setExtractionOptions(clusterOptions());
    const Result culled = render(content(group.get(), mesh.get()).get(), osgViewer::ViewerBase::DrawThreadPerContext);
    for (unsigned v = 0; v < 2; ++v)
    {
        ASSERT_TRUE(culled.images[v] && culled.images[v]->data());
        EXPECT_TRUE(samePixels(*reference.images[v], *culled.images[v])) << "view " << v;
        EXPECT_EQ(culled.objects[v], 1.0) << "view " << v;
        EXPECT_EQ(culled.clusters[v], -1.0) << "view " << v; // no clusters: no such statistic
    }
    EXPECT_EQ(callback->calls.load(), 2 * Frames);
}
