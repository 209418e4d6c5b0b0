// SPDX-License-Identifier: MIT
// osgVis::Portal: its polygon and the names of the two cells it joins; children come through
// osg::Group's wrapper.
#include "PolygonStream.h"

#include <osgVis/Portal>

#include <osgDB/ObjectWrapper>
#include <osgDB/Serializer>

namespace
{
bool checkPolygon(const osgVis::Portal& portal)
{
    return !portal.getPolygon().empty();
}

bool readPolygon(osgDB::InputStream& is, osgVis::Portal& portal)
{
    osgVis::serializers::Polygon polygon;
    const bool complete = osgVis::serializers::readPolygon(is, polygon);
    portal.setPolygon(polygon);
    return complete;
}

bool writePolygon(osgDB::OutputStream& os, const osgVis::Portal& portal)
{
    osgVis::serializers::writePolygon(os, portal.getPolygon());
    return true;
}
} // namespace

REGISTER_OBJECT_WRAPPER(osgVis_Portal, new osgVis::Portal, osgVis::Portal,
                        "osg::Object osg::Node osg::Group osgVis::Portal")
{
    ADD_USER_SERIALIZER(Polygon);
    ADD_STRING_SERIALIZER(CellA, "");
    ADD_STRING_SERIALIZER(CellB, "");
}
