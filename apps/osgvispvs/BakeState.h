// SPDX-License-Identifier: MIT
#pragma once
// The state folder of a bake (OUT.pvs.units/ beside the output): each finished unit's range file,
// written atomically (temporary file, then rename), so that a bake killed at any moment and run
// again with the same command bakes only what is missing. A file there that is not this bake's
// result for its unit (another model or options, truncated, corrupt) is baked again.
#include "BakeJob.h"
#include "BakeUnits.h"

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

namespace osgVis::pvstool
{
class BakeState
{
public:
    explicit BakeState(const std::string& pvsFile);
    const std::filesystem::path& folder() const { return _folder; }

    /// Creates the folder if needed; throws ToolError when it cannot.
    void open();
    /// Per unit: its file holds this job's result. Units with a file that does not are listed in
    /// `redone` with the reason.
    std::vector<bool> finished(const BakeJob& job, const std::vector<BakeUnit>& units,
                               std::vector<std::string>& redone) const;
    void store(const BakeUnit& unit, const core::PvsFile& file);
    /// The files of `units`, in their order.
    std::vector<core::PvsFile> read(const std::vector<BakeUnit>& units) const;
    /// Removes the units' files and the folder (once the output is written).
    void remove(const std::vector<BakeUnit>& units) const;

private:
    std::filesystem::path _folder;
    std::atomic<unsigned> _stored{0}; // store() runs on several worker threads
    unsigned _killAfter = 0; // OSGVISPVS_KILL_AFTER_UNITS: the tests' stand-in for a kill mid-bake
};
} // namespace osgVis::pvstool
