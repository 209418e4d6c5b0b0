// SPDX-License-Identifier: MIT
#pragma once
// One Vec3d polygon in the .osgt/.osgb/.osgx streams: its vertex count, then its vertices (in
// brackets in ascii). Shared by the Occluder and Portal wrappers so both files spell polygons alike.
#include <osg/Vec3d>

#include <vector>

namespace osgDB
{
class InputStream;
class OutputStream;
} // namespace osgDB

namespace osgVis::serializers
{
using Polygon = std::vector<osg::Vec3d>;

// False once the stream failed (truncated file, a count larger than the data): the polygon then
// holds only the vertices actually read, so a lying count never allocates or loops past the data.
bool readPolygon(osgDB::InputStream& is, Polygon& polygon);
void writePolygon(osgDB::OutputStream& os, const Polygon& polygon);
} // namespace osgVis::serializers
