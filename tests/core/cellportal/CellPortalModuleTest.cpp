// SPDX-License-Identifier: MIT
// The cell-portal bake and module on hand-made scenes whose visibility is known: rooms in a row
// joined by doors, a room around a corner, an open field (one cell), and the search budget.
#include <osgVis/core/cellportal/CellPortalModule.h>
#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/pvs/CellPortalMerge.h>
#include <osgVis/core/pvs/PvsFormat.h>

#include "BoxScenes.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace
{
using namespace osgVis::core;
using osgVis::test::addBox;

// Rooms 4 m wide (x) in a row along x, walls 0.2 m thick and 3 m tall, floor and ceiling slabs; a
// door 1 m wide, 2 m tall in each inner wall at y in [doorY, doorY+1]. A crate in each room.
struct RoomRow
{
    Scene scene;
    std::vector<ObjectId> crates;
};

RoomRow roomRow(int rooms, const std::vector<double>& doorY)
{
    RoomRow row;
    Scene& s = row.scene;
    osgVis::test::addRoomRowShell(s, rooms);
    for (int i = 1; i < rooms; ++i)
    {
        const double x = 4.0 * i, y = doorY[std::size_t(i - 1)];
        addBox(s, {x - 0.1, 0.0, 0.0}, {x + 0.1, y, 3.0}, "wall");
        addBox(s, {x - 0.1, y + 1.0, 0.0}, {x + 0.1, 4.0, 3.0}, "wall");
        addBox(s, {x - 0.1, y, 2.0}, {x + 0.1, y + 1.0, 3.0}, "lintel");
    }
    for (int i = 0; i < rooms; ++i)
        row.crates.push_back(addBox(s, {4.0 * i + 1.5, 1.5, 0.0}, {4.0 * i + 2.5, 2.5, 1.0}, "crate"));
    return row;
}

View lookingFrom(const Vec3& eye, const Vec3& direction)
{
    const Mat4 view = glm::lookAt(eye, eye + direction, Vec3(0, 0, 1));
    const Mat4 projection = glm::perspective(glm::radians(60.0), 1.25, 0.1, 200.0);
    return makeView(view, projection);
}

VisibleSet culled(VisibilityModule& module, const View& view, std::size_t objects)
{
    VisibleSet visible(objects, true);
    module.cull(view, visible);
    return visible;
}

TEST(CellPortal, StraightRowOfDoorsSeesDownTheRowButNotPastAnOffsetDoor)
{
    // Doors 1-2 and 2-3 line up; door 3-4 is at the far side: from room 1 no line passes doors
    // 1-2, 2-3 and 3-4 and then reaches room 4's far end... but one may: check with cells.
    RoomRow row = roomRow(5, {1.5, 1.5, 0.1, 2.9});
    CellPortalModule module(CellPortalStage::CellToObject);
    module.setScene(row.scene);
    ASSERT_TRUE(module.bakedOnTheSpot());
    const CellPortalData& data = *module.bakedData();
    EXPECT_EQ(data.statistics.budgetExceededCells, 0u);
    std::vector<std::uint32_t> cells;
    data.graph.locate({2.0, 2.0, 1.5}, 1e-6, cells);
    ASSERT_EQ(cells.size(), 1u);
    const VisibleSet& pvs = data.sources[cells[0]].cellToObject;
    EXPECT_TRUE(pvs.test(row.crates[0]));
    EXPECT_TRUE(pvs.test(row.crates[1]));
    EXPECT_TRUE(pvs.test(row.crates[2])); // straight through two aligned doors
    // Room 5 needs a line through doors at y 1.5-2.5 (x=4, 8), 0.1-1.1 (x=12) and 2.9-3.9 (x=16):
    // from x=4 to x=12 it may fall at most 2.4 m, then it must climb 1.8 m over the next 4 m. No.
    EXPECT_FALSE(pvs.test(row.crates[4]));
}

TEST(CellPortal, EyeToObjectKeepsOnlyWhatTheViewCanReach)
{
    RoomRow row = roomRow(3, {1.5, 1.5});
    CellPortalModule eyeToObject(CellPortalStage::EyeToObject);
    eyeToObject.setScene(row.scene);
    const std::size_t n = row.scene.objects.size();
    // In room 1 looking east through the aligned doors: both other crates can be seen.
    VisibleSet east = culled(eyeToObject, lookingFrom({1.0, 2.0, 1.5}, {1, 0, 0}), n);
    EXPECT_TRUE(east.test(row.crates[1]));
    EXPECT_TRUE(east.test(row.crates[2]));
    // Looking west at the west wall: nothing beyond the doors.
    VisibleSet west = culled(eyeToObject, lookingFrom({3.0, 2.0, 1.5}, {-1, 0, 0}), n);
    EXPECT_FALSE(west.test(row.crates[1]));
    EXPECT_FALSE(west.test(row.crates[2]));
    EXPECT_TRUE(west.test(row.crates[0]));
    // Standing against the south wall of room 1 looking north-east: the door at y 1.5-2.5 is in view
    // but the line from the eye through it misses crate 3 (x 9.5-10.5, y 1.5-2.5)? It reaches y >= 4
    // by x = 4.5; the crate of room 2 (y up to 2.5) is hidden by the door's edge.
    VisibleSet steep = culled(eyeToObject, lookingFrom({3.6, 0.2, 1.5}, {0.3, 1, 0}), n);
    EXPECT_FALSE(steep.test(row.crates[2]));
}

TEST(CellPortal, StagesAreNested)
{
    RoomRow row = roomRow(4, {1.5, 0.2, 2.8});
    const std::size_t n = row.scene.objects.size();
    CellPortalModule cells(CellPortalStage::CellToCell), pvs(CellPortalStage::CellToObject),
        eyeCells(CellPortalStage::EyeToCell), eyeObjects(CellPortalStage::EyeToObject);
    for (CellPortalModule* m : {&cells, &pvs, &eyeCells, &eyeObjects})
        m->setScene(row.scene);
    // The first bake was registered by fingerprint: the others reuse it.
    EXPECT_TRUE(cells.bakedOnTheSpot());
    EXPECT_FALSE(eyeObjects.bakedOnTheSpot());
    for (const View& view : {lookingFrom({1, 2, 1.5}, {1, 0, 0}), lookingFrom({6, 1, 1}, {1, 0.2, 0}),
                             lookingFrom({13, 3, 2}, {-1, -0.3, 0})})
    {
        const VisibleSet a = culled(cells, view, n), b = culled(pvs, view, n), c = culled(eyeCells, view, n),
                         d = culled(eyeObjects, view, n);
        for (ObjectId id = 0; id < n; ++id)
        {
            EXPECT_TRUE(!b.test(id) || a.test(id)) << id;
            EXPECT_TRUE(!c.test(id) || a.test(id)) << id;
            EXPECT_TRUE(!d.test(id) || (b.test(id) && c.test(id))) << id;
        }
        EXPECT_LT(d.count(), a.count());
    }
}

TEST(CellPortal, EyeOutsideEveryCellOrOrthographicKeepsEverything)
{
    RoomRow row = roomRow(3, {1.5, 1.5});
    CellPortalModule module;
    module.setScene(row.scene);
    const std::size_t n = row.scene.objects.size();
    EXPECT_EQ(culled(module, lookingFrom({-50, 2, 1.5}, {1, 0, 0}), n).count(), n);
    const Mat4 view = glm::lookAt(Vec3(2, 2, 1.5), Vec3(3, 2, 1.5), Vec3(0, 0, 1));
    const View ortho = makeView(view, glm::ortho(-5.0, 5.0, -4.0, 4.0, 0.1, 100.0));
    ASSERT_TRUE(ortho.orthographic);
    EXPECT_EQ(culled(module, ortho, n).count(), n);
}

TEST(CellPortal, BudgetExceededFallsBackToEverythingReachable)
{
    RoomRow row = roomRow(6, {1.5, 1.5, 1.5, 1.5, 1.5});
    BakeOptions tight;
    tight.stabBudget = 2;
    const CellPortalData data = bakeCellPortal(row.scene, tight);
    EXPECT_GT(data.statistics.budgetExceededCells, 0u);
    // Room 1's search stops after two nodes; every room is reachable through the doors, so every
    // crate is in its PVS, while cells outside the building (above the ceiling) are not reachable.
    std::vector<std::uint32_t> cells;
    data.graph.locate({2.0, 2.0, 1.5}, 1e-6, cells);
    ASSERT_EQ(cells.size(), 1u);
    const SourceCellVisibility& room1 = data.sources[cells[0]];
    ASSERT_TRUE(room1.budgetExceeded);
    EXPECT_EQ(room1.stabTree.size(), 2u);
    for (ObjectId crate : row.crates)
        EXPECT_TRUE(room1.cellToObject.test(crate));
    EXPECT_LT(room1.cellToCell.count(), data.graph.cells.size());
}

TEST(CellPortal, ResultsDoNotDependOnThreadCount)
{
    RoomRow row = roomRow(5, {1.5, 0.4, 2.6, 1.5});
    BakeOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const CellPortalData a = bakeCellPortal(row.scene, one), b = bakeCellPortal(row.scene, two);
    ASSERT_EQ(a.sources.size(), b.sources.size());
    for (std::size_t c = 0; c < a.sources.size(); ++c)
    {
        EXPECT_TRUE(a.sources[c].cellToObject == b.sources[c].cellToObject);
        EXPECT_EQ(a.sources[c].stabTree.size(), b.sources[c].stabTree.size());
    }
}

TEST(CellPortal, SameBakeGivesTheSamePvsBytes)
{
    // No wall-clock time in the data: bakes on one and on two threads save to identical files.
    RoomRow row = roomRow(5, {1.5, 0.4, 2.6, 1.5});
    BakeOptions one, two;
    one.threads = 1;
    two.threads = 2;
    PvsFile a, b;
    a.data = bakeCellPortal(row.scene, one);
    b.data = bakeCellPortal(row.scene, two);
    a.method = b.method = "cellportal";
    a.options = canonicalBakeOptions(one);
    b.options = canonicalBakeOptions(two);
    EXPECT_EQ(encodePvs(a), encodePvs(b));
}

TEST(CellPortal, CanonicalOptionsSpellEverySettingButThreads)
{
    BakeOptions options;
    const std::string defaults =
        "min-coverage=0.3 min-face-area=0 min-cell-size=1e-04 max-depth=40 max-cells=200000 stab-budget=50000";
    EXPECT_EQ(canonicalBakeOptions(options), defaults);
    options.threads = 3;
    EXPECT_EQ(canonicalBakeOptions(options), defaults);
    options.subdivision.minCoverage = 0.1 + 0.2;
    options.subdivision.minFaceArea = 2.5;
    options.subdivision.maxCells = 64;
    options.stabBudget = 500;
    EXPECT_EQ(canonicalBakeOptions(options), "min-coverage=0.30000000000000004 min-face-area=2.5 min-cell-size=1e-04 "
                                             "max-depth=40 max-cells=64 stab-budget=500");
}

TEST(CellPortal, RegisteredUnderTheFourStageNames)
{
    for (const char* name : {"cellportal", "cellportal-cells", "cellportal-pvs", "cellportal-eyecells"})
    {
        ASSERT_TRUE(hasModule(name)) << name;
        EXPECT_STREQ(createModule(name)->name(), name);
    }
}
} // namespace

