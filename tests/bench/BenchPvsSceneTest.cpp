// SPDX-License-Identifier: MIT
// A baked .pvs file as the bench's scene: loaded through the osgdb_pvs plugin (found from the build
// tree without OSG_LIBRARY_PATH), the model it names measured with the bench's own modes, the walk
// found beside the model, the trust verdict printed, and no visible object culled.
#include "AppProcess.h"
#include "BenchJson.h"

#include <osgVis/gen/Generator.h>

#include <osgDB/WriteFile>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace osgVis::test;

namespace
{
std::string quoted(const fs::path& path)
{
    return "'" + path.string() + "'";
}

// A small office and its walk in <dir>/model/, baked by osgvispvs into <dir>/baked/office.pvs.
fs::path bakedOffice(const fs::path& dir)
{
    fs::create_directories(dir / "model");
    fs::create_directories(dir / "baked");
    osgVis::gen::GenerateOptions options;
    options.kind = osgVis::gen::SceneKind::Office;
    options.triangles = 5000;
    const osgVis::gen::GeneratedScene scene = osgVis::gen::generate(options);
    EXPECT_TRUE(osgDB::writeNodeFile(*scene.root, (dir / "model" / "office.osgb").string()));
    scene.walk.save((dir / "model" / "office.walk").string());
    const fs::path pvs = dir / "baked" / "office.pvs";
    const AppRun bake = runApp(OSGVISPVS_EXE, quoted(dir / "model" / "office.osgb") + " -o " + quoted(pvs));
    EXPECT_EQ(bake.exitCode, 0) << bake.output;
    return pvs;
}
} // namespace

TEST(BenchPvsScene, MeasuresTheNamedModelWithTheBakedData)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display (scripts/test.sh provides Xvfb)";
    const fs::path dir = scratchDirectory("bench", "pvs-scene");
    const fs::path pvs = bakedOffice(dir);
    const fs::path json = dir / "bench.json";
    // env -u: the plugin must be found from the build tree alone.
    const AppRun run = runApp("/usr/bin/env", "-u OSG_LIBRARY_PATH '" + std::string(OSGVIS_BENCH_EXE) + "' --scene " +
                                                  quoted(pvs) + " --modes frustum,cellportal --views 10 --size 320x256"
                                                  " --json " + quoted(json));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("baked cell-portal data trusted"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("walk: " + (dir / "model" / "office.walk").string()), std::string::npos) << run.output;

    const std::string text = readText(json);
    EXPECT_NE(text.find("\"scene\": \"" + pvs.string() + "\""), std::string::npos) << text;
    EXPECT_EQ(numberField(text, "views"), 10.0);
    for (const char* mode : {"frustum", "cellportal"})
    {
        const std::string result = modeObject(text, mode);
        ASSERT_FALSE(result.empty()) << mode << " in " << text;
        EXPECT_EQ(numberField(result, "false_invisible"), 0.0) << result;
    }
    // The bench wrapped the model itself: its objects are the model's, not one plugin group.
    EXPECT_GT(numberField(text, "objects").value_or(0), 10.0);
}

TEST(BenchPvsScene, PvsNamingAMissingModelFailsWithMessage)
{
    const fs::path dir = scratchDirectory("bench", "pvs-missing-model");
    const fs::path pvs = bakedOffice(dir);
    fs::remove(dir / "model" / "office.osgb");
    const AppRun run = runApp(OSGVIS_BENCH_EXE, "--scene " + quoted(pvs) + " --modes frustum --views 2");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("cannot read scene '" + pvs.string() + "'"), std::string::npos) << run.output;
}

// A multifocal bake of the office's walk cells: the bench measures it under mode multifocal with
// its cells (0 false-invisible), and --volume-cells checks baked cells against the volume oracle.
TEST(BenchPvsScene, AMultifocalBakeIsMeasuredAndItsCellsHoldWhatTheOracleSees)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display (scripts/test.sh provides Xvfb)";
    const fs::path dir = scratchDirectory("bench", "pvs-multifocal");
    fs::create_directories(dir);
    osgVis::gen::GenerateOptions options;
    options.kind = osgVis::gen::SceneKind::Office;
    options.triangles = 5000;
    const osgVis::gen::GeneratedScene scene = osgVis::gen::generate(options);
    ASSERT_TRUE(osgDB::writeNodeFile(*scene.root, (dir / "office.osgb").string()));
    scene.walk.save((dir / "office.walk").string());
    const fs::path pvs = dir / "office.pvs";
    const AppRun bake = runApp(OSGVISPVS_EXE, quoted(dir / "office.osgb") + " -o " + quoted(pvs) +
                                                  " --method multifocal --cell-size 3,3,2 --cell-origin 0,0,0.7"
                                                  " --plane-resolution 48 --planes 2");
    ASSERT_EQ(bake.exitCode, 0) << bake.output;
    EXPECT_NE(bake.output.find("multifocal bake of"), std::string::npos) << bake.output;

    const fs::path json = dir / "bench.json";
    const AppRun run = runApp(OSGVIS_BENCH_EXE, "--scene " + quoted(pvs) +
                                                    " --modes frustum,multifocal --views 10 --size 320x256 --json " +
                                                    quoted(json));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("baked view cells trusted"), std::string::npos) << run.output;
    EXPECT_EQ(numberField(modeObject(readText(json), "multifocal"), "false_invisible"), 0.0);

    const fs::path cells = dir / "cells.json";
    const AppRun check = runApp(OSGVIS_BENCH_EXE, "--scene " + quoted(pvs) +
                                                      " --volume-cells 2 --volume-face 96 --volume-eyes 4 --json " +
                                                      quoted(cells));
    ASSERT_EQ(check.exitCode, 0) << check.output;
    const std::string text = readText(cells);
    EXPECT_EQ(numberField(text, "cells_checked"), 2.0) << text;
    EXPECT_EQ(numberField(text, "missing_objects"), 0.0) << text;
    EXPECT_GE(numberField(text, "mean_triangle_ratio").value_or(0.0), 1.0) << text;
}
