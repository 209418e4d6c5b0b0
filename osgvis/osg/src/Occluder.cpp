// SPDX-License-Identifier: MIT
#include <osgVis/Occluder>

namespace osgVis
{
Occluder::Occluder() = default;

Occluder::Occluder(const Occluder& other, const osg::CopyOp& copyop)
    : osg::Group(other, copyop), _polygons(other._polygons)
{
}

Occluder::~Occluder() = default;
} // namespace osgVis
