// SPDX-License-Identifier: MIT
// osgvispvs end to end: bakes a small generated office into a .pvs that decodes (the same bytes for
// the same bake), prints and writes the bake's statistics, merges the range files of a view-cell
// bake, and refuses bad input with a message naming the thing and the documented exit status
// (1: files and scenes, 2: command line).
#include "AppProcess.h"
#include "BadModelFiles.h"
#include "BenchJson.h"
#include "PagedOffice.h"
#include "PvsSample.h"

#include <osgVis/core/cellportal/CellPortalBake.h>
#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/gen/Generator.h>
#include <osgVis/gen/PagedScene.h>

#include <osgDB/WriteFile>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace osgVis::test;

namespace
{
AppRun osgvispvs(const std::string& arguments)
{
    return runApp(OSGVISPVS_EXE, arguments);
}

// The office osgvisgen writes for --kind office --triangles 2000, in a fresh scratch folder.
fs::path writeSmallOffice()
{
    const fs::path dir = scratchDirectory("apps", ::testing::UnitTest::GetInstance()->current_test_info()->name());
    osgVis::gen::GenerateOptions options;
    options.kind = osgVis::gen::SceneKind::Office;
    options.triangles = 2000;
    const fs::path model = dir / "office.osgb";
    EXPECT_TRUE(osgDB::writeNodeFile(*osgVis::gen::generate(options).root, model.string()));
    return model;
}

std::string quoted(const fs::path& path)
{
    return "'" + path.string() + "'";
}

// The number printed after `label` on its line of the statistics.
std::string printedAfter(const std::string& output, const std::string& label)
{
    const std::size_t at = output.find(label);
    if (at == std::string::npos)
        return "";
    std::size_t from = output.find_first_not_of(' ', at + label.size());
    const std::size_t to = output.find_first_not_of("0123456789.", from);
    return output.substr(from, to - from);
}

void expectFailure(const std::string& arguments, int exitCode, const std::string& message)
{
    const AppRun run = osgvispvs(arguments);
    EXPECT_EQ(run.exitCode, exitCode) << arguments << " printed:\n" << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << arguments << " printed:\n" << run.output;
}

std::vector<std::uint8_t> readBytes(const fs::path& path)
{
    const std::string text = readText(path);
    return std::vector<std::uint8_t>(text.begin(), text.end());
}

// Cells [begin, end) of the sample view-cell bake (tests/core/pvs/PvsSample.h) as `dir`/`name`.
fs::path writeRange(const fs::path& dir, const std::string& name, std::uint32_t begin, std::uint32_t end)
{
    const fs::path file = dir / name;
    osgVis::core::writePvsFile(file.string(),
                               osgVis::test::viewCellRange(osgVis::test::makeViewCellBake(), begin, end));
    return file;
}
} // namespace

TEST(PvsTool, BakesASmallOfficeAndReportsItsStatistics)
{
    const fs::path model = writeSmallOffice();
    const fs::path pvs = model.parent_path() / "office.pvs", json = model.parent_path() / "office.json";
    const AppRun run = osgvispvs(quoted(model) + " -o " + quoted(pvs) + " --threads 2 --json " + quoted(json));
    ASSERT_EQ(run.exitCode, 0) << run.output;

    const osgVis::core::PvsFile file = osgVis::core::readPvsFile(pvs.string());
    EXPECT_EQ(file.modelPath, "office.osgb");
    const osgVis::core::CellPortalData& data = file.data;
    ASSERT_GT(data.graph.cells.size(), 1u);
    ASSERT_EQ(data.sources.size(), data.graph.cells.size());
    std::uint64_t stabNodes = 0;
    for (const auto& source : data.sources)
        stabNodes += source.stabTree.size();

    EXPECT_EQ(printedAfter(run.output, "cells:"), std::to_string(data.graph.cells.size())) << run.output;
    EXPECT_EQ(printedAfter(run.output, "portals:"), std::to_string(data.graph.portals.size())) << run.output;
    EXPECT_EQ(printedAfter(run.output, "stab-tree nodes:"), std::to_string(stabNodes)) << run.output;
    for (const char* label : {"average visible cells:", "average PVS:", "search budget hit:", "bake time:"})
        EXPECT_FALSE(printedAfter(run.output, label).empty()) << label << " in\n" << run.output;
    EXPECT_NE(run.output.find("% of the model"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("baked " + std::to_string(data.graph.cells.size()) + " cells in"), std::string::npos);
    // stderr is no terminal here: no bar, only the closing line.
    EXPECT_EQ(run.output.find("baking ["), std::string::npos) << run.output;

    const std::string text = readText(json);
    EXPECT_EQ(numberField(text, "cells"), double(data.graph.cells.size())) << text;
    EXPECT_EQ(numberField(text, "portals"), double(data.graph.portals.size())) << text;
    EXPECT_EQ(numberField(text, "stab_nodes"), double(stabNodes)) << text;
    EXPECT_EQ(numberField(text, "objects"), double(data.objectCount)) << text;
    EXPECT_EQ(numberField(text, "file_bytes"), double(fs::file_size(pvs))) << text;
    EXPECT_EQ(numberField(text, "threads"), 2.0) << text;
    for (const char* key : {"average_visible_cells", "average_pvs_fraction", "budget_exceeded_cells", "bake_seconds"})
        EXPECT_TRUE(hasKey(text, key)) << key;
}

TEST(PvsTool, NamesTheModelRelativeToThePvsAndDrawsTheBarWhenAsked)
{
    const fs::path model = writeSmallOffice();
    fs::create_directories(model.parent_path() / "baked");
    const fs::path pvs = model.parent_path() / "baked" / "office.pvs";
    const AppRun run = osgvispvs(quoted(model) + " -o " + quoted(pvs) + " --progress --max-cells 64 --stab-budget 500");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("baking ["), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("100%"), std::string::npos) << run.output;
    const osgVis::core::PvsFile file = osgVis::core::readPvsFile(pvs.string());
    EXPECT_EQ(file.modelPath, "../office.osgb");
    EXPECT_LE(file.data.graph.cells.size(), 64u);
}

