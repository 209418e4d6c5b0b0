// SPDX-License-Identifier: MIT
// Paged tiles with OSG's own DatabasePager running (docs/paging.md): a tile hidden behind a wall is
// never requested; once seen it loads, is merged, extracted and culled like any object, and the
// frames are the plain graph's; a hidden tile the pager expires leaves the extraction; a missing or
// corrupt tile file leaves the rest drawn. Every threading model. Needs a display (Xvfb).
//
//   top view: a wall across x in [-14, 14] at y = 10, z in [-12, 12] (it must hide the box of the
//   row's bounding sphere, not only the row); tile "front" (a box at y = 0) before it, tile
//   "behind" (a row of boxes at y = 25) behind it. The front view stands at y = -20 looking
//   along +y (the row is hidden); the side view stands at x = 40 looking along -x past the wall's end.
#include "TestScenes.h"

#include <osgVis/CullVisitor>
#include <osgVis/PagedDatabase>
#include <osgVis/SceneExtractor>
#include <osgVis/ViewCuller>
#include <osgVis/Statistics>
#include <osgVis/VisibilityGroup>

#include <osgVis/gen/Generator.h>
#include <osgVis/gen/PagedScene.h>
#include <osgVis/core/cellportal/CellPortalModule.h>

#include <osg/Geode>
#include <osg/Notify>
#include <osg/PagedLOD>
#include <osgDB/DatabasePager>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <osgViewer/Viewer>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <thread>
#include <unistd.h>

using osgVis::test::CaptureImage;
using osgVis::test::makeBox;
using osgVis::test::samePixels;
using osgVis::test::setUpCapturingCamera;

namespace
{
constexpr unsigned Width = 128, Height = 96;

// The tile files of this process, removed at exit.
std::filesystem::path tileDirectory()
{
    struct Directory
    {
        std::filesystem::path path =
            std::filesystem::temp_directory_path() / ("osgvis-paged-test-" + std::to_string(::getpid()));
        Directory() { std::filesystem::create_directories(path); }
        ~Directory()
        {
            std::error_code ignored;
            std::filesystem::remove_all(path, ignored);
        }
    };
    static const Directory dir;
    return dir.path;
}

osg::ref_ptr<osg::Geode> boxes(const std::vector<std::pair<osg::Vec3, osg::Vec3>>& extents, const osg::Vec4& colour)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    for (const auto& [lo, hi] : extents)
        geode->addDrawable(makeBox(lo, hi, colour));
    return geode;
}

// A tile file (written once per process) and a PagedLOD stating the tile's bound.
osg::ref_ptr<osg::PagedLOD> tile(const std::string& file, osg::Node* content, const osg::BoundingSphere& bound)
{
    const std::filesystem::path path = tileDirectory() / file;
    if (content && !std::filesystem::exists(path))
    {
        EXPECT_TRUE(osgDB::writeNodeFile(*content, path.string())) << path;
    }
    osg::ref_ptr<osg::PagedLOD> paged = new osg::PagedLOD;
    paged->setName(file);
    paged->setCenterMode(osg::LOD::USER_DEFINED_CENTER);
    paged->setCenter(bound.center());
    paged->setRadius(bound.radius());
    paged->setDatabasePath(tileDirectory().string() + "/");
    paged->setFileName(0, file);
    paged->setRange(0, 0.0f, 1e30f);
    return paged;
}

struct Scene
{
    osg::ref_ptr<osg::Group> root;
    osg::ref_ptr<osg::PagedLOD> front, behind, extra;
};

