// SPDX-License-Identifier: MIT
#pragma once
// Mis-drawn pixels of a mode (the paper's image-error measure for approximate culling): per view,
// the pixels of the oracle's exact ID image (display resolution) whose object is not in the mode's
// visible set. Conservative modes give 0 by construction, so the count cross-checks them too.
#include "BenchReport.h"
#include "OracleReference.h"

#include <osgVis/core/scene/VisibleSet.h>

#include <cstdint>
#include <string>

namespace osgVis::bench
{
// Pixels of `view`'s exact image showing an object outside `drawn`; pixels of objects the extraction
// does not know always count (no mode can draw them as objects).
std::uint64_t misdrawnPixels(const ViewReference& view, const core::VisibleSet& drawn);
// Index of the histogram bin of MisdrawnPixels holding `pixels` per frame.
std::size_t misdrawnBin(std::uint64_t pixels);
// "0", "1-4", ..., "257-1024", ">1024".
std::string misdrawnBinLabel(std::size_t bin);

// Per-frame counts in, the summary out.
class MisdrawnTally
{
public:
    void add(std::uint64_t pixels);
    MisdrawnPixels summary() const;

private:
    MisdrawnPixels _summary;
    std::uint64_t _frames = 0;
    double _sum = 0.0;
};
} // namespace osgVis::bench
