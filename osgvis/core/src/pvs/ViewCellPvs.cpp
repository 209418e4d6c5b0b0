// SPDX-License-Identifier: MIT
#include <osgVis/core/pvs/ViewCellPvs.h>

namespace osgVis::core
{
std::uint32_t ViewCellPvs::locate(const Vec3& p) const
{
    for (std::size_t c = 0; c < cells.size(); ++c)
        if (cells[c].contains(p))
            return static_cast<std::uint32_t>(c);
    return NoCell;
}
} // namespace osgVis::core
