// SPDX-License-Identifier: MIT
// osgvisbench: every culling mode side by side over one scene and walk, measured against the
// exact-visibility oracle (docs/benchmark.md). Exit status 1 when a conservative mode culled a
// visible object or answered differently at different thread counts, so CI can run the bench as a
// check.
#include "BenchMode.h"
#include "BenchOptions.h"
#include "BenchRun.h"
#include "DynamicBench.h"
#include "PagedBench.h"
#include "ReportHtml.h"
#include "ReportJson.h"
#include "ReportTable.h"
#include "BakedCellCheck.h"
#include "VisibleDump.h"
#include "VolumeBench.h"

#include <SceneSource.h>

#include <PluginPaths.h>
#include <Q3PvsMode.h>

#include <exception>
#include <filesystem>
#include <iostream>

using namespace osgVis::bench;

namespace
{
// The conservative modes that culled something the oracle saw; prints one line each.
int reportFalseInvisible(const BenchReport& report)
{
    int failures = 0;
    for (const ModeResult& result : report.modes)
    {
        if (!result.mode.conservative || result.metrics.falseInvisible == 0)
            continue;
        std::cerr << "osgvisbench: FAIL: conservative mode '" << result.mode.name << "' culled "
                  << result.metrics.falseInvisible << " visible objects in " << result.viewsWithFalseInvisible << " of "
                  << report.views << " views" << std::endl;
        ++failures;
    }
    return failures;
}

// The conservative swept modes whose answer changed with the thread count; prints one line each.
int reportNondeterminism(const BenchReport& report)
{
    int failures = 0;
    for (const SweepDeterminism& determinism : report.sweeps.determinism)
    {
        if (!determinism.conservative || determinism.identicalAcrossThreads)
            continue;
        std::cerr << "osgvisbench: FAIL: conservative mode '" << determinism.mode << "' gave different visible sets "
                  << "at different thread counts in " << determinism.differingViews << " answers" << std::endl;
        ++failures;
    }
    return failures;
}
// Threading-table rows of conservative modes that culled a visible object or, synchronous, drew
// other sets than the single-threaded pass; prints one line each.
int reportThreadingFailures(const BenchReport& report)
{
    int failures = 0;
    for (const ThreadingRow& row : report.threading)
    {
        const std::string name = row.mode + " (" + row.threading + (row.async ? ", async" : "") + ")";
        if (row.conservative && row.falseInvisible != 0)
        {
            std::cerr << "osgvisbench: FAIL: conservative mode '" << name << "' culled " << row.falseInvisible
                      << " visible objects in " << row.viewsWithFalseInvisible << " views" << std::endl;
            ++failures;
        }
        if (row.conservative && row.differingViews && *row.differingViews != 0)
        {
            std::cerr << "osgvisbench: FAIL: synchronous mode '" << name << "' drew other objects than single-threaded in "
                      << *row.differingViews << " views" << std::endl;
            ++failures;
        }
    }
    return failures;
}
} // namespace

int main(int argc, char** argv)
{
    osgVis::apps::addOsgVisPluginPaths(); // .pvs and .gltf/.glb load from the build tree and after install
    osgVis::apps::registerQ3PvsMode();   // a Quake 3 level's own cells (the mode keeps everything elsewhere)
    BenchOptions options;
    std::vector<BenchMode> modes;
    try
    {
        options = parseBenchOptions(argc, argv);
        if (options.help)
        {
            std::cout << benchUsage(options);
            return 0;
        }
        modes = parseBenchModes(options.modes);
        if (options.command == BenchCommand::Dump)
            for (const BenchMode& mode : modes)
                if (mode.kind != BenchMode::Kind::ModuleChain)
                    throw UsageError("--dump-visible writes what a module chain answers; '" + mode.name + "' is none");
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvisbench: " << e.what()
                  << "\n(osgvisbench --help lists every option, osgvisbench SUBCOMMAND --help one run's)" << std::endl;
        return 2;
    }

    try
    {
        switch (options.command)
        {
        case BenchCommand::Dump:
            writeVisibleDumps(options, modes, std::cout);
            return 0;
        case BenchCommand::Volume:
            return runVolumeBench(options, std::cout);
        case BenchCommand::Cells:
            return runBakedCellCheck(options, std::cout);
        case BenchCommand::Paged:
            return runPagedBench(options, modes, std::cout);
        case BenchCommand::Run:
        case BenchCommand::Dynamic:
            break;
        }
        const BenchReport report = options.dynamic ? runDynamicBench(options, modes) : runBench(options, modes);
        writeReportTable(std::cout, report);
        if (!options.jsonFile.empty())
            saveReportJson(options.jsonFile, report);
        if (!options.reportDir.empty())
        {
            std::cout << "report: " << saveReportHtml(options.reportDir, report);
            for (const std::string& picture : report.pictures)
                std::cout << (&picture == &report.pictures.front() ? "\npictures (" + report.pictureBaseline + " | " +
                                                                         report.pictureMode + " | map): "
                                                                   : " ")
                          << (std::filesystem::path(options.reportDir) / picture).string();
            std::cout << std::endl;
        }
        const int failures =
            reportFalseInvisible(report) + reportNondeterminism(report) + reportThreadingFailures(report);
        return failures == 0 ? 0 : 1;
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvisbench: error: " << e.what() << std::endl;
        return 1;
    }
}