TEST(PvsTool, RefusesBadInputNamingIt)
{
    const fs::path dir = scratchDirectory("apps", "PvsToolErrors");
    const fs::path out = dir / "x.pvs";
    const std::string o = " -o " + quoted(out);
    // Command line: exit 2.
    expectFailure("", 2, "missing the model to bake");
    expectFailure(quoted(dir / "m.osgb"), 2, "missing output path (-o OUT.pvs)");
    expectFailure(quoted(dir / "m.osgb") + " -o", 2, "-o expects a value");
    expectFailure("m.osgb --max-cells lots" + o, 2, "--max-cells expects a non-negative integer, got 'lots'");
    expectFailure("m.osgb --threads -1" + o, 2, "--threads expects a non-negative integer, got '-1'");
    expectFailure("m.osgb --stab-budget 0" + o, 2, "--stab-budget must lie between 1 and");
    expectFailure("m.osgb --min-coverage 1.5" + o, 2, "--min-coverage must lie between 0 and 1, got '1.5'");
    expectFailure("m.osgb --min-coverage 0.3x" + o, 2, "--min-coverage expects a number, got '0.3x'");
    expectFailure("m.osgb --min-face-area nan" + o, 2, "--min-face-area expects a number, got 'nan'");
    expectFailure("m.osgb --min-cell-size -0.1" + o, 2, "--min-cell-size must lie between 0 and 1");
    expectFailure("m.osgb --frobnicate" + o, 2, "unknown option '--frobnicate' (see --help)");
    expectFailure("a.osgb b.osgb" + o, 2, "one model only");
    expectFailure("m.osgb --cells-from voxels" + o, 2, "--cells-from is faces or solids, got 'voxels'");
    expectFailure("m.osgb --method multifocal --cells-from solids" + o, 2, "--cells-from goes with --method cellportal");

    // Files and scenes: exit 1.
    expectFailure(quoted(dir / "missing.osgb") + o, 1, "model file '" + (dir / "missing.osgb").string() + "' does not exist");
    const fs::path garbage = writeGarbageModel(dir);
    expectFailure(quoted(garbage) + o, 1, "cannot read model '" + garbage.string() + "'");
    const fs::path empty = writeEmptyModel(dir);
    expectFailure(quoted(empty) + o, 1, "model '" + empty.string() + "' holds no drawable objects");
    expectFailure(quoted(empty) + " -o /nonexistent-osgvis-dir/x.pvs", 1,
                  "cannot write the .pvs file '/nonexistent-osgvis-dir/x.pvs': folder '/nonexistent-osgvis-dir' does not exist");
    expectFailure(quoted(empty) + " -o " + quoted(dir), 1, "it is a folder");
    expectFailure(quoted(empty) + o + " --json /nonexistent-osgvis-dir/s.json", 1,
                  "cannot write the JSON file '/nonexistent-osgvis-dir/s.json'");
    EXPECT_FALSE(fs::exists(out));
}

