// SPDX-License-Identifier: MIT
#include "BakeState.h"

#include "ToolFiles.h"

#include <csignal>
#include <cstdlib>

namespace fs = std::filesystem;

namespace osgVis::pvstool
{
BakeState::BakeState(const std::string& pvsFile) : _folder(pvsFile + ".units")
{
    if (const char* kill = std::getenv("OSGVISPVS_KILL_AFTER_UNITS"))
        _killAfter = unsigned(std::strtoul(kill, nullptr, 10));
}

void BakeState::open()
{
    std::error_code error;
    fs::create_directories(_folder, error);
    if (!fs::is_directory(_folder, error))
        throw ToolError("cannot create the bake's state folder '" + _folder.string() + "'");
}

std::vector<bool> BakeState::finished(const BakeJob& job, const std::vector<BakeUnit>& units,
                                      std::vector<std::string>& redone) const
{
    std::vector<bool> done(units.size(), false);
    for (std::size_t i = 0; i < units.size(); ++i)
    {
        const fs::path file = _folder / unitFileName(units[i]);
        std::error_code error;
        if (!fs::exists(file, error))
            continue;
        try
        {
            const std::string why = job.mismatch(core::readPvsFile(file.string()), units[i]);
            done[i] = why.empty();
            if (!why.empty())
                redone.push_back(file.filename().string() + ": " + why);
        }
        catch (const core::PvsFormatError& e)
        {
            redone.push_back(file.filename().string() + ": " + e.what());
        }
    }
    return done;
}

void BakeState::store(const BakeUnit& unit, const core::PvsFile& file)
{
    const fs::path path = _folder / unitFileName(unit);
    try
    {
        core::writePvsFile(path.string(), file);
    }
    catch (const std::exception& e)
    {
        throw ToolError("cannot write the unit file '" + path.string() + "': " + e.what());
    }
    if (_killAfter != 0 && ++_stored == _killAfter)
        std::raise(SIGKILL);
}

std::vector<core::PvsFile> BakeState::read(const std::vector<BakeUnit>& units) const
{
    std::vector<core::PvsFile> files;
    files.reserve(units.size());
    for (const BakeUnit& unit : units)
        files.push_back(core::readPvsFile((_folder / unitFileName(unit)).string()));
    return files;
}

void BakeState::remove(const std::vector<BakeUnit>& units) const
{
    std::error_code error;
    for (const BakeUnit& unit : units)
        fs::remove(_folder / unitFileName(unit), error);
    // Files of other unit grids (an earlier run with other --unit-cells or ranks) and temporary
    // files a kill left behind: everything this tool names "cells-...".
    std::vector<fs::path> leftovers;
    for (fs::directory_iterator entry(_folder, error), end; !error && entry != end; entry.increment(error))
        if (entry->path().filename().string().rfind("cells-", 0) == 0)
            leftovers.push_back(entry->path());
    for (const fs::path& path : leftovers)
        fs::remove(path, error);
    fs::remove(_folder, error); // only when nothing else is left in it
}
} // namespace osgVis::pvstool
