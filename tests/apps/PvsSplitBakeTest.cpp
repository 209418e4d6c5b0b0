// SPDX-License-Identifier: MIT
// osgvispvs bakes split every way (issue 26): the units' grid and order, --shard ranges joined by
// merge, a bake killed half-way and run again, unit files of other bakes or cut short, and over MPI
// ranks (mpirun --oversubscribe): the output is byte-identical to the one-process bake every time,
// and a failing rank fails the bake with its message while the finished units stay.
#include "AppProcess.h"

#include "BakeUnits.h"
#include "PvsToolOptions.h"

#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/gen/Generator.h>

#include <osgDB/WriteFile>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using namespace osgVis::test;
using osgVis::pvstool::BakeUnit;

namespace
{
const std::string MultifocalCells = " --method multifocal --grid 0,0,0.7,12,8,2.7 --cell-size 2,2,2"
                                    " --plane-resolution 24 --planes 1 --near 0.3";

AppRun osgvispvs(const std::string& arguments, const std::string& environment = "")
{
    return runApp("/usr/bin/env", environment + " '" + std::string(OSGVISPVS_EXE) + "' " + arguments);
}

std::string quoted(const fs::path& path)
{
    return "'" + path.string() + "'";
}

struct SplitBake : ::testing::Test
{
    void SetUp() override
    {
        dir = scratchDirectory("apps", ::testing::UnitTest::GetInstance()->current_test_info()->name());
        osgVis::gen::GenerateOptions options;
        options.kind = osgVis::gen::SceneKind::Office;
        options.triangles = 2000;
        model = dir / "office.osgb";
        ASSERT_TRUE(osgDB::writeNodeFile(*osgVis::gen::generate(options).root, model.string()));
    }

    // Bakes `output` with `options`; expects success.
    std::string bake(const std::string& output, const std::string& options, const std::string& environment = "")
    {
        const AppRun run = osgvispvs(quoted(model) + " -o " + quoted(dir / output) + options, environment);
        EXPECT_EQ(run.exitCode, 0) << options << ":\n" << run.output;
        return readText(dir / output);
    }

    std::size_t unitFiles(const std::string& output) const
    {
        std::size_t count = 0;
        std::error_code error;
        for (fs::directory_iterator it(dir / (output + ".units"), error), end; !error && it != end; it.increment(error))
            ++count;
        return count;
    }