namespace
{
// Source cells [first, end) of `plan` as the range file of a split bake.
PvsFile sourceRangeFile(const CellPortalBakePlan& plan, std::uint32_t first, std::uint32_t end,
                        const BakeOptions& options)
{
    PvsFile file;
    file.method = "cellportal";
    file.options = canonicalBakeOptions(options);
    file.data = plan.skeleton();
    std::vector<SourceCellVisibility> sources = plan.bakeSources(first, end);
    for (std::uint32_t c = first; c < end; ++c)
        file.data.sources[c] = std::move(sources[c - first]);
    file.sourceRange = std::make_pair(first, end);
    return decodePvs(encodePvs(file).data(), encodePvs(file).size()); // as read back from disk
}

std::string mergeError(const std::vector<PvsFile>& ranges, bool requireAll = false)
{
    ViewCellMergeOptions options;
    options.requireAllCells = requireAll;
    try
    {
        mergeCellPortalPvs(ranges, options);
    }
    catch (const PvsFormatError& e)
    {
        return e.what();
    }
    return "(merged)";
}
} // namespace

TEST(CellPortal, SourceRangesBakedApartMergeIntoTheWholeBakesBytes)
{
    RoomRow row = roomRow(5, {1.5, 0.4, 2.6, 1.5});
    BakeOptions options;
    options.threads = 1;
    PvsFile whole;
    whole.method = "cellportal";
    whole.options = canonicalBakeOptions(options);
    whole.data = bakeCellPortal(row.scene, options);
    const CellPortalBakePlan plan(row.scene, options);
    const auto n = std::uint32_t(plan.cellCount());
    ASSERT_GT(n, 4u);
    EXPECT_EQ(plan.skeleton().graph.cells.size(), whole.data.graph.cells.size());
    const std::vector<PvsFile> ranges = {sourceRangeFile(plan, 3, n, options), sourceRangeFile(plan, 0, 1, options),
                                         sourceRangeFile(plan, 1, 3, options)};
    ViewCellMergeOptions complete;
    complete.requireAllCells = true;
    const PvsFile merged = mergeCellPortalPvs(ranges, complete);
    EXPECT_FALSE(merged.sourceRange);
    EXPECT_EQ(encodePvs(merged), encodePvs(whole));

    // Two adjacent ranges give the range file of both, its statistics left empty.
    const PvsFile partial = mergeCellPortalPvs({ranges[2], ranges[1]});
    ASSERT_TRUE(partial.sourceRange);
    EXPECT_EQ(*partial.sourceRange, std::make_pair(0u, 3u));
    EXPECT_EQ(partial.data.statistics.stabNodes, 0u);
    for (std::uint32_t c = 0; c < n; ++c)
        EXPECT_EQ(isPlaceholderSource(partial.data.sources[c]), c >= 3) << c;

    const std::vector<double> costs = plan.sourceCostEstimates();
    ASSERT_EQ(costs.size(), n);
    for (double cost : costs)
        EXPECT_GE(cost, 1.0);
}

