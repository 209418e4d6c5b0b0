// SPDX-License-Identifier: MIT
#pragma once
// Exact comparison of two osgVis graphs (properties, classes, children) and of their extractions,
// shared by the in-process round trip and the osgconv round trip.
#include <osg/Node>

namespace osgVis::test
{
// Adds a gtest failure for every difference: class names, node names, child counts, the osgVis
// properties of every node (recursively), and the occluders, cells, portals and object bounds of the
// two extractions.
void expectSameGraph(const osg::Node& expected, const osg::Node& actual);
} // namespace osgVis::test
