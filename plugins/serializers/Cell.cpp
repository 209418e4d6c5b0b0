// SPDX-License-Identifier: MIT
// osgVis::Cell: its box (the cell's name is the node's name); children come through osg::Group's wrapper.
#include <osgVis/Cell>

#include <osgDB/ObjectWrapper>
#include <osgDB/Serializer>

REGISTER_OBJECT_WRAPPER(osgVis_Cell, new osgVis::Cell, osgVis::Cell, "osg::Object osg::Node osg::Group osgVis::Cell")
{
    ADD_BOUNDINGBOXD_SERIALIZER(Bounds, osg::BoundingBoxd());
}
