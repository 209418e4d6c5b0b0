// SPDX-License-Identifier: MIT
// osgvispvs: bakes cell-and-portal visibility or multifocal view cells for a model into a .pvs file
// (docs/pvs-format.md) in resumable units, in one process or over MPI ranks, and reports the bake's
// statistics; `osgvispvs merge` joins range files of a split bake (PvsMerge.h). Exit status 1 for
// files that cannot be read or written, an empty scene or a failed unit, 2 for a bad command line
// (as osgvisbench).
#include "BakeCommand.h"
#include "PvsMerge.h"
#include "PvsToolOptions.h"
#ifdef OSGVIS_WITH_MPI
#include "MpiBake.h"
#endif

#include <osgVis/Version>

#include <iostream>
#include <memory>

using namespace osgVis::pvstool;

int main(int argc, char** argv)
{
    if (argc > 1 && std::string(argv[1]) == "merge")
        return runPvsMerge(std::vector<std::string>(argv + 2, argv + argc));
    PvsToolOptions options;
    try
    {
        options = parsePvsToolOptions(argc, argv);
    }
    catch (const UsageError& e)
    {
        std::cerr << "osgvispvs: " << e.what() << "\n(osgvispvs --help for usage)\n";
        return 2;
    }
    if (options.help)
    {
        std::cout << pvsToolUsage();
        return 0;
    }
    if (options.version)
    {
        std::cout << "osgvispvs (osgVis " << osgVisGetVersion() << ")\n";
        return 0;
    }
    MpiBake* ranks = nullptr;
#ifdef OSGVIS_WITH_MPI
    std::unique_ptr<MpiBake> mpi;
    if (MpiBake::launchedByMpirun())
    {
        mpi = std::make_unique<MpiBake>(argc, argv);
        ranks = mpi.get();
    }
#endif
    try
    {
        return runBake(options, ranks);
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvispvs: " << e.what() << '\n';
        return 1;
    }
}
