// SPDX-License-Identifier: MIT
#pragma once

#include <osg/Drawable>
#include <osg/Matrixd>
#include <osg/Node>

#include <vector>

namespace osgVis::oracle
{
// One object as the oracle sees it: a drawable instance reached through one node path.
// Matched with the adapter's extraction by (drawable pointer, path).
struct OracleObject
{
    osg::NodePath path; // root given to the oracle .. drawable, inclusive
    osg::ref_ptr<osg::Drawable> drawable;
    osg::Matrixd world; // osg::computeLocalToWorld(path)
    // Drawn, but never hides anything behind it: blending on, a depth-sorted (TRANSPARENT_BIN) bin,
    // alpha test on (its cut-outs are not modelled), or depth writes off.
    bool transparent = false;
};

// Objects under root, depth-first, children in index order: every drawable reached through active
// children (Switch/LOD as a plain NodeVisitor with TRAVERSE_ACTIVE_CHILDREN sees them) and nodes whose
// mask is not 0. A drawable shared under two paths is two objects.
std::vector<OracleObject> enumerateObjects(osg::Node& root);
} // namespace osgVis::oracle