TEST(PvsTool, ExplainsWhyAModelGivesOneCellAndReadsGltf)
{
    // The glTF plugin is osgVis's own: osgvispvs finds it in the build tree as the other apps do.
    const fs::path engine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    if (!fs::exists(engine))
        GTEST_SKIP() << engine << " is missing (assimp-testmodels)";
    const fs::path dir = scratchDirectory("apps", "PvsToolExplain");
    const AppRun faces = osgvispvs(quoted(engine) + " --explain -o " + quoted(dir / "faces.pvs"));
    ASSERT_EQ(faces.exitCode, 0) << faces.output;
    EXPECT_NE(faces.output.find("subdivision from faces: "), std::string::npos) << faces.output;
    EXPECT_NE(faces.output.find("try --cells-from solids"), std::string::npos) << faces.output;
    const AppRun solids = osgvispvs(quoted(engine) + " --cells-from solids --explain -o " + quoted(dir / "solids.pvs"));
    ASSERT_EQ(solids.exitCode, 0) << solids.output;
    EXPECT_NE(solids.output.find("subdivision from solids: 0 solid boxes"), std::string::npos) << solids.output;
    EXPECT_NE(solids.output.find("the model states no solid space"), std::string::npos) << solids.output;
    EXPECT_EQ(printedAfter(solids.output, "cells:"), "1") << solids.output;
    EXPECT_NE(osgVis::core::readPvsFile((dir / "solids.pvs").string()).options.find("from-solids=1"), std::string::npos);
}

TEST(PvsTool, SameBakeGivesTheSameBytesAndRecordsIt)
{
    const fs::path model = writeSmallOffice();
    const fs::path one = model.parent_path() / "one.pvs", two = model.parent_path() / "two.pvs";
    ASSERT_EQ(osgvispvs(quoted(model) + " -o " + quoted(one) + " --threads 1 --max-cells 64").exitCode, 0);
    ASSERT_EQ(osgvispvs(quoted(model) + " -o " + quoted(two) + " --threads 2 --max-cells 64").exitCode, 0);
    EXPECT_EQ(readBytes(one), readBytes(two)); // no time or thread count in the file
    const osgVis::core::PvsFile file = osgVis::core::readPvsFile(one.string());
    EXPECT_EQ(file.method, "cellportal");
    osgVis::core::BakeOptions options;
    options.subdivision.maxCells = 64;
    EXPECT_EQ(file.options, osgVis::core::canonicalBakeOptions(options));
    EXPECT_NE(file.geometryFingerprint, 0u);
    EXPECT_NE(file.geometryFingerprint, file.data.fingerprint);
}

TEST(PvsTool, MergeJoinsTheRangesOfOneBake)
{
    const fs::path dir = scratchDirectory("apps", "PvsToolMerge");
    const fs::path a = writeRange(dir, "a.pvs", 0, 3), b = writeRange(dir, "b.pvs", 3, 5),
                   c = writeRange(dir, "c.pvs", 5, 7);
    const fs::path merged = dir / "merged.pvs";
    const AppRun run =
        osgvispvs("merge " + quoted(c) + " " + quoted(a) + " " + quoted(b) + " -o " + quoted(merged) + " --complete");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output,
              "merged 3 files into " + merged.string() + ": 7 of the 7 cells of the bake, model 'office.osgb'\n");
    EXPECT_EQ(readBytes(merged), osgVis::core::encodePvs(osgVis::test::makeViewCellBake()));

    // Written elsewhere, the merged file names the model relative to its own folder.
    fs::create_directories(dir / "out");
    const AppRun partial =
        osgvispvs("merge " + quoted(a) + " " + quoted(c) + " --output " + quoted(dir / "out" / "m.pvs"));
    ASSERT_EQ(partial.exitCode, 0) << partial.output;
    const osgVis::core::PvsFile file = osgVis::core::readPvsFile((dir / "out" / "m.pvs").string());
    EXPECT_EQ(file.modelPath, "../office.osgb");
    EXPECT_EQ(file.viewCells.cellIndices, (std::vector<std::uint32_t>{0, 1, 2, 5, 6}));
}

