// SPDX-License-Identifier: MIT
// osgvispvs: bakes cell-and-portal visibility or multifocal view cells for a model into a .pvs file
// (docs/pvs-format.md) in resumable units, in one process or over MPI ranks, and reports the bake's
// statistics; `osgvispvs merge` joins range files of a split bake (PvsMerge.h). Exit status 1 for
// files that cannot be read or written, an empty scene or a failed unit, 2 for a bad command line
// (as osgvisbench).
#include "BakeCommand.h"
#include "PvsMerge.h"
#include "PvsToolOptions.h"

#include <osgVis/Version>

#include <PluginPaths.h>

#include <iostream>

using namespace osgVis::pvstool;

int main(int argc, char** argv)
{
    osgVis::apps::addOsgVisPluginPaths(); // .gltf/.glb (and .pvs) load from the build tree and after install
    if (argc > 1 && std::string(argv[1]) == "merge")
        return runPvsMerge(std::vector<std::string>(argv + 2, argv + argc));
    PvsToolOptions options;
    if (const std::optional<int> status = osgVis::apps::readCommandLine(
            [&]
            {
                options = parsePvsToolOptions(argc, argv);
                return options.help;
            },
            "osgvispvs", "(osgvispvs --help for usage)\n", pvsToolUsage()))
        return *status;
    if (options.version)
    {
        std::cout << "osgvispvs (osgVis " << osgVisGetVersion() << ")\n";
        return 0;
    }
    const MpiSession mpi(argc, argv);
    try
    {
        return runBake(options, mpi.ranks());
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvispvs: " << e.what() << '\n';
        return 1;
    }
}
