// osgVis::Occluder: its explicit occluder polygons; children come through osg::Group's wrapper.
#include "PolygonStream.h"

#include <osgVis/Occluder>

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
// named element for each nested list. A stream failure keeps the polygons read in full and reports the
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
        osgVis::serializers::Polygon polygon;
        is >> is.PROPERTY("Polygon");
        complete = !is.getException() && osgVis::serializers::readPolygon(is, polygon);
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