TEST(PvsTool, MergeRefusesWhatDoesNotBelongNamingIt)
{
    const fs::path dir = scratchDirectory("apps", "PvsToolMergeErrors");
    const fs::path a = writeRange(dir, "a.pvs", 0, 3), b = writeRange(dir, "b.pvs", 2, 5),
                   c = writeRange(dir, "c.pvs", 5, 7);
    const fs::path out = dir / "out.pvs";
    const std::string o = " -o " + quoted(out);
    expectFailure("merge " + quoted(a) + " " + quoted(b) + o, 1,
                  "osgvispvs merge: cell 2 is in both " + a.string() + " and " + b.string());
    expectFailure("merge " + quoted(a) + " " + quoted(c) + o + " --complete", 1,
                  "osgvispvs merge: the inputs miss 2 of the 7 cells: 3-4");
    osgVis::core::PvsFile otherModel = osgVis::test::viewCellRange(osgVis::test::makeViewCellBake(), 3, 5);
    otherModel.geometryFingerprint ^= 1;
    osgVis::core::writePvsFile((dir / "other.pvs").string(), otherModel);
    expectFailure("merge " + quoted(a) + " " + quoted(dir / "other.pvs") + o, 1,
                  "osgvispvs merge: " + (dir / "other.pvs").string() + " and " + a.string() +
                      " were baked for different models (geometry fingerprint 0x1111222233334445 and "
                      "0x1111222233334444)");
    osgVis::core::writePvsFile((dir / "cells.pvs").string(), osgVis::test::makeCellPortalSample());
    expectFailure("merge " + quoted(a) + " " + quoted(dir / "cells.pvs") + o, 1,
                  "osgvispvs merge: cannot merge " + (dir / "cells.pvs").string() + ": it holds no view cells");
    expectFailure("merge " + quoted(dir / "cells.pvs") + " " + quoted(a) + o, 1,
                  "osgvispvs merge: cannot merge " + a.string() + ": it holds no cell-portal data");
    expectFailure("merge " + quoted(dir / "missing.pvs") + o, 1,
                  "osgvispvs merge: cannot open .pvs file '" + (dir / "missing.pvs").string() + "'");
    expectFailure("merge " + quoted(a) + " -o /nonexistent-osgvis-dir/x.pvs", 1,
                  "osgvispvs merge: cannot write .pvs file '/nonexistent-osgvis-dir/x.pvs.tmp'");
    EXPECT_FALSE(fs::exists(out));
    // Command line: exit 2.
    expectFailure("merge" + o, 2, "merge: missing the .pvs files to merge");
    expectFailure("merge " + quoted(a), 2, "merge: missing output path (-o OUT.pvs)");
    expectFailure("merge " + quoted(a) + " -o", 2, "merge: -o expects a value");
    expectFailure("merge " + quoted(a) + o + " --cells 1:2", 2, "merge: unknown option '--cells' (see --help)");
}

TEST(PvsTool, HelpAndVersionTellTheTruth)
{
    const AppRun help = osgvispvs("--help");
    EXPECT_EQ(help.exitCode, 0);
    for (const char* option : {"-o, --output", "--min-coverage", "--min-face-area", "--min-cell-size", "--max-cells",
                               "--stab-budget", "--threads", "0 = all cores", "--json", "--progress", "--version",
                               "(default 0.3)", "(default 50000)", "osgvispvs merge IN1.pvs IN2.pvs ... -o OUT.pvs",
                               "--cells A:B", "--shard K/N", "--shard slurm", "--unit-cells N", "OUT.pvs.units/",
                               "Under mpirun"})
        EXPECT_NE(help.output.find(option), std::string::npos) << option << " in\n" << help.output;
    const AppRun mergeHelp = osgvispvs("merge --help");
    EXPECT_EQ(mergeHelp.exitCode, 0);
    for (const char* option : {"usage: osgvispvs merge", "-o, --output OUT.pvs", "--complete", "Exit status"})
        EXPECT_NE(mergeHelp.output.find(option), std::string::npos) << option << " in\n" << mergeHelp.output;
    const AppRun version = osgvispvs("--version");
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_NE(version.output.find("osgVis 0.1.0"), std::string::npos) << version.output;
}