// `extraFile`: one more tile before the wall, whose file is missing or corrupt.
Scene scene(osg::Group* root, const std::string& extraFile = "")
{
    Scene s;
    s.root = root;
    root->addChild(boxes({{{-14, 10, -12}, {14, 11, 12}}}, {0.8f, 0.8f, 0.8f, 1}));
    osg::ref_ptr<osg::Geode> front = boxes({{{-1, 0, 0}, {1, 1, 1}}}, {1, 0.3f, 0.2f, 1});
    s.front = tile("front.osgb", front.get(), front->getBound());
    std::vector<std::pair<osg::Vec3, osg::Vec3>> row;
    for (int i = 0; i < 8; ++i)
        row.push_back({{-10.f + 2.5f * i, 25, 0}, {-9.f + 2.5f * i, 26, 2}});
    osg::ref_ptr<osg::Geode> behind = boxes(row, {0.2f, 0.4f, 1.0f, 1});
    s.behind = tile("behind.osgb", behind.get(), behind->getBound());
    root->addChild(s.front);
    root->addChild(s.behind);
    if (!extraFile.empty())
    {
        s.extra = tile(extraFile, nullptr, osg::BoundingSphere(osg::Vec3(4, 2, 1), 1.5f));
        root->addChild(s.extra);
    }
    return s;
}

const osg::Matrixd FrontView =
    osg::Matrixd::lookAt(osg::Vec3d(0, -20, 1.7), osg::Vec3d(0, 0, 1.5), osg::Vec3d(0, 0, 1));
const osg::Matrixd SideView = osg::Matrixd::lookAt(osg::Vec3d(40, 18, 1.7), osg::Vec3d(0, 18, 1.2), osg::Vec3d(0, 0, 1));

struct Step
{
    osg::Matrixd view;
    std::function<bool()> settled; // checked after each frame; the step ends 3 frames after it holds
    std::function<void(osgDB::DatabasePager&)> pager = nullptr; // settings for this step
};

struct Outcome
{
    osg::ref_ptr<osg::Image> image; // the last frame
    double visible = -1, skipped = -1;
    bool settled = true; // every step settled before its deadline
};

// `setUp`: what to do to the viewer before it is realized (install osgVis::CullVisitor).
Outcome run(osg::Node* root, osgViewer::ViewerBase::ThreadingModel threading, const std::vector<Step>& steps,
            const std::function<void(osgViewer::Viewer&)>& setUp = nullptr)
{
    osgViewer::Viewer viewer;
    viewer.setThreadingModel(threading);
    osg::Camera* camera = viewer.getCamera();
    osg::ref_ptr<CaptureImage> capture = setUpCapturingCamera(*camera, Width, Height);
    if (!capture)
        return {};
    camera->setProjectionMatrixAsPerspective(60.0, double(Width) / Height, 0.1, 200.0);
    camera->getStats()->collectStats("rendering", true);
    viewer.setSceneData(root);
    if (setUp)
        setUp(viewer);
    viewer.realize();
    Outcome outcome;
    double time = 0.0;
    for (const Step& step : steps)
    {
        camera->setViewMatrix(step.view);
        if (step.pager)
            step.pager(*viewer.getDatabasePager());
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        int after = -1;
        while (after < 3)
        {
            viewer.frame(time += 0.05);
            if (after >= 0 || step.settled())
                ++after;
            else if (std::chrono::steady_clock::now() > deadline)
            {
                outcome.settled = false;
                break;
            }
            else
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    }
    viewer.stopThreading();
    outcome.image = capture->image;
    const unsigned last = viewer.getFrameStamp()->getFrameNumber();
    camera->getStats()->getAttribute(last, osgVis::STATS_VISIBLE, outcome.visible);
    camera->getStats()->getAttribute(last, osgVis::STATS_PAGED_SKIPPED, outcome.skipped);
    return outcome;
}

bool loaded(const osg::PagedLOD& paged)
{
    return paged.getNumChildren() > 0;
}

const osgViewer::ViewerBase::ThreadingModel AllModels[] = {
    osgViewer::ViewerBase::SingleThreaded, osgViewer::ViewerBase::CullDrawThreadPerContext,
    osgViewer::ViewerBase::DrawThreadPerContext, osgViewer::ViewerBase::CullThreadPerCameraDrawThreadPerContext};

osg::ref_ptr<osgVis::VisibilityGroup> octreeGroup(const osgVis::PagingOptions& paging)
{
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("octree");
    group->setPagingOptions(paging);
    return group;
}

// Live drawable objects (placeholders and empty slots left out) of the group's current extraction.
unsigned liveObjects(const osgVis::VisibilityGroup& group)
{
    osg::ref_ptr<const osgVis::ExtractedScene> extraction = group.getViewCuller()->getScene();
    unsigned count = 0;
    for (const osgVis::core::SceneObject& object : extraction->scene.objects)
        count += !extraction->removed(object.id) && !extraction->placeholder(object.id);
    return count;
}
} // namespace

