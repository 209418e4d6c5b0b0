// SPDX-License-Identifier: MIT
#include <osgVis/Cell>

namespace osgVis
{
Cell::Cell() = default;

Cell::Cell(const Cell& other, const osg::CopyOp& copyop) : osg::Group(other, copyop), _bounds(other._bounds) {}

Cell::~Cell() = default;
} // namespace osgVis