TEST(PvsTool, MultifocalRangesBakedApartMergeIntoTheWholeBake)
{
    const fs::path model = writeSmallOffice();
    const fs::path dir = model.parent_path();
    const std::string cells = " --method multifocal --grid 0,0,0.7,12,8,2.7 --cell-size 4,4,2 --plane-resolution 32"
                              " --planes 1 --near 0.3";
    const AppRun whole = osgvispvs(quoted(model) + " -o " + quoted(dir / "whole.pvs") + cells + " --threads 2");
    ASSERT_EQ(whole.exitCode, 0) << whole.output;
    EXPECT_NE(whole.output.find("cells 0-5 of 6"), std::string::npos) << whole.output;
    const osgVis::core::PvsFile file = osgVis::core::readPvsFile((dir / "whole.pvs").string());
    EXPECT_EQ(file.method, "multifocal");
    EXPECT_EQ(file.nearDistance, 0.3);
    EXPECT_FALSE(file.hasCellPortal);
    ASSERT_TRUE(file.hasViewCells);
    EXPECT_EQ(file.viewCells.totalCells, 6u);
    ASSERT_EQ(osgvispvs(quoted(model) + " -o " + quoted(dir / "low.pvs") + cells + " --cells 0:2 --threads 1").exitCode, 0);
    ASSERT_EQ(osgvispvs(quoted(model) + " -o " + quoted(dir / "high.pvs") + cells + " --cells 2:6").exitCode, 0);
    const AppRun merge = osgvispvs("merge " + quoted(dir / "high.pvs") + " " + quoted(dir / "low.pvs") + " -o " +
                                   quoted(dir / "merged.pvs") + " --complete");
    ASSERT_EQ(merge.exitCode, 0) << merge.output;
    EXPECT_EQ(readBytes(dir / "merged.pvs"), readBytes(dir / "whole.pvs"));
}

TEST(PvsTool, RefusesBadViewCellsNamingThem)
{
    const fs::path model = writeSmallOffice();
    const std::string o = " -o " + quoted(model.parent_path() / "x.pvs");
    expectFailure(quoted(model) + o + " --grid 0,0,0,1,1,1", 2, "--grid, --walk, --cell-size and --near go with --method multifocal");
    expectFailure(quoted(model) + o + " --method multifocal --cell-size 0,1,1", 2, "--cell-size must be positive along every axis");
    expectFailure(quoted(model) + o + " --method multifocal --cell-size -1,1,1", 2, "--cell-size must be positive along every axis");
    expectFailure(quoted(model) + o + " --method multifocal --grid 0,0,0,1,1", 2, "--grid expects 6 comma-separated numbers");
    expectFailure(quoted(model) + o + " --method multifocal --grid 0,0,0,0,1,1", 2, "--grid needs X0 < X1");
    expectFailure(quoted(model) + o + " --method multifocal --grid 0,0,0,nan,1,1", 2, "--grid expects a number, got 'nan'");
    expectFailure(quoted(model) + o + " --method multifocal --cells 3:2", 2, "--cells A:B needs A < B");
    expectFailure(quoted(model) + o + " --method portals", 2, "--method is cellportal or multifocal, got 'portals'");
    expectFailure(quoted(model) + o + " --method multifocal --grid 0,0,0,8,4,2 --cell-size 4,4,2 --cells 0:9", 1,
                  "--cells 0:9 reaches past the 2 view cells of this layout");
}

// A paged database is baked whole: every tile read first, the file keyed by tile so that it serves
// any load state; a tile that cannot be read stops the bake, named.
TEST(PvsTool, BakesAPagedDatabaseWholeAndRefusesOneWithAnUnreadableTile)
{
    const fs::path dir = scratchDirectory("apps", "PvsToolPaged");
    const osgVis::gen::PagedSummary paged = osgVis::test::writePagedOffice(dir.string());
    const AppRun run = osgvispvs(quoted(fs::path(paged.rootPath)) + " -o " + quoted(dir / "db.pvs"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("read " + std::to_string(paged.tiles) + " paged tiles to bake the whole database"),
              std::string::npos)
        << run.output;
    const osgVis::core::PvsFile file = osgVis::core::readPvsFile((dir / "db.pvs").string());
    ASSERT_TRUE(file.data.tiles);
    EXPECT_EQ(file.data.tiles->files.size(), paged.tiles);
    EXPECT_EQ(file.modelPath, "root.osgb");
    EXPECT_EQ(file.data.tiles->files[0], "tile_0000.osgb"); // relative to the root's folder

    const fs::path tile = dir / file.data.tiles->files[2];
    ASSERT_TRUE(fs::exists(tile)) << tile;
    fs::remove(tile);
    expectFailure(quoted(fs::path(paged.rootPath)) + " -o " + quoted(dir / "again.pvs"), 1,
                  "is a paged database whose tile " + tile.string());
    expectFailure(quoted(fs::path(paged.rootPath)) + " -o " + quoted(dir / "again.pvs"), 1,
                  "cannot be read: a bake needs every tile");
    EXPECT_FALSE(fs::exists(dir / "again.pvs"));
}
