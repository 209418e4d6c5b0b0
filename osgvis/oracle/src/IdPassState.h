// SPDX-License-Identifier: MIT
#pragma once

#include <osg/StateSet>

namespace osgVis::oracle
{
// The state of the ID render. Each is applied with OVERRIDE|PROTECTED above the objects' own state,
// so the objects keep what decides coverage (cull face, front face, polygon mode and offset, line
// width, point size, clip planes) and lose what would change the ID colour or the depth test.
struct IdPassState
{
    // Root: ID shader (colour = uniform IdUniformName), no blending/lighting/fog/texturing/
    // multisampling/dithering/smoothing, depth test LESS with writes.
    osg::ref_ptr<osg::StateSet> root;
    // Opaque objects drawing their IDs.
    osg::ref_ptr<osg::StateSet> opaqueIds;
    // Opaque objects laying down depth only, before the transparent ones.
    osg::ref_ptr<osg::StateSet> opaqueDepth;
    // Transparent objects: IDs tested against the opaque depth, no depth writes, drawn last.
    osg::ref_ptr<osg::StateSet> transparentIds;
};

extern const char* const IdUniformName;

IdPassState createIdPassState();
} // namespace osgVis::oracle
