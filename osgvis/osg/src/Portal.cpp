// SPDX-License-Identifier: MIT
#include <osgVis/Portal>

namespace osgVis
{
Portal::Portal() = default;

Portal::Portal(const Portal& other, const osg::CopyOp& copyop)
    : osg::Group(other, copyop), _polygon(other._polygon), _cellA(other._cellA), _cellB(other._cellB)
{
}

Portal::~Portal() = default;
} // namespace osgVis
