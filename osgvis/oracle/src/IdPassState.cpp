// SPDX-License-Identifier: MIT
#include "IdPassState.h"

#include <osg/ColorMask>
#include <osg/Depth>
#include <osg/Program>
#include <osg/ShadeModel>
#include <osg/Shader>

namespace osgVis::oracle
{
const char* const IdUniformName = "osgVisOracleId";

namespace
{
constexpr unsigned ForceOn = osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE | osg::StateAttribute::PROTECTED;
constexpr unsigned ForceOff =
    osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE | osg::StateAttribute::PROTECTED;

// Compatibility profile: the objects' fixed-function transform (ftransform is invariant with it) and
// user clip planes (gl_ClipVertex) apply as in the real render.
const char* const VertexSource = R"(#version 120
void main()
{
    gl_Position = ftransform();
    gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex;
}
)";

const char* const FragmentSource = R"(#version 120
uniform vec3 osgVisOracleId;
void main()
{
    gl_FragColor = vec4(osgVisOracleId, 1.0);
}
)";

// The per-triangle ID arrives as the vertex colour, all 32 bits of RGBA.
const char* const VertexColourVertexSource = R"(#version 120
void main()
{
    gl_Position = ftransform();
    gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex;
    gl_FrontColor = gl_Color;
}
)";

const char* const VertexColourFragmentSource = R"(#version 120
void main()
{
    gl_FragColor = gl_Color;
}
)";

osg::ref_ptr<osg::StateSet> createRootState(IdSource source)
{
    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    osg::ref_ptr<osg::Program> program = new osg::Program;
    const bool perVertex = source == IdSource::VertexColour;
    program->setName(perVertex ? "osgVisOracleTriangleId" : "osgVisOracleId");
    program->addShader(new osg::Shader(osg::Shader::VERTEX, perVertex ? VertexColourVertexSource : VertexSource));
    program->addShader(
        new osg::Shader(osg::Shader::FRAGMENT, perVertex ? VertexColourFragmentSource : FragmentSource));
    state->setAttributeAndModes(program.get(), ForceOn);
    if (perVertex)
    {
        // note: with two-sided vertex programs on, back faces would read gl_BackColor, never written;
        // flat shading keeps the provoking corner's colour exactly (all three are the same anyway)
        state->setMode(GL_VERTEX_PROGRAM_TWO_SIDE, ForceOff);
        state->setAttributeAndModes(new osg::ShadeModel(osg::ShadeModel::FLAT), ForceOn);
    }

    for (GLenum mode : {GLenum(GL_BLEND), GLenum(GL_LIGHTING), GLenum(GL_FOG), GLenum(GL_ALPHA_TEST),
                        GLenum(GL_MULTISAMPLE), GLenum(GL_SAMPLE_ALPHA_TO_COVERAGE), GLenum(GL_DITHER),
                        GLenum(GL_POINT_SMOOTH), GLenum(GL_LINE_SMOOTH), GLenum(GL_POLYGON_SMOOTH),
                        GLenum(GL_COLOR_LOGIC_OP)})
        state->setMode(mode, ForceOff);
    state->setTextureMode(0, GL_TEXTURE_2D, ForceOff);
    state->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, true), ForceOn);
    return state;
}

osg::ref_ptr<osg::StateSet> createBinState(int binNumber)
{
    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    // note: the objects' own bins (sky at -1, DepthSortedBin at 10) would reorder the passes
    state->setRenderBinDetails(binNumber, "RenderBin", osg::StateSet::OVERRIDE_PROTECTED_RENDERBIN_DETAILS);
    return state;
}
} // namespace

IdPassState createIdPassState(IdSource source)
{
    IdPassState pass;
    pass.root = createRootState(source);
    pass.opaqueIds = createBinState(0);
    pass.opaqueDepth = createBinState(0);
    pass.opaqueDepth->setAttribute(new osg::ColorMask(false, false, false, false),
                                   osg::StateAttribute::OVERRIDE | osg::StateAttribute::PROTECTED);
    pass.transparentIds = createBinState(1);
    pass.transparentIds->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false), ForceOn);
    return pass;
}

void IdPassGraph::addOpaque(osg::Node* chain)
{
    opaqueIds->addChild(chain);
    opaqueDepth->addChild(chain);
}

void IdPassGraph::showOpaqueIds(bool opaque)
{
    opaqueIds->setNodeMask(opaque ? ~0u : 0u);
    opaqueDepth->setNodeMask(opaque ? 0u : ~0u);
    transparentIds->setNodeMask(opaque ? 0u : ~0u);
}

IdPassGraph createIdPassGraph(const IdPassState& pass)
{
    IdPassGraph graph;
    graph.root = new osg::Group;
    graph.root->setStateSet(pass.root.get());
    graph.opaqueIds = new osg::Group;
    graph.opaqueIds->setStateSet(pass.opaqueIds.get());
    graph.opaqueDepth = new osg::Group;
    graph.opaqueDepth->setStateSet(pass.opaqueDepth.get());
    graph.transparentIds = new osg::Switch;
    graph.transparentIds->setStateSet(pass.transparentIds.get());
    graph.root->addChild(graph.opaqueIds.get());
    graph.root->addChild(graph.opaqueDepth.get());
    graph.root->addChild(graph.transparentIds.get());
    return graph;
}
} // namespace osgVis::oracle
