// SPDX-License-Identifier: MIT
// Joining range files of one view-cell bake: ranges merged in any order give the bytes of the whole
// bake, and every input that does not belong is refused with a message naming it.
#include "PvsSample.h"

#include <osgVis/core/pvs/ViewCellMerge.h>

#include <gtest/gtest.h>

using namespace osgVis::core;
using osgVis::test::viewCellRange;

namespace
{
std::string mergeError(const std::vector<PvsFile>& inputs, const ViewCellMergeOptions& options = {})
{
    try
    {
        mergeViewCellPvs(inputs, options);
    }
    catch (const PvsFormatError& e)
    {
        return e.what();
    }
    return "";
}
} // namespace

TEST(ViewCellMerge, RangesJoinedEqualTheWhole)
{
    const PvsFile whole = osgVis::test::makeViewCellBake();
    const std::vector<PvsFile> ranges = {viewCellRange(whole, 3, 7), viewCellRange(whole, 0, 2),
                                         viewCellRange(whole, 2, 3)};
    ViewCellMergeOptions complete;
    complete.requireAllCells = true;
    const PvsFile merged = mergeViewCellPvs(ranges, complete);
    EXPECT_EQ(merged.viewCells.cellIndices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(encodePvs(merged), encodePvs(whole));
    // A merged result merges again like any range.
    EXPECT_EQ(encodePvs(mergeViewCellPvs({merged}, complete)), encodePvs(whole));
}

TEST(ViewCellMerge, PartialResultKeepsAscendingIndices)
{
    const PvsFile whole = osgVis::test::makeViewCellBake();
    const PvsFile merged = mergeViewCellPvs({viewCellRange(whole, 5, 7), viewCellRange(whole, 0, 2)});
    EXPECT_EQ(merged.viewCells.totalCells, 7u);
    EXPECT_EQ(merged.viewCells.cellIndices, (std::vector<std::uint32_t>{0, 1, 5, 6}));
    EXPECT_EQ(merged.viewCells.pvs[2], whole.viewCells.pvs[5]);
    EXPECT_EQ(merged.viewCells.cells[3].min.x, 6.0);
    EXPECT_EQ(merged.modelPath, "office.osgb");
    EXPECT_EQ(merged.method, "multifocal");
    EXPECT_EQ(merged.options, "resolution=64");
    EXPECT_EQ(merged.nearDistance, 0.05);
    EXPECT_EQ(merged.geometryFingerprint, whole.geometryFingerprint);
    EXPECT_EQ(merged.data.fingerprint, whole.data.fingerprint);
    EXPECT_FALSE(merged.hasCellPortal);
}

TEST(ViewCellMerge, MissingCellsAreRefusedWhenAllAreAskedFor)
{
    const PvsFile whole = osgVis::test::makeViewCellBake();
    ViewCellMergeOptions complete;
    complete.requireAllCells = true;
    EXPECT_EQ(mergeError({viewCellRange(whole, 5, 7), viewCellRange(whole, 0, 2)}, complete),
              "the inputs miss 3 of the 7 cells: 2-4");
    EXPECT_EQ(
        mergeError({viewCellRange(whole, 1, 2), viewCellRange(whole, 3, 4), viewCellRange(whole, 6, 7)}, complete),
        "the inputs miss 4 of the 7 cells: 0, 2, 4-5");
}

TEST(ViewCellMerge, InputsOfOtherModelsOrBakesAreRefused)
{
    const PvsFile whole = osgVis::test::makeViewCellBake();
    const PvsFile a = viewCellRange(whole, 0, 3);
    const auto refusedWith = [&](PvsFile b) { return mergeError({a, b}, {false, {"a.pvs", "b.pvs"}}); };
    PvsFile b = viewCellRange(whole, 3, 7);
    EXPECT_EQ(refusedWith(b), "");

    PvsFile other = b;
    other.geometryFingerprint = 1;
    EXPECT_EQ(refusedWith(other), "b.pvs and a.pvs were baked for different models (geometry fingerprint "
                                  "0x0000000000000001 and 0x1111222233334444)");
    other = b;
    other.data.fingerprint = 2;
    EXPECT_EQ(refusedWith(other), "b.pvs and a.pvs were baked for different models (fingerprint "
                                  "0x0000000000000002 and 0x5555666677778888)");
    other = b;
    other.data.objectCount = 38;
    EXPECT_EQ(refusedWith(other), "b.pvs and a.pvs were baked for different models (38 and 37 objects)");
    other = b;
    other.method = "cellportal";
    EXPECT_EQ(refusedWith(other), "b.pvs and a.pvs are not ranges of one bake (method 'cellportal' and 'multifocal')");
    other = b;
    other.options = "resolution=128";
    EXPECT_EQ(refusedWith(other),
              "b.pvs and a.pvs are not ranges of one bake (options 'resolution=128' and 'resolution=64')");
    other = b;
    other.nearDistance = 0.1;
    EXPECT_EQ(refusedWith(other), "b.pvs and a.pvs are not ranges of one bake (near distance 0.1 and 0.05)");
    other = b;
    other.viewCells.totalCells = 8;
    EXPECT_EQ(refusedWith(other), "b.pvs and a.pvs are not ranges of one bake (8 and 7 cells in all)");
}

TEST(ViewCellMerge, RepeatedCellsAndWrongInputsAreRefused)
{
    const PvsFile whole = osgVis::test::makeViewCellBake();
    EXPECT_EQ(mergeError({viewCellRange(whole, 0, 4), viewCellRange(whole, 3, 7)}),
              "cell 3 is in both input 1 and input 2");
    EXPECT_EQ(mergeError({viewCellRange(whole, 0, 4), viewCellRange(whole, 4, 7), viewCellRange(whole, 6, 7)}),
              "cell 6 is in both input 2 and input 3");
    EXPECT_EQ(mergeError({}), "nothing to merge: no input files");
    PvsFile cellPortal = osgVis::test::makeCellPortalSample();
    EXPECT_EQ(mergeError({viewCellRange(whole, 0, 4), cellPortal}), "cannot merge input 2: it holds no view cells");
    cellPortal.hasViewCells = true;
    EXPECT_EQ(mergeError({cellPortal}), "cannot merge input 1: it holds cell-portal data (view-cell and cell-portal files do not merge together)");
    PvsFile ragged = viewCellRange(whole, 0, 4);
    ragged.viewCells.pvs.pop_back();
    EXPECT_EQ(mergeError({ragged}), "cannot merge input 1: its view cells have 4 indices, 4 boxes and 3 sets");
}
