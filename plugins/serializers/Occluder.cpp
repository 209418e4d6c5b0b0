// SPDX-License-Identifier: MIT
// osgVis::Occluder: its explicit occluder polygons; children come through osg::Group's wrapper.
#include "PolygonStream.h"

#include <osgVis/Occluder>

#include <osg/Notify>
#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/OutputStream>
#include <osgDB/Serializer>

namespace
{
bool checkPolygons(const osgVis::Occluder& occluder)
{
    return occluder.getNumPolygons() > 0;
}

// A polygon count, then each polygon (PolygonStream) as a "Polygon" property: the XML format needs a
// named element for each nested list. A failure keeps the polygons read in full and reports the
// property as failed.
bool readPolygons(osgDB::InputStream& is, osgVis::Occluder& occluder)
{
    const unsigned count = is.readSize();
    if (is.getException())
        return false;
    is >> is.BEGIN_BRACKET;
    osgVis::Occluder::PolygonList polygons;
    bool complete = true;
    for (unsigned i = 0; i < count && complete; ++i)
    {
        // note: a text file's count may promise more polygons than follow: keep those that do and go on
        // after the list's end instead of reading into the next object.
        if (!is.isBinary() && !is.matchString("Polygon"))
        {
            OSG_WARN << "osgVis::Occluder \"" << occluder.getName() << "\": " << i
                     << " polygons where the file promises " << count << std::endl;
            is >> is.END_BRACKET;
            occluder.setPolygons(polygons);
            return false;
        }
        osgVis::serializers::Polygon polygon;
        complete = osgVis::serializers::readPolygon(is, polygon);
        if (complete)
            polygons.push_back(std::move(polygon));
    }
    if (complete)
        is >> is.END_BRACKET;
    occluder.setPolygons(polygons);
    return complete && !is.getException();
}

bool writePolygons(osgDB::OutputStream& os, const osgVis::Occluder& occluder)
{
    os.writeSize(occluder.getNumPolygons());
    os << os.BEGIN_BRACKET << std::endl;
    for (const osgVis::Occluder::Polygon& polygon : occluder.getPolygons())
    {
        os << os.PROPERTY("Polygon");
        osgVis::serializers::writePolygon(os, polygon);
    }
    os << os.END_BRACKET << std::endl;
    return true;
}
} // namespace

REGISTER_OBJECT_WRAPPER(osgVis_Occluder, new osgVis::Occluder, osgVis::Occluder,
                        "osg::Object osg::Node osg::Group osgVis::Occluder")
{
    ADD_USER_SERIALIZER(Polygons);
}
