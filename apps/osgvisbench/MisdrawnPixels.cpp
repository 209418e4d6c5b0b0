// SPDX-License-Identifier: MIT
#include "MisdrawnPixels.h"

namespace osgVis::bench
{
std::uint64_t misdrawnPixels(const ViewReference& view, const core::VisibleSet& drawn)
{
    std::uint64_t pixels = 0;
    for (const ObjectPixels& object : view.pixels)
    {
        if (object.id == core::InvalidObject)
        {
            pixels += object.pixels;
            continue;
        }
        // note: a clustered drawable's pixels all count when one of its visible clusters was culled
        // (an upper bound: the ID buffer does not say which cluster owns which pixel)
        bool missing = false;
        for (core::ObjectId id = object.id; id < object.id + object.clusters && !missing; ++id)
            missing = (object.clusters == 1 || view.exact.test(id)) && !drawn.test(id);
        if (missing)
            pixels += object.pixels;
    }
    return pixels;
}

std::size_t misdrawnBin(std::uint64_t pixels)
{
    std::size_t bin = 0;
    while (bin < MisdrawnPixels::BinUpperBounds.size() && pixels > MisdrawnPixels::BinUpperBounds[bin])
        ++bin;
    return bin;
}

std::string misdrawnBinLabel(std::size_t bin)
{
    const auto& upper = MisdrawnPixels::BinUpperBounds;
    if (bin == 0)
        return std::to_string(upper[0]);
    if (bin >= upper.size())
        return ">" + std::to_string(upper.back());
    return std::to_string(upper[bin - 1] + 1) + "-" + std::to_string(upper[bin]);
}

void MisdrawnTally::add(std::uint64_t pixels)
{
    ++_frames;
    _sum += double(pixels);
    if (pixels != 0)
        ++_summary.framesWithAny;
    if (pixels > _summary.maxPerFrame)
        _summary.maxPerFrame = pixels;
    ++_summary.histogram[misdrawnBin(pixels)];
}

MisdrawnPixels MisdrawnTally::summary() const
{
    MisdrawnPixels summary = _summary;
    if (_frames != 0)
        summary.meanPerFrame = _sum / double(_frames);
    return summary;
}
} // namespace osgVis::bench
