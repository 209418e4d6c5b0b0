// SPDX-License-Identifier: MIT
// osgvisbench's subcommands: each takes only its own options and says so; without one every option
// is taken as before; a subcommand and the older option that chose the same run write the same.
#include "AppProcess.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace osgVis::test;

namespace
{
AppRun runBench(const std::string& arguments)
{
    return runApp(OSGVIS_BENCH_EXE, arguments);
}

void expectUsageError(const std::string& arguments, const std::string& message)
{
    const AppRun run = runBench(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << arguments << ": " << run.output;
    EXPECT_EQ(run.output.find("oracle:"), std::string::npos) << "no work before the check: " << run.output;
}
} // namespace

TEST(BenchSubcommand, EachHelpListsOnlyItsOwnOptions)
{
    const AppRun paged = runBench("paged --help");
    ASSERT_EQ(paged.exitCode, 0) << paged.output;
    EXPECT_NE(paged.output.find("usage: osgvisbench paged"), std::string::npos) << paged.output;
    EXPECT_NE(paged.output.find("--paging-requests"), std::string::npos) << paged.output;
    EXPECT_EQ(paged.output.find("--speeds"), std::string::npos) << paged.output;
    EXPECT_EQ(paged.output.find("--volume-face"), std::string::npos) << paged.output;

    const AppRun volume = runBench("volume --help");
    ASSERT_EQ(volume.exitCode, 0) << volume.output;
    EXPECT_NE(volume.output.find("--plane-resolution"), std::string::npos) << volume.output;
    EXPECT_EQ(volume.output.find("--modes"), std::string::npos) << volume.output;

    // Without a subcommand: every option, and the subcommands listed.
    const AppRun all = runBench("--help");
    ASSERT_EQ(all.exitCode, 0) << all.output;
    for (const char* word : {"--paging-requests", "--speeds", "--volume-face", "--dump-visible", "  dynamic  "})
        EXPECT_NE(all.output.find(word), std::string::npos) << word;
}

TEST(BenchSubcommand, OptionsOfAnotherRunAreUnknown)
{
    expectUsageError("volume --generate forest --volume paper --modes osg", "unknown option '--modes' (see --help)");
    expectUsageError("paged --generate city --speeds 1", "unknown option '--speeds'");
    expectUsageError("dump --generate city --modes frustum --json x.json", "unknown option '--json'");
    expectUsageError("run --generate city --paging-keep 3", "unknown option '--paging-keep'");
    // What a subcommand cannot run without.
    expectUsageError("volume --generate forest", "volume needs --volume");
    expectUsageError("cells --scene x.pvs", "cells needs --volume-cells N");
    expectUsageError("dump --generate city", "dump needs --dump-visible DIR");
    // The checks of the options together hold as before.
    expectUsageError("paged --generate city", "--paged walks a paged database given by --scene");
    expectUsageError("dynamic --generate city --modes frustum --cull-only", "unknown option '--cull-only'");
}

TEST(BenchSubcommand, DumpWritesWhatDumpVisibleWrote)
{
    const std::filesystem::path dir = scratchDirectory("bench", "subcommand-dump");
    const std::string scene = " --generate city --triangles 5000 --views 3 --size 96x64 --modes frustum,frustum+octree";
    const AppRun older = runBench(scene + " --dump-visible '" + (dir / "older").string() + "'");
    const AppRun newer = runBench("dump" + scene + " --dump-visible '" + (dir / "newer").string() + "'");
    ASSERT_EQ(older.exitCode, 0) << older.output;
    ASSERT_EQ(newer.exitCode, 0) << newer.output;
    for (const char* file : {"frustum.visible", "frustum+octree.visible"})
    {
        const std::string expected = readText(dir / "older" / file);
        EXPECT_FALSE(expected.empty()) << file;
        EXPECT_EQ(readText(dir / "newer" / file), expected) << file;
    }
}
