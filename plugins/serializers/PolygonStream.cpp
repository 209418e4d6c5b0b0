// SPDX-License-Identifier: MIT
#include "PolygonStream.h"

#include <osgDB/InputStream>
#include <osgDB/OutputStream>

namespace osgVis::serializers
{
bool readPolygon(osgDB::InputStream& is, Polygon& polygon)
{
    polygon.clear();
    const unsigned count = is.readSize();
    if (is.getException())
        return false;
    is >> is.BEGIN_BRACKET;
    // note: no reserve(count): the count is untrusted input.
    for (unsigned i = 0; i < count; ++i)
    {
        osg::Vec3d vertex;
        is >> vertex;
        if (is.getException())
            return false;
        polygon.push_back(vertex);
    }
    is >> is.END_BRACKET;
    return !is.getException();
}

void writePolygon(osgDB::OutputStream& os, const Polygon& polygon)
{
    os.writeSize(polygon.size());
    os << os.BEGIN_BRACKET << std::endl;
    for (const osg::Vec3d& vertex : polygon)
        os << vertex << std::endl;
    os << os.END_BRACKET << std::endl;
}
} // namespace osgVis::serializers