TEST(CellPortal, SourceRangeMergeRefusesWhatIsNotOneBake)
{
    RoomRow row = roomRow(4, {1.5, 0.4, 2.6});
    BakeOptions options;
    const CellPortalBakePlan plan(row.scene, options);
    const auto n = std::uint32_t(plan.cellCount());
    const PvsFile low = sourceRangeFile(plan, 0, 2, options), high = sourceRangeFile(plan, 2, n, options);
    EXPECT_EQ(mergeError({low, sourceRangeFile(plan, 1, 3, options)}), "source cell 1 is in both input 1 and input 2");
    EXPECT_EQ(mergeError({low}, true).rfind("the inputs miss " + std::to_string(n - 2) + " of the " +
                                                std::to_string(n) + " source cells: 2-",
                                            0),
              0u)
        << mergeError({low}, true);
    EXPECT_NE(mergeError({low, sourceRangeFile(plan, 3, n, options)}).find("a partial merge must hold one contiguous range"),
              std::string::npos);
    PvsFile otherOptions = high;
    otherOptions.options = "min-coverage=0.5";
    EXPECT_EQ(mergeError({low, otherOptions}).rfind("input 2 and input 1 are not ranges of one bake (options", 0), 0u);
    PvsFile otherGraph = high;
    otherGraph.data.graph.cells[0].max.z += 1.0;
    EXPECT_EQ(mergeError({low, otherGraph}),
              "input 2 and input 1 are not ranges of one bake (different subdivisions: " + std::to_string(n) + " and " +
                  std::to_string(n) + " cells)");
    PvsFile otherModel = high;
    otherModel.data.fingerprint ^= 1;
    EXPECT_EQ(mergeError({low, otherModel}).rfind("input 2 and input 1 were baked for different models (fingerprint", 0),
              0u);
    PvsFile viewCells;
    viewCells.hasCellPortal = false;
    EXPECT_EQ(mergeError({viewCells}), "cannot merge input 1: it holds no cell-portal data");
}

TEST(CellPortal, RangeFileWithDataOutsideItsRangeIsRefused)
{
    RoomRow row = roomRow(3, {1.5, 0.4});
    const CellPortalBakePlan plan(row.scene, {});
    PvsFile file;
    file.data = plan.skeleton();
    file.data.sources = plan.bakeSources(0, plan.cellCount());
    file.sourceRange = std::make_pair(0u, 1u); // the other sources are not placeholders
    try
    {
        encodePvs(file);
        ADD_FAILURE() << "encoded";
    }
    catch (const PvsFormatError& e)
    {
        EXPECT_NE(std::string(e.what()).find("source cell 1 outside the range 0:1 holds data"), std::string::npos)
            << e.what();
    }
    file.sourceRange = std::make_pair(1u, 1u);
    EXPECT_THROW(encodePvs(file), PvsFormatError);
}
