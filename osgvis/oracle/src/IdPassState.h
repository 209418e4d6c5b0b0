// SPDX-License-Identifier: MIT
#pragma once

#include <osg/Group>
#include <osg/StateSet>
#include <osg/Switch>

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

// Where the ID colour comes from: the uniform IdUniformName (one colour for a whole object), or the
// vertex colour (one colour per triangle, every corner the same).
enum class IdSource
{
    ObjectUniform,
    VertexColour
};

IdPassState createIdPassState(IdSource source = IdSource::ObjectUniform);

// The passes as one graph under `root`: opaque objects drawing their IDs; the same objects drawing
// depth only; transparent objects drawing IDs over that depth (a Switch, so found ones can leave).
struct IdPassGraph
{
    osg::ref_ptr<osg::Group> root, opaqueIds, opaqueDepth;
    osg::ref_ptr<osg::Switch> transparentIds;

    void addOpaque(osg::Node* chain); // drawn in both opaque passes
    // The opaque IDs alone, or else the opaque depth with the transparent IDs over it.
    void showOpaqueIds(bool opaque);
};

IdPassGraph createIdPassGraph(const IdPassState& pass);
} // namespace osgVis::oracle
