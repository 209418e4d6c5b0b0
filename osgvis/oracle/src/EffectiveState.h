// SPDX-License-Identifier: MIT
#pragma once

#include <osg/Node>
#include <osg/StateAttribute>

namespace osgVis::oracle
{
// The state a drawable is drawn with, read along its node path (root .. drawable) by OSG's rules:
// a value set with OVERRIDE wins over the values below it, unless those are PROTECTED.

// INHERIT when no stateset on the path sets the mode.
osg::StateAttribute::GLModeValue effectiveMode(const osg::NodePath& path, osg::StateAttribute::GLMode mode);
bool effectiveModeOn(const osg::NodePath& path, osg::StateAttribute::GLMode mode); // INHERIT: GL default, off

// Null when no stateset on the path sets the attribute.
const osg::StateAttribute* effectiveAttribute(const osg::NodePath& path, osg::StateAttribute::Type type,
                                              unsigned member = 0);

// Drawn but hides nothing: blending, a depth-sorted bin, alpha test, or depth writes off.
bool drawsWithoutOccluding(const osg::NodePath& path);

// Which triangles GL discards for this path, by their winding as seen from the eye (GL decides facing
// by window-space winding; counter-clockwise is front unless a FrontFace attribute says otherwise).
struct FaceCulling
{
    bool cullsCounterClockwise = false;
    bool cullsClockwise = false;
};
FaceCulling effectiveFaceCulling(const osg::NodePath& path);
} // namespace osgVis::oracle
