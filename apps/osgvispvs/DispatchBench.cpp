// SPDX-License-Identifier: MIT
// osgvispvs-dispatch-bench: how many units a second rank 0 of an MPI bake hands out, checks and
// stores, with synthetic units of a fixed cost (a sleep, so oversubscribed ranks do not take the
// cores from rank 0) and results of one tiny view cell each. Runs the real dispatcher, unit files
// and join of osgvispvs (docs/scaling.md uses its figures).
//   mpirun --oversubscribe -np R osgvispvs-dispatch-bench --units N --unit-ms MS -o OUT.pvs
#include "BakeCommand.h"
#include "BakeJob.h"
#include "PvsToolOptions.h"
#ifdef OSGVIS_WITH_MPI
#include "MpiBake.h"
#endif

#include <osgVis/core/pvs/ViewCellMerge.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <thread>

using namespace osgVis;
using namespace osgVis::pvstool;

namespace
{
class SyntheticJob final : public BakeJob
{
public:
    SyntheticJob(std::uint32_t cells, double unitMs) : _cells(cells), _unitMs(unitMs)
    {
        _identity.method = "synthetic";
        _identity.options = "unit-ms=" + std::to_string(unitMs);
        _identity.data.objectCount = 1;
        _identity.hasCellPortal = false;
        _identity.hasViewCells = true;
        _identity.viewCells.totalCells = cells;
    }
    std::uint32_t cellCount() const override { return _cells; }
    std::pair<std::uint32_t, std::uint32_t> cellsToBake() const override { return {0, _cells}; }
    std::uint32_t defaultUnitCount() const override { return _cells; }
    std::vector<double> cellCosts() const override { return std::vector<double>(_cells, 1.0); }
    core::PvsFile bakeUnit(std::uint32_t first, std::uint32_t end) const override
    {
        std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(_unitMs * (end - first)));
        core::PvsFile file = _identity;
        for (std::uint32_t c = first; c < end; ++c)
        {
            file.viewCells.cellIndices.push_back(c);
            file.viewCells.cells.push_back(core::Aabb(core::Vec3(c), core::Vec3(c + 1.0)));
            file.viewCells.pvs.push_back(core::VisibleSet(1, true));
        }
        return file;
    }
    std::string mismatch(const core::PvsFile& file, const BakeUnit& unit) const override
    {
        if (std::string why = bakeIdentityMismatch(file, _identity); !why.empty())
            return why;
        return file.viewCells.cellIndices.size() == unit.cells() ? "" : "other cells";
    }
    core::PvsFile join(std::vector<core::PvsFile>&& units, const std::string&) const override
    {
        return core::mergeViewCellPvs(units);
    }
    void report(const core::PvsFile&, const BakeRunFigures& run) const override
    {
        const int workers = run.ranks; // rank 0 bakes too
        const double ideal = _unitMs * 1e-3 * _cells / workers;
        std::printf("{\"ranks\": %d, \"units\": %u, \"unit_ms\": %g, \"seconds\": %.3f, \"units_per_second\": %.1f, "
                    "\"ideal_seconds\": %.3f, \"efficiency\": %.3f, \"join_seconds\": %.3f}\n",
                    run.ranks, _cells, _unitMs, run.seconds, _cells / run.seconds, ideal, ideal / run.seconds,
                    run.joinSeconds);
    }

private:
    std::uint32_t _cells;
    double _unitMs;
    core::PvsFile _identity;
};
} // namespace

int main(int argc, char** argv)
{
    std::uint32_t units = 1000;
    double unitMs = 1.0;
    PvsToolOptions o;
    o.pvsFile = "dispatch-bench.pvs";
    o.bake.threads = 1;
    const char* usage = "usage: [mpirun -np R] osgvispvs-dispatch-bench --units N --unit-ms MS -o OUT.pvs\n";
    bool help = false; // the shared parser's errors point to --help
    apps::CommandLine line;
    line.flag({"--help", "-h"}, help)
        .value({"--units"}, [&](const std::string& text)
               { units = std::uint32_t(apps::parseUnsigned("--units", text, 0, 4294967295u)); })
        .value({"--unit-ms"}, [&](const std::string& text) { unitMs = apps::parseNumber("--unit-ms", text); })
        .value({"-o"}, o.pvsFile);
    if (const std::optional<int> status = apps::readCommandLine(
            [&]
            {
                line.parse(argc, argv);
                return help;
            },
            "osgvispvs-dispatch-bench", usage, usage))
        return *status;
    const SyntheticJob job(std::max(units, 1u), unitMs);
    const MpiSession mpi(argc, argv);
#ifdef OSGVIS_WITH_MPI
    if (mpi.worker())
    {
        mpi.ranks()->serve(job, 1);
        return 0;
    }
#endif
    try
    {
        return leadBake(o, job, mpi.ranks());
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvispvs-dispatch-bench: " << e.what() << '\n';
        return 1;
    }
}