// Octree under every threading model; the other conservative modes that need no baked data under
// two of them.
struct ModeRun
{
    std::string modes;
    osgViewer::ViewerBase::ThreadingModel threading;
};

std::vector<ModeRun> modeRuns()
{
    std::vector<ModeRun> runs;
    for (const auto threading : AllModels)
        runs.push_back({"octree", threading});
    for (const char* modes : {"frustum", "mask", "cdt", "frustum+octree"})
        for (const auto threading : {osgViewer::ViewerBase::SingleThreaded, osgViewer::ViewerBase::DrawThreadPerContext})
            runs.push_back({modes, threading});
    return runs;
}

TEST(PagedViewer, HiddenTileIsNeverRequestedSeenTileLoadsAndEveryModeDrawsThePlainPixels)
{
    for (const ModeRun& modeRun : modeRuns())
    {
        const std::string& modes = modeRun.modes;
        const auto threading = modeRun.threading;
        SCOPED_TRACE(modes + ", threading model " + std::to_string(int(threading)));
        Scene plain = scene(new osg::Group);
        const Outcome plainFront = run(plain.root.get(), threading, {{FrontView, [&] { return loaded(*plain.front); }}});
        if (!plainFront.image || !plainFront.image->data())
            GTEST_SKIP() << "no GL context (run under xvfb-run)";
        // Plain OSG requests every tile in the frustum: the hidden row is loaded too.
        const Outcome plainLoadsAll =
            run(plain.root.get(), threading, {{FrontView, [&] { return loaded(*plain.behind); }}});
        EXPECT_TRUE(plainLoadsAll.settled);
        const Outcome plainSide = run(plain.root.get(), threading, {{SideView, [] { return true; }}});
        const Outcome plainBack = run(plain.root.get(), threading, {{FrontView, [] { return true; }}});

        osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup(modes);
        Scene culled = scene(group.get());
        const Outcome front = run(group.get(), threading, {{FrontView, [&] { return loaded(*culled.front); }}});
        ASSERT_TRUE(front.settled);
        // A few more frames give the pager every chance to load what it was asked for.
        run(group.get(), threading, {{FrontView, [frames = 0]() mutable { return ++frames > 10; }}});
        // The frustum alone cannot tell the row is hidden; every mode that sees occlusion here does.
        const bool occludes = modes != "frustum";
        EXPECT_EQ(loaded(*culled.behind), !occludes);
        if (occludes)
        {
            EXPECT_FALSE(culled.behind->getDatabaseRequest(0).valid()) << "the hidden tile was requested";
        }
        EXPECT_EQ(front.skipped, occludes ? 1.0 : 0.0);
        EXPECT_TRUE(samePixels(*plainFront.image, *front.image));

        // Seen from the side, the row loads, is merged and extracted, and draws as in the plain graph.
        const Outcome side = run(group.get(), threading, {{SideView, [&] { return loaded(*culled.behind); }}});
        ASSERT_TRUE(side.settled);
        EXPECT_EQ(side.skipped, 0.0);
        EXPECT_EQ(liveObjects(*group), 1u + 1u + 8u);
        EXPECT_TRUE(samePixels(*plainSide.image, *side.image));

        // Back in front, the loaded row is culled object by object, and the tile is not entered.
        const Outcome back = run(group.get(), threading, {{FrontView, [] { return true; }}});
        EXPECT_EQ(back.skipped, occludes ? 1.0 : 0.0);
        if (occludes)
        {
            EXPECT_LT(back.visible, 1.0 + 1.0 + 8.0);
        }
        EXPECT_TRUE(samePixels(*plainBack.image, *back.image));
    }
}

