// SPDX-License-Identifier: MIT
// Figures of cell-portal data counted from the data themselves, and the placeholders of source
// cells that a range file of a split bake leaves to the other ranges.
#include <osgVis/core/pvs/CellPortalData.h>

namespace osgVis::core
{
BakeStatistics bakeStatisticsOf(const CellPortalData& data)
{
    BakeStatistics stats;
    stats.cells = static_cast<std::uint32_t>(data.graph.cells.size());
    stats.portals = static_cast<std::uint32_t>(data.graph.portals.size());
    for (const SourceCellVisibility& source : data.sources)
    {
        stats.stabNodes += source.stabTree.size();
        stats.budgetExceededCells += source.budgetExceeded ? 1u : 0u;
        stats.averageVisibleCells += double(source.cellToCell.count());
        stats.averagePvsObjects += double(source.cellToObject.count());
    }
    if (!data.sources.empty())
    {
        stats.averageVisibleCells /= double(data.sources.size());
        stats.averagePvsObjects /= double(data.sources.size());
    }
    return stats;
}

SourceCellVisibility placeholderSource(std::size_t cellCount, std::size_t objectCount)
{
    SourceCellVisibility source;
    source.cellToCell.reset(cellCount);
    source.cellToObject.reset(objectCount);
    return source;
}

bool isPlaceholderSource(const SourceCellVisibility& source)
{
    return source.stabTree.empty() && !source.budgetExceeded && source.cellToCell.count() == 0 &&
           source.cellToObject.count() == 0;
}
} // namespace osgVis::core
