// SPDX-License-Identifier: MIT
// osgvisbench --volume end to end: the multifocal volume PVS of a forest's view volume and of a box
// in a city street, against the volume oracle (small faces and few eyes, to stay fast): nothing
// the oracle saw is missing, it culls, and bad boxes are refused as bad command lines.
#include "AppProcess.h"
#include "BenchJson.h"

#include <gtest/gtest.h>

#include <string>

using namespace osgVis::test;

namespace
{
std::filesystem::path scratchFile(const std::string& name)
{
    return scratchDirectory("bench-volume", ::testing::UnitTest::GetInstance()->current_test_info()->name()) / name;
}

AppRun runVolume(const std::string& arguments, const std::filesystem::path& json)
{
    return runApp(OSGVIS_BENCH_EXE, arguments + " --volume-face 128 --volume-eyes 8 --volume-repeat 1 --json '" +
                                        json.string() + "'");
}
} // namespace

TEST(BenchVolume, TheForestsViewVolumeMissesNothingTheOracleSees)
{
    const std::filesystem::path json = scratchFile("forest.json");
    const AppRun run = runVolume("--generate forest --layout single --triangles 3000 --volume paper", json);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("volume PVS (multifocal)"), std::string::npos) << run.output;
    const std::string text = readText(json);
    EXPECT_EQ(numberField(text, "missing_objects"), 0.0) << text;
    EXPECT_EQ(numberField(text, "missing_triangles"), 0.0) << text;
    EXPECT_EQ(numberField(text, "oracle_eyes"), 22.0) << text; // 8 corners, 6 face centres, 8 inside
    // Self-occlusion inside the tree: some triangles that face the volume are culled.
    EXPECT_GT(numberField(text, "rest_culled").value_or(0.0), 0.0) << text;
    EXPECT_GT(numberField(text, "triangles").value_or(0.0), numberField(text, "exact_triangles").value_or(1e9));
}

TEST(BenchVolume, AStreetVolumeOfTheCityMissesNothingAndCulls)
{
    const std::filesystem::path json = scratchFile("city.json");
    const AppRun run = runVolume("--generate city --triangles 5000 --volume 84,4,1.2,86,8,2.2", json);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string text = readText(json);
    EXPECT_EQ(numberField(text, "missing_objects"), 0.0) << text;
    EXPECT_EQ(numberField(text, "missing_triangles"), 0.0) << text;
    EXPECT_LT(numberField(text, "pvs_objects").value_or(1e9), numberField(text, "objects").value_or(0.0)) << text;
}

TEST(BenchVolume, BadBoxesAreBadCommandLines)
{
    const std::pair<const char*, const char*> cases[] = {
        {"--generate city --volume 1,2,3", "--volume expects X0,Y0,Z0,X1,Y1,Z1 or paper"},
        {"--generate city --volume 0,0,0,0,1,1", "--volume: the box must have positive size along every axis"},
        {"--generate city --volume 0,0,0,nan,1,1", "--volume: the box's corners must be finite"},
        {"--generate city --volume paper", "--volume paper is the view volume of a generated forest"},
        {"--generate forest --volume paper --dynamic", "--volume is a run of its own"},
        {"--generate forest --volume paper --planes 0", "--planes must lie between 1 and 64"},
    };
    for (const auto& [arguments, message] : cases)
    {
        const AppRun run = runApp(OSGVIS_BENCH_EXE, arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments << "\n" << run.output;
        EXPECT_NE(run.output.find(message), std::string::npos) << arguments << "\n" << run.output;
    }
}