TEST(PagedViewer, HiddenTileThePagerExpiresLeavesTheExtraction)
{
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("octree");
    Scene culled = scene(group.get());
    const Outcome outcome = run(group.get(), osgViewer::ViewerBase::SingleThreaded,
                                {{SideView, [&] { return loaded(*culled.behind) && loaded(*culled.front); }},
                                 {FrontView,
                                  [&] { return !loaded(*culled.behind); },
                                  [](osgDB::DatabasePager& pager) { pager.setTargetMaximumNumberOfPageLOD(0); }}});
    if (!outcome.image || !outcome.image->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    ASSERT_TRUE(outcome.settled);
    EXPECT_TRUE(loaded(*culled.front)); // seen every frame: never expired
    EXPECT_EQ(liveObjects(*group), 1u + 1u); // the wall and the front box; the row's slots are empty
}

TEST(PagedViewer, MissingOrCorruptTileLeavesTheRestDrawn)
{
    {
        std::ofstream corrupt(tileDirectory() / "corrupt.osgb", std::ios::binary);
        corrupt << "this is no osgb file";
    }
    for (const std::string file : {"missing.osgb", "corrupt.osgb"})
    {
        SCOPED_TRACE(file);
        Scene plain = scene(new osg::Group, file);
        const Outcome reference =
            run(plain.root.get(), osgViewer::ViewerBase::SingleThreaded, {{FrontView, [&] { return loaded(*plain.front); }}});
        if (!reference.image || !reference.image->data())
            GTEST_SKIP() << "no GL context (run under xvfb-run)";
        osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup("octree");
        Scene culled = scene(group.get(), file);
        const Outcome outcome = run(group.get(), osgViewer::ViewerBase::SingleThreaded,
                                    {{FrontView, [&] { return loaded(*culled.front); }}});
        ASSERT_TRUE(outcome.settled);
        EXPECT_FALSE(loaded(*culled.extra));
        EXPECT_TRUE(samePixels(*reference.image, *outcome.image));
        EXPECT_EQ(liveObjects(*group), 1u + 1u);
    }
}

TEST(PagedViewer, TilesBehindTilesStillLoadingWaitTheirTurn)
{
    // Four tiles in a row straight ahead at 5, 10, 15 and 20, each covering the next on screen, and
    // a fifth, farthest of all, off to the side where none covers it.
    osgVis::PagingOptions paging;
    paging.requestsPerFrame = 1;
    osg::ref_ptr<osgVis::VisibilityGroup> group = octreeGroup(paging);
    std::vector<osg::ref_ptr<osg::PagedLOD>> tiles;
    const auto add = [&](const std::string& name, const osg::Vec3& lo, const osg::Vec3& hi) {
        osg::ref_ptr<osg::Geode> content = boxes({{lo, hi}}, {1, 1, 0, 1});
        tiles.push_back(tile(name, content.get(), content->getBound()));
        group->addChild(tiles.back());
    };
    add("side.osgb", {9, 25, 0}, {9.5f, 25.5f, 1}); // first in the graph: the order must come from distance
    for (int i = 3; i >= 0; --i)
        add("row" + std::to_string(i) + ".osgb", {-0.25f, 5.f * (i + 1), 0}, {0.25f, 5.f * (i + 1) + 0.5f, 1});
    std::vector<bool> requestedAfterFirstFrame;
    const Outcome outcome = run(group.get(), osgViewer::ViewerBase::SingleThreaded,
                                {{osg::Matrixd::lookAt(osg::Vec3d(0, -3, 0.5), osg::Vec3d(0, 10, 0.5), osg::Vec3d(0, 0, 1)),
                                  [&] {
                                      if (requestedAfterFirstFrame.empty())
                                          for (const auto& t : tiles)
                                              requestedAfterFirstFrame.push_back(t->getDatabaseRequest(0).valid());
                                      return std::all_of(tiles.begin(), tiles.end(),
                                                         [](const auto& t) { return loaded(*t); });
                                  }}});
    if (!outcome.image || !outcome.image->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    ASSERT_TRUE(outcome.settled); // every visible tile loads in the end
    // side, row3 (farthest) .. row0 (nearest): the nearest, the one budgeted behind it, and the side tile.
    EXPECT_EQ(requestedAfterFirstFrame, (std::vector<bool>{true, false, false, true, true}));
}

TEST(PagedViewer, HiddenTilesSeenLatelyAreKeptFreshWithinThePagersBudget)
{
    // keepBytes: unlimited; room for the one-box tile but not the eight-box row (a box is 8
    // vertices, one colour and 36 short indices: 184 bytes); room for none.
    for (const auto& [keepFrames, keepBytes] :
         {std::pair<unsigned, std::uint64_t>{120u, 0u}, {0u, 0u}, {120u, 1000u}, {120u, 1u}})
    {
        SCOPED_TRACE("keepFrames " + std::to_string(keepFrames) + ", keepBytes " + std::to_string(keepBytes));
        osgVis::PagingOptions paging;
        paging.keepFrames = keepFrames;
        paging.keepBytes = keepBytes;
        osg::ref_ptr<osgVis::VisibilityGroup> group = octreeGroup(paging);
        Scene culled = scene(group.get());
        osg::ref_ptr<osg::Geode> content = boxes({{{-4, 30, 0}, {-3, 31, 1}}}, {0.3f, 1, 0.3f, 1});
        osg::ref_ptr<osg::PagedLOD> farther = tile("farther.osgb", content.get(), content->getBound());
        group->addChild(farther);
        // Seen from the side, three tiles load; from the front two of them are hidden, and the
        // pager's budget of two loaded PagedLODs leaves room to keep one of those.
        const Outcome outcome =
            run(group.get(), osgViewer::ViewerBase::SingleThreaded,
                {{SideView, [&] { return loaded(*culled.behind) && loaded(*culled.front) && loaded(*farther); }},
                 {FrontView, [frames = 0]() mutable { return ++frames > 30; },
                  [](osgDB::DatabasePager& pager) { pager.setTargetMaximumNumberOfPageLOD(2); }}});
        if (!outcome.image || !outcome.image->data())
            GTEST_SKIP() << "no GL context (run under xvfb-run)";
        ASSERT_TRUE(outcome.settled);
        // 30 frames 20 ms apart: past the pager's expiry delay (0.1 s), within the 120 kept frames.
        EXPECT_TRUE(loaded(*culled.front));
        EXPECT_EQ(int(loaded(*culled.behind)) + int(loaded(*farther)), keepFrames != 0 && keepBytes != 1 ? 1 : 0);
        if (keepBytes == 1000)
        {
            EXPECT_TRUE(loaded(*farther));
        }
    }
}

namespace
{
// A generated scene written as a paged database, and views at four keys of its walk.
struct GeneratedDatabase
{
    std::string rootFile;
    std::vector<osg::Matrixd> views;
};

GeneratedDatabase generatedDatabase(osgVis::gen::SceneKind kind, std::uint64_t triangles, unsigned tiles,
                                    const std::string& name)
{
    const std::filesystem::path dir = tileDirectory() / name;
    std::filesystem::create_directories(dir);
    osgVis::gen::GenerateOptions generate;
    generate.kind = kind;
    generate.triangles = triangles;
    const osgVis::gen::GeneratedScene scene = osgVis::gen::generate(generate);
    osgVis::gen::PagedOptions paging;
    paging.tiles = tiles;
    GeneratedDatabase database;
    database.rootFile = osgVis::gen::writePagedScene(*scene.root, dir.string(), paging).rootPath;
    for (std::size_t k = 0; k < scene.walk.keys.size(); k += scene.walk.keys.size() / 4)
    {
        const osgVis::core::Mat4 m = scene.walk.keys[k].viewMatrix();
        database.views.emplace_back();
        database.views.back().set(&m[0][0]);
    }
    return database;
}

// One run per view, each until the pager has had nothing in progress for the last frames.
std::vector<Outcome> runSettled(osg::Node* root, const std::vector<osg::Matrixd>& views)
{
    std::vector<Outcome> outcomes;
    for (const osg::Matrixd& view : views)
    {
        osgDB::DatabasePager* pager = nullptr;
        const auto settled = [&, quiet = 0]() mutable
        {
            quiet = pager && !pager->getRequestsInProgress() ? quiet + 1 : 0;
            return quiet >= 3;
        };
        outcomes.push_back(run(root, osgViewer::ViewerBase::SingleThreaded,
                               {Step{view, settled, [&](osgDB::DatabasePager& p) { pager = &p; }}}));
    }
    return outcomes;
}

bool haveImages(const std::vector<Outcome>& outcomes)
{
    return std::all_of(outcomes.begin(), outcomes.end(),
                       [](const Outcome& o) { return o.image && o.image->data() && o.settled; });
}

// A group of `modes` over a fresh read of the database.
osg::ref_ptr<osgVis::VisibilityGroup> groupOver(const std::string& modes, const std::string& rootFile)
{
    osg::ref_ptr<osgVis::VisibilityGroup> group = new osgVis::VisibilityGroup(modes);
    group->addChild(osgDB::readRefNodeFile(rootFile));
    return group;
}

// `group` draws `reference`'s pixels at every view once loading settles; returns how many paged
// nodes it skipped, summed over the views' last frames.
double expectPlainPixels(osgVis::VisibilityGroup& group, const std::vector<osg::Matrixd>& views,
                         const std::vector<Outcome>& reference)
{
    SCOPED_TRACE(group.getModes());
    const std::vector<Outcome> outcomes = runSettled(&group, views);
    double skipped = 0;
    for (std::size_t i = 0; i < views.size(); ++i)
    {
        EXPECT_TRUE(outcomes[i].settled) << "view " << i;
        EXPECT_TRUE(outcomes[i].image && samePixels(*reference[i].image, *outcomes[i].image)) << "view " << i;
        skipped += outcomes[i].skipped;
    }
    return skipped;
}
} // namespace

TEST(PagedViewer, GeneratedPagedCityDrawsThePlainPixelsOnceLoadingSettles)
{
    const GeneratedDatabase city = generatedDatabase(osgVis::gen::SceneKind::City, 20000, 24, "city");
    osg::ref_ptr<osg::Node> plain = osgDB::readRefNodeFile(city.rootFile);
    ASSERT_TRUE(plain.valid());
    const std::vector<Outcome> reference = runSettled(plain.get(), city.views);
    if (!reference[0].image || !reference[0].image->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    ASSERT_TRUE(haveImages(reference));
    // Every conservative mode that needs no bake (the cellportal ones: the paged floor below).
    for (const char* modes : {"octree", "octree-single", "octree-paper", "mask", "mask-distance", "cdt", "cdt-depthfree",
                              "cdt-depth", "frustum+octree"})
        // some tile was left unrequested, or the comparison proves little
        EXPECT_GT(expectPlainPixels(*groupOver(modes, city.rootFile), city.views, reference), 0.0) << modes;
    // Unbaked, multifocal answers for the grid cell around the eye, which sees every tile on these
    // views: its pixels still must be plain OSG's.
    expectPlainPixels(*groupOver("multifocal", city.rootFile), city.views, reference);
}

// cellportal with data baked on the whole database (docs/paging.md): every load state uses them,
// none bakes on the spot, and the pixels are plain OSG's once loading settles.
namespace
{
// The generated floor as a paged database, baked whole (as osgvispvs does) and the data registered.
GeneratedDatabase bakedPagedFloor()
{
    const GeneratedDatabase floor = generatedDatabase(osgVis::gen::SceneKind::Floor, 60000, 24, "floor");
    osg::ref_ptr<osg::Node> whole = osgDB::readRefNodeFile(floor.rootFile);
    EXPECT_TRUE(whole.valid() && osgVis::loadWholeDatabase(*whole).unreadable.empty());
    if (whole)
    {
        const osg::ref_ptr<osgVis::ExtractedScene> extracted = osgVis::extractScene(*whole);
        auto data = std::make_shared<const osgVis::core::CellPortalData>(osgVis::core::bakeCellPortal(extracted->scene));
        EXPECT_TRUE(data->tiles);
        osgVis::core::registerBakedCellPortalData(data);
    }
    return floor;
}

} // namespace

TEST(PagedViewer, PagedFloorWithAWholeDatabaseBakeDrawsThePlainPixels)
{
    const GeneratedDatabase floor = bakedPagedFloor();
    osg::ref_ptr<osg::Node> plain = osgDB::readRefNodeFile(floor.rootFile);
    const std::vector<Outcome> reference = runSettled(plain.get(), floor.views);
    if (!reference[0].image || !reference[0].image->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    ASSERT_TRUE(haveImages(reference));
    for (const char* stage : {"cellportal-cells", "cellportal-pvs", "cellportal-eyecells"})
        EXPECT_GT(expectPlainPixels(*groupOver(stage, floor.rootFile), floor.views, reference), 0.0) << stage;
    const osg::ref_ptr<osgVis::VisibilityGroup> group = groupOver("cellportal", floor.rootFile);
    EXPECT_GT(expectPlainPixels(*group, floor.views, reference), 0.0);
    // The last scene the group extracted found the whole bake: an on-the-spot bake would have been
    // registered under that scene's own fingerprint, without tile keys.
    const osg::ref_ptr<const osgVis::ExtractedScene> scene = group->getViewCuller()->getScene();
    const auto found = osgVis::core::findBakedCellPortalData(osgVis::core::sceneFingerprint(scene->scene));
    EXPECT_TRUE(!found || found->tiles);
}

TEST(PagedViewer, OsgVisCullVisitorSkipsHiddenTilesToo)
{
    // No VisibilityGroup: osgVis::CullVisitor culls the whole graph under the camera.
    Scene plain = scene(new osg::Group);
    const Outcome reference = run(plain.root.get(), osgViewer::ViewerBase::SingleThreaded,
                                  {{SideView, [&] { return loaded(*plain.behind) && loaded(*plain.front); }}});
    if (!reference.image || !reference.image->data())
        GTEST_SKIP() << "no GL context (run under xvfb-run)";
    Scene culled = scene(new osg::Group);
    const auto install = [](osgViewer::Viewer& viewer) { osgVis::CullVisitor::installOn(viewer, "octree"); };
    const Outcome front = run(culled.root.get(), osgViewer::ViewerBase::SingleThreaded,
                              {{FrontView, [&, frames = 0]() mutable { return loaded(*culled.front) && ++frames > 10; }}},
                              install);
    ASSERT_TRUE(front.settled);
    EXPECT_FALSE(loaded(*culled.behind));
    EXPECT_FALSE(culled.behind->getDatabaseRequest(0).valid()) << "the hidden tile was requested";
    const Outcome side = run(culled.root.get(), osgViewer::ViewerBase::SingleThreaded,
                             {{SideView, [&] { return loaded(*culled.behind); }}}, install);
    ASSERT_TRUE(side.settled);
    EXPECT_TRUE(samePixels(*reference.image, *side.image));
}

TEST(PagedViewer, TileOnThePathAheadIsPrefetchedThoughHidden)
{
    // The eye walks along +y towards the wall; the row behind it lies on the path ahead.
    for (const unsigned prefetchFrames : {0u, 200u})
    {
        SCOPED_TRACE("prefetchFrames " + std::to_string(prefetchFrames));
        osgVis::PagingOptions paging;
        paging.prefetchFrames = prefetchFrames;
        osg::ref_ptr<osgVis::VisibilityGroup> group = octreeGroup(paging);
        Scene culled = scene(group.get());
        std::vector<Step> steps;
        for (int i = 0; i < 12; ++i)
            steps.push_back({osg::Matrixd::lookAt(osg::Vec3d(0, -20 + 0.2 * i, 1.7), osg::Vec3d(0, 0 + 0.2 * i, 1.5),
                                                  osg::Vec3d(0, 0, 1)),
                             [frames = 0]() mutable { return ++frames > 1; }});
        steps.push_back({steps.back().view, [&, frames = 0]() mutable {
                             return loaded(*culled.front) && (loaded(*culled.behind) || ++frames > 20);
                         }});
        const Outcome outcome = run(group.get(), osgViewer::ViewerBase::SingleThreaded, steps);
        if (!outcome.image || !outcome.image->data())
            GTEST_SKIP() << "no GL context (run under xvfb-run)";
        ASSERT_TRUE(outcome.settled);
        EXPECT_EQ(outcome.skipped, 1.0); // the row is hidden all along
        EXPECT_EQ(loaded(*culled.behind), prefetchFrames != 0);
    }
}

// With a baked cellportal PVS the prefetch also asks for the tiles some eye along the predicted
// path may see (the PVS of the cells ahead), not only those whose box the path crosses; culling
// asynchronously, the worker's regions say the same.
namespace
{
void expectPrefetchFromRegions(const GeneratedDatabase& floor, bool async)
{
    SCOPED_TRACE(async ? "asynchronous" : "synchronous");
    // A creeping eye: 1 cm every other frame along its gaze for 45 steps, so the path ahead is a few
    // cm long.
    osg::Vec3d eye, centre, up;
    floor.views[1].getLookAt(eye, centre, up);
    const osg::Vec3d gaze = (centre - eye) / (centre - eye).length();
    std::set<std::string> before;
    for (const unsigned prefetchFrames : {0u, 5u})
    {
        SCOPED_TRACE("prefetchFrames " + std::to_string(prefetchFrames));
        const osg::ref_ptr<osgVis::VisibilityGroup> group = groupOver("cellportal", floor.rootFile);
        group->setAsync(async);
        osgVis::PagingOptions paging;
        paging.prefetchFrames = prefetchFrames;
        group->setPagingOptions(paging);
        std::vector<Step> steps;
        for (int i = 0; i < 45; ++i)
            steps.push_back({osg::Matrixd::lookAt(eye + gaze * (0.01 * i), centre + gaze * (0.01 * i), up),
                             [frames = 0]() mutable { return ++frames > 1; }});
        const Outcome outcome = run(group.get(), osgViewer::ViewerBase::SingleThreaded, steps);
        if (!outcome.image || !outcome.image->data())
            GTEST_SKIP() << "no GL context (run under xvfb-run)";
        ASSERT_TRUE(outcome.settled);
        const osg::ref_ptr<const osgVis::ExtractedScene> scene = group->getViewCuller()->getScene();
        std::set<std::string> loadedNow;
        unsigned offThePath = 0; // loaded now, not without prefetch, and its box nowhere near the path
        for (const osgVis::PagedNodeRecord& record : scene->pagedNodes)
        {
            const osg::Group& node = *scene->refs[record.placeholder].paged;
            if (node.getNumChildren() == 0)
                continue;
            loadedNow.insert(node.getName());
            osgVis::core::Aabb box = scene->scene.objects[record.placeholder].bounds;
            box.expand(box.min - osgVis::core::Vec3(0.5));
            box.expand(box.max + osgVis::core::Vec3(0.5));
            bool onPath = false;
            for (int cm = 0; cm <= 55; ++cm)
            {
                const osg::Vec3d at = eye + gaze * (0.01 * cm);
                onPath = onPath || box.contains(osgVis::core::Vec3(at.x(), at.y(), at.z()));
            }
            offThePath += prefetchFrames != 0 && !before.count(node.getName()) && !onPath;
        }
        if (prefetchFrames == 0)
            before = loadedNow;
        else
        {
            EXPECT_GT(offThePath, 0u) << loadedNow.size() << " tiles loaded, " << before.size() << " without prefetch";
            EXPECT_TRUE(std::includes(loadedNow.begin(), loadedNow.end(), before.begin(), before.end()));
        }
    }
}
} // namespace

TEST(PagedViewer, TilesInTheBakedPvsAheadArePrefetched)
{
    const GeneratedDatabase floor = bakedPagedFloor();
    expectPrefetchFromRegions(floor, false);
    expectPrefetchFromRegions(floor, true);
}