    fs::path dir, model;
};

TEST(BakeUnits, GridDependsOnTheCellsAloneAndTheDearestComeFirst)
{
    EXPECT_EQ(osgVis::pvstool::cellsPerUnitFor(470, 1024), 1u);
    EXPECT_EQ(osgVis::pvstool::cellsPerUnitFor(1749, 64), 28u);
    EXPECT_EQ(osgVis::pvstool::cellsPerUnitFor(0, 128), 1u);
    // A range cut from the grid keeps the grid's boundaries.
    const std::vector<BakeUnit> units = osgVis::pvstool::splitIntoUnits(5, 17, 4);
    ASSERT_EQ(units.size(), 4u);
    EXPECT_EQ(units[0].first, 5u);
    EXPECT_EQ(units[0].end, 8u);
    EXPECT_EQ(units[1].first, 8u);
    EXPECT_EQ(units[3].first, 16u);
    EXPECT_EQ(units[3].end, 17u);
    std::vector<BakeUnit> ordered = units;
    std::vector<double> costs(17, 1.0);
    costs[16] = 10.0;
    osgVis::pvstool::orderByCost(ordered, costs);
    EXPECT_EQ(ordered[0].first, 16u); // one dear cell beats four cheap ones
    EXPECT_EQ(ordered[1].first, 8u);  // ties by first cell
    EXPECT_EQ(ordered[2].first, 12u);
    EXPECT_EQ(ordered[3].first, 5u);
    EXPECT_EQ(osgVis::pvstool::shardCells(1, 3, 10), std::make_pair(0u, 3u));
    EXPECT_EQ(osgVis::pvstool::shardCells(3, 3, 10), std::make_pair(6u, 10u));
    EXPECT_EQ(osgVis::pvstool::unitFileName(units[1]), "cells-00000008-00000012.pvs");
}

TEST(BakeUnits, ShardOptionTakesKOfNOrSlurmsArrayTask)
{
    const auto parse = [](std::vector<std::string> args, const char* (*environment)(const char*) = nullptr)
    {
        args.insert(args.begin(), {"osgvispvs", "m.osgb", "-o", "x.pvs"});
        std::vector<char*> argv;
        for (std::string& arg : args)
            argv.push_back(arg.data());
        return osgVis::pvstool::parsePvsToolOptions(int(argv.size()), argv.data(), environment);
    };
    EXPECT_EQ(*parse({"--shard", "2/3"}).shard, std::make_pair(2u, 3u));
    const auto slurm = [](const char* name) -> const char*
    {
        const std::string n = name;
        return n == "SLURM_ARRAY_TASK_ID" ? "7" : n == "SLURM_ARRAY_TASK_MIN" ? "5" : n == "SLURM_ARRAY_TASK_COUNT" ? "4" : nullptr;
    };
    EXPECT_EQ(*parse({"--shard", "slurm"}, slurm).shard, std::make_pair(3u, 4u));
    const auto none = [](const char*) -> const char* { return nullptr; };
    const auto error = [&](std::vector<std::string> args, const char* (*environment)(const char*) = nullptr)
    {
        try
        {
            parse(args, environment);
        }
        catch (const osgVis::pvstool::UsageError& e)
        {
            return std::string(e.what());
        }
        return std::string("(parsed)");
    };
    EXPECT_EQ(error({"--shard", "4/3"}), "--shard must lie between 1 and 3, got '4'");
    EXPECT_EQ(error({"--shard", "0/3"}), "--shard must lie between 1 and 3, got '0'");
    EXPECT_EQ(error({"--shard", "3"}), "--shard expects K/N (the K-th of N cell ranges, 1 <= K <= N) or slurm, got '3'");
    EXPECT_EQ(error({"--shard", "slurm"}, none).rfind("--shard slurm needs SLURM_ARRAY_TASK_ID", 0), 0u);
    EXPECT_EQ(error({"--shard", "1/2", "--cells", "0:3"}), "give --cells or --shard, not both");
    EXPECT_EQ(error({"--unit-cells", "0"}), "--unit-cells must lie between 1 and 100000000, got '0'");
}

TEST_F(SplitBake, ShardsMergeIntoTheWholeBakeForBothMethods)
{
    for (const std::string& method : {std::string(), MultifocalCells})
    {
        const std::string whole = bake("whole.pvs", method);
        ASSERT_FALSE(whole.empty());
        for (int k = 1; k <= 3; ++k)
            bake("shard" + std::to_string(k) + ".pvs", method + " --shard " + std::to_string(k) + "/3");
        const AppRun merge = osgvispvs("merge " + quoted(dir / "shard2.pvs") + " " + quoted(dir / "shard3.pvs") + " " +
                                       quoted(dir / "shard1.pvs") + " -o " + quoted(dir / "merged.pvs") + " --complete");
        ASSERT_EQ(merge.exitCode, 0) << merge.output;
        EXPECT_EQ(readText(dir / "merged.pvs"), whole) << method;
        // Other unit grids and thread counts: the same bytes.
        EXPECT_EQ(bake("fine.pvs", method + " --unit-cells 1 --threads 2"), whole) << method;
        EXPECT_EQ(bake("coarse.pvs", method + " --unit-cells 1000 --threads 1"), whole) << method;
        EXPECT_FALSE(fs::exists(dir / "whole.pvs.units")) << "the state folder goes once the output is written";
    }
    // A shard alone is a range file, which the plugin and the modules will not use as visibility.
    const osgVis::core::PvsFile shard = osgVis::core::readPvsFile((dir / "shard2.pvs").string());
    EXPECT_TRUE(shard.hasViewCells);
    EXPECT_LT(shard.viewCells.cellIndices.size(), shard.viewCells.totalCells);
}

TEST_F(SplitBake, KilledBakeRunAgainBakesTheRestAndGivesTheSameFile)
{
    for (const std::string& method : {std::string(), MultifocalCells})
    {
        const std::string whole = bake("whole.pvs", method + " --unit-cells 1");
        // One worker thread: with two, a second unit may land between the fifth and the kill.
        const AppRun killed = osgvispvs(quoted(model) + " -o " + quoted(dir / "k.pvs") + method +
                                            " --unit-cells 1 --threads 1",
                                        "OSGVISPVS_KILL_AFTER_UNITS=5");
        EXPECT_EQ(killed.exitCode, 128 + 9) << killed.output;
        EXPECT_FALSE(fs::exists(dir / "k.pvs"));
        EXPECT_EQ(unitFiles("k.pvs"), 5u);
        const AppRun resumed = osgvispvs(quoted(model) + " -o " + quoted(dir / "k.pvs") + method + " --unit-cells 1");
        ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
        EXPECT_NE(resumed.output.find("resuming: 5 of "), std::string::npos) << resumed.output;
        EXPECT_EQ(readText(dir / "k.pvs"), whole) << method;
        fs::remove(dir / "k.pvs");
    }
}

TEST_F(SplitBake, CorruptAndForeignUnitFilesAreBakedAgain)
{
    const std::string whole = bake("whole.pvs", MultifocalCells + " --unit-cells 1");
    // A state folder with a truncated unit, a unit of another option set, garbage, a good one and
    // a stale temporary file from a kill mid-write.
    const AppRun killed = osgvispvs(quoted(model) + " -o " + quoted(dir / "k.pvs") + MultifocalCells +
                                        " --unit-cells 1 --threads 1",
                                    "OSGVISPVS_KILL_AFTER_UNITS=4");
    ASSERT_EQ(killed.exitCode, 128 + 9) << killed.output;
    const fs::path units = dir / "k.pvs.units";
    // The units finished dearest first, so which four are there is the estimate's choice: the
    // first three (in name order) are spoilt, the fourth stays good.
    std::vector<fs::path> finished;
    for (const fs::directory_entry& entry : fs::directory_iterator(units))
        finished.push_back(entry.path());
    std::sort(finished.begin(), finished.end());
    ASSERT_EQ(finished.size(), 4u);
    const auto [first, end] = [](const fs::path& file)
    {
        const std::string name = file.filename().string(); // cells-AAAAAAAA-BBBBBBBB.pvs
        return std::make_pair(std::stoul(name.substr(6, 8)), std::stoul(name.substr(15, 8)));
    }(finished[1]);
    fs::resize_file(finished[0], 60);
    bake("other.pvs", " --method multifocal --grid 0,0,0.7,12,8,2.7 --cell-size 2,2,2 --plane-resolution 16"
                      " --planes 1 --near 0.3 --cells " + std::to_string(first) + ":" + std::to_string(end));
    fs::copy_file(dir / "other.pvs", finished[1], fs::copy_options::overwrite_existing);
    std::ofstream(finished[2]) << "not a pvs";
    std::ofstream(units / "cells-00000009-00000010.pvs.tmp") << "half";
    const AppRun resumed = osgvispvs(quoted(model) + " -o " + quoted(dir / "k.pvs") + MultifocalCells + " --unit-cells 1");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    const auto again = [&](std::size_t k) { return "baking again " + finished[k].filename().string() + ": "; };
    EXPECT_NE(resumed.output.find(again(0)), std::string::npos) << resumed.output;
    EXPECT_NE(resumed.output.find("truncated at byte 60"), std::string::npos) << resumed.output;
    EXPECT_NE(resumed.output.find(again(1) + "baked with options"), std::string::npos) << resumed.output;
    EXPECT_NE(resumed.output.find(again(2) + finished[2].string() + ": not a .pvs file: bad magic"), std::string::npos)
        << resumed.output;
    EXPECT_NE(resumed.output.find("resuming: 1 of "), std::string::npos) << resumed.output;
    EXPECT_EQ(readText(dir / "k.pvs"), whole);
    EXPECT_FALSE(fs::exists(units));
}

#ifdef OSGVIS_MPIEXEC
AppRun mpirun(int ranks, const std::string& arguments, const std::string& environment = "")
{
    return runApp("/usr/bin/env", environment + " '" + std::string(OSGVIS_MPIEXEC) +
                                      "' --allow-run-as-root --oversubscribe -np " + std::to_string(ranks) + " '" +
                                      std::string(OSGVISPVS_EXE) + "' " + arguments);
}

TEST_F(SplitBake, AnyNumberOfMpiRanksGivesTheOneProcessFile)
{
    for (const std::string& method : {std::string(), MultifocalCells})
    {
        const std::string whole = bake("whole.pvs", method);
        for (int ranks = 1; ranks <= 4; ++ranks)
        {
            const std::string output = "ranks" + std::to_string(ranks) + ".pvs";
            const AppRun run = mpirun(ranks, quoted(model) + " -o " + quoted(dir / output) + method);
            ASSERT_EQ(run.exitCode, 0) << run.output;
            EXPECT_EQ(readText(dir / output), whole) << ranks << " ranks" << method;
        }
    }
}

TEST_F(SplitBake, FailingRankFailsTheBakeKeepingFinishedUnits)
{
    const std::string whole = bake("whole.pvs", MultifocalCells + " --unit-cells 1");
    const std::string command = quoted(model) + " -o " + quoted(dir / "f.pvs") + MultifocalCells + " --unit-cells 1";
    const AppRun failed = mpirun(3, command, "OSGVISPVS_FAIL_RANK=2");
    EXPECT_NE(failed.exitCode, 0) << failed.output;
    EXPECT_NE(failed.output.find("osgvispvs: the bake failed (rank 2: cells "), std::string::npos) << failed.output;
    EXPECT_NE(failed.output.find("failure injected by OSGVISPVS_FAIL_RANK); the units finished so far stay in"),
              std::string::npos)
        << failed.output;
    EXPECT_FALSE(fs::exists(dir / "f.pvs"));
    const std::size_t kept = unitFiles("f.pvs");
    EXPECT_GE(kept, 1u);
    const AppRun again = mpirun(2, command);
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find("resuming: " + std::to_string(kept) + " of "), std::string::npos) << again.output;
    EXPECT_EQ(readText(dir / "f.pvs"), whole);
}

TEST_F(SplitBake, RankThatCannotReadTheModelFailsTheBake)
{
    const AppRun run = mpirun(2, quoted(dir / "missing.osgb") + " -o " + quoted(dir / "x.pvs"));
    EXPECT_NE(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("osgvispvs: model file '" + (dir / "missing.osgb").string() + "' does not exist"),
              std::string::npos)
        << run.output;
}
#endif
} // namespace
