// SPDX-License-Identifier: MIT
#pragma once

#include <osgVis/oracle/OracleObject.h>

#include <osg/Node>

#include <cstdint>

namespace osgVis::oracle
{
// The object redrawn outside its graph with the same state: a chain of groups carrying the statesets
// found along its path, in path order (so OVERRIDE/PROTECTED resolve as in the real graph), then a
// MatrixTransform with its world matrix and its ID uniform, then the very same drawable (shared, so
// its own stateset comes along).
osg::ref_ptr<osg::Node> createObjectChain(const OracleObject& object, std::uint32_t objectIndex);

// `placed` (already carrying the object's world matrix) under groups carrying the statesets found
// along the object's path above its drawable, in path order.
osg::ref_ptr<osg::Node> underPathState(const OracleObject& object, osg::Node* placed);
} // namespace osgVis::oracle
