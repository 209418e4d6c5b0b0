// SPDX-License-Identifier: MIT
#include "OccluderEligibility.h"

#include "PagedNodeCulling.h"
#include "ValueHash.h"

#include "CullingContext.h"

#include <osgVis/Cell>
#include <osgVis/Occluder>
#include <osgVis/Portal>

#include <osg/ColorMask>
#include <osg/CullFace>
#include <osg/Depth>
#include <osg/Drawable>
#include <osg/FrontFace>
#include <osg/Geode>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/Multisample>
#include <osg/PagedLOD>
#include <osg/PolygonMode>
#include <osg/PositionAttitudeTransform>
#include <osg/Program>
#include <osg/ProxyNode>

#include <osgVis/core/scene/Scene.h>

#include <limits>
#include <typeinfo>

namespace osgVis
{
namespace
{
// The value a mode or attribute takes below a chain of state sets, following OSG's rules: a
// lower setting wins unless the inherited one is OVERRIDE and the lower one is not PROTECTED.
template <class Value> struct Inherited
{
    Value value{};
    bool set = false;
    osg::StateAttribute::OverrideValue how = osg::StateAttribute::OFF;

    void apply(const Value& lower, osg::StateAttribute::OverrideValue lowerHow)
    {
        const bool locked =
            set && (how & osg::StateAttribute::OVERRIDE) && !(lowerHow & osg::StateAttribute::PROTECTED);
        if (locked)
            return;
        value = lower;
        how = lowerHow;
        set = true;
    }
};

struct DrawnState
{
    Inherited<bool> cullFace, alphaTest, alphaToCoverage, blend, depthTest, stencilTest, scissorTest, clipPlane;
    Inherited<const osg::StateAttribute*> cullFaceMode, frontFace, polygonMode, depth, program, colorMask;

    void applyMode(Inherited<bool>& mode, const osg::StateSet& ss, GLenum gl)
    {
        const osg::StateAttribute::GLModeValue v = ss.getMode(gl);
        if (v & osg::StateAttribute::INHERIT)
            return;
        mode.apply((v & osg::StateAttribute::ON) != 0, v);
    }
    void applyAttribute(Inherited<const osg::StateAttribute*>& slot, const osg::StateSet& ss,
                        osg::StateAttribute::Type type)
    {
        const osg::StateSet::RefAttributePair* pair = ss.getAttributePair(type);
        if (pair && pair->first.valid())
            slot.apply(pair->first.get(), pair->second);
    }
    void apply(const osg::StateSet& ss)
    {
        applyMode(cullFace, ss, GL_CULL_FACE);
        applyMode(alphaTest, ss, GL_ALPHA_TEST);
        applyMode(alphaToCoverage, ss, GL_SAMPLE_ALPHA_TO_COVERAGE_ARB);
        applyMode(blend, ss, GL_BLEND);
        applyMode(depthTest, ss, GL_DEPTH_TEST);
        applyMode(stencilTest, ss, GL_STENCIL_TEST);
        applyMode(scissorTest, ss, GL_SCISSOR_TEST);
        for (GLenum plane = GL_CLIP_PLANE0; plane <= GL_CLIP_PLANE5; ++plane)
        {
            const osg::StateAttribute::GLModeValue v = ss.getMode(plane);
            if (!(v & osg::StateAttribute::INHERIT) && (v & osg::StateAttribute::ON))
                clipPlane.apply(true, v);
        }
        applyAttribute(cullFaceMode, ss, osg::StateAttribute::CULLFACE);
        applyAttribute(frontFace, ss, osg::StateAttribute::FRONTFACE);
        applyAttribute(polygonMode, ss, osg::StateAttribute::POLYGONMODE);
        applyAttribute(depth, ss, osg::StateAttribute::DEPTH);
        applyAttribute(program, ss, osg::StateAttribute::PROGRAM);
        applyAttribute(colorMask, ss, osg::StateAttribute::COLORMASK);
    }
};

// Nodes whose cull traversal always draws their drawables where extraction put them.
// An LOD child whose range holds every distance (every pixel size) is drawn whenever the LOD is
// traversed, as is every loaded child of a ProxyNode.
bool childDrawnWheneverTraversed(const osg::Node& node, const osg::Node* child)
{
    if (dynamic_cast<const osg::ProxyNode*>(&node))
        return true;
    const auto* lod = dynamic_cast<const osg::LOD*>(&node);
    if (!lod || !child)
        return false;
    // note: OSG culls an LOD by its bound; a plain LOD's user-stated sphere may be smaller than its
    // children (nothing checks it, as the extraction checks a paged node's tiles), and then part of
    // a child may go undrawn.
    const bool paged = dynamic_cast<const osg::PagedLOD*>(lod) != nullptr;
    if (!paged && lod->getCenterMode() == osg::LOD::USER_DEFINED_CENTER && lod->getRadius() >= 0)
        return false;
    const unsigned index = lod->getChildIndex(child);
    return index < lod->getNumRanges() && lod->getMinRange(index) <= 0.0f &&
           lod->getMaxRange(index) >= std::numeric_limits<float>::max();
}

// note: a paged node is skipped by its osgVis callback only when its placeholder is hidden, and then
// whatever its children would hide is hidden already by what hides them.
bool ownCallbackOnly(const osg::Node& node)
{
    const osg::Callback* cb = node.getCullCallback();
    return !cb || (dynamic_cast<const PagedNodeCullCallback*>(cb) && !cb->getNestedCallback());
}

bool drawsEveryFrame(const osg::Node& node, const osg::Node* next, bool isRoot)
{
    if (node.asDrawable())
    {
        const osg::Callback* cb = node.getCullCallback();
        const auto* own = dynamic_cast<const VisibilityCullCallback*>(cb);
        return !node.asDrawable()->getDrawCallback() && (!cb || (own && !own->getChained()));
    }
    if (!isRoot && !ownCallbackOnly(node))
        return false;
    const std::type_info& t = typeid(node);
    return isRoot || t == typeid(osg::Group) || t == typeid(osg::Geode) || t == typeid(osg::MatrixTransform) ||
           t == typeid(osg::PositionAttitudeTransform) || t == typeid(Occluder) || t == typeid(Cell) ||
           t == typeid(Portal) || childDrawnWheneverTraversed(node, next);
}

bool fillsBothSides(const osg::StateAttribute* attribute)
{
    const auto* mode = static_cast<const osg::PolygonMode*>(attribute);
    return !mode || (mode->getMode(osg::PolygonMode::FRONT) == osg::PolygonMode::FILL &&
                     mode->getMode(osg::PolygonMode::BACK) == osg::PolygonMode::FILL);
}

bool writesDepthNormally(const osg::StateAttribute* attribute)
{
    const auto* depth = static_cast<const osg::Depth*>(attribute);
    if (!depth)
        return true;
    const osg::Depth::Function f = depth->getFunction();
    return depth->getWriteMask() && depth->getZNear() == 0.0 && depth->getZFar() == 1.0 &&
           (f == osg::Depth::LESS || f == osg::Depth::LEQUAL);
}

// note: an occluder drawn after what it hides (a later bin) hides it only by painting over it
bool writesEveryColour(const osg::StateAttribute* attribute)
{
    const auto* mask = static_cast<const osg::ColorMask*>(attribute);
    return !mask || (mask->getRedMask() && mask->getGreenMask() && mask->getBlueMask() && mask->getAlphaMask());
}

// Why triangles drawn with `state` may hide nothing, or null. A shader may discard or move fragments,
// an alpha test or alpha-to-coverage punches holes, clip planes, the scissor and the stencil cut
// pixels away: none of them may hide anything on our word.
const char* whyStateHidesNothing(const DrawnState& state)
{
    const std::pair<bool, const char*> rules[] = {
        {!(state.alphaTest.set && state.alphaTest.value), "alpha test"},
        {!(state.alphaToCoverage.set && state.alphaToCoverage.value), "alpha to coverage"},
        {!(state.blend.set && state.blend.value), "blending"},
        {!(state.stencilTest.set && state.stencilTest.value), "stencil test"},
        {!(state.scissorTest.set && state.scissorTest.value), "scissor test"},
        {!state.clipPlane.set, "clip plane"},
        {!(state.depthTest.set && !state.depthTest.value), "depth test off"},
        {fillsBothSides(state.polygonMode.value), "polygon mode lines or points"},
        {writesDepthNormally(state.depth.value), "no depth write, or a depth range or function that is not the usual"},
        {writesEveryColour(state.colorMask.value), "a colour mask (drawn later, it would not paint over what it hides)"},
        {!state.program.value, "a shader program (it may discard or move fragments)"}};
    for (const auto& [holds, why] : rules)
        if (!holds)
            return why;
    return nullptr;
}

// Whether nearer geometry can make this state's depth test fail: the test on, a function that passes
// only for a nearer or equal depth, and the usual depth range.
bool occludable(const DrawnState& state)
{
    if (state.depthTest.set && !state.depthTest.value)
        return false;
    const auto* depth = static_cast<const osg::Depth*>(state.depth.value);
    if (!depth)
        return true;
    const osg::Depth::Function f = depth->getFunction();
    return depth->getZNear() == 0.0 && depth->getZFar() == 1.0 &&
           (f == osg::Depth::LESS || f == osg::Depth::LEQUAL || f == osg::Depth::EQUAL);
}
} // namespace

OccluderEligibility occluderEligibility(const osg::NodePath& path)
{
    OccluderEligibility out;
    DrawnState state;
    bool everyFrame = true;
    for (std::size_t i = 0; i < path.size(); ++i)
    {
        everyFrame = everyFrame && drawsEveryFrame(*path[i], i + 1 < path.size() ? path[i + 1] : nullptr, i == 0);
        if (const osg::StateSet* ss = path[i]->getStateSet())
            state.apply(*ss);
    }

    out.notOccluderBecause =
        everyFrame ? whyStateHidesNothing(state)
                   : "under a node that may not draw it every frame (LOD, Switch, a cull or draw callback)";
    if (out.notOccluderBecause)
        out.flags |= core::OBJECT_NO_AUTO_OCCLUDER;
    // note: a draw callback draws what it likes, the depth test off included
    const osg::Drawable* drawable = path.empty() ? nullptr : path.back()->asDrawable();
    if (!occludable(state) || (drawable && drawable->getDrawCallback()))
        out.flags |= core::OBJECT_UNOCCLUDABLE;

    if (const auto* front = static_cast<const osg::FrontFace*>(state.frontFace.value))
        out.clockwiseFront = front->getMode() == osg::FrontFace::CLOCKWISE;
    if (state.cullFace.set && state.cullFace.value)
    {
        const auto* cull = static_cast<const osg::CullFace*>(state.cullFaceMode.value);
        const osg::CullFace::Mode mode = cull ? cull->getMode() : osg::CullFace::BACK;
        if (mode == osg::CullFace::BACK || mode == osg::CullFace::FRONT_AND_BACK)
            out.flags |= core::OBJECT_CULL_BACK;
        if (mode == osg::CullFace::FRONT || mode == osg::CullFace::FRONT_AND_BACK)
            out.flags |= core::OBJECT_CULL_FRONT;
    }
    return out;
}

InheritedStateRules inheritedStateRules(const std::vector<const osg::StateSet*>& stateSets)
{
    DrawnState state;
    for (const osg::StateSet* ss : stateSets)
        if (ss)
            state.apply(*ss);
    return {whyStateHidesNothing(state), occludable(state)};
}

// note: reads every value DrawnState, the rules above and the extractor's transparency test read, so
// that a state set edited in place changes the key (docs/changes.md).
std::uint64_t drawnStateKey(const osg::StateSet& ss)
{
    ValueHash key;
    for (GLenum mode : {GLenum(GL_CULL_FACE), GLenum(GL_ALPHA_TEST), GLenum(GL_SAMPLE_ALPHA_TO_COVERAGE_ARB),
                        GLenum(GL_DEPTH_TEST), GLenum(GL_STENCIL_TEST), GLenum(GL_SCISSOR_TEST), GLenum(GL_BLEND)})
        key.mix(ss.getMode(mode));
    for (GLenum plane = GL_CLIP_PLANE0; plane <= GL_CLIP_PLANE5; ++plane)
        key.mix(ss.getMode(plane));
    key.mix(static_cast<std::uint64_t>(ss.getRenderingHint()));
    const auto attribute = [&](osg::StateAttribute::Type type) -> const osg::StateAttribute*
    {
        const osg::StateSet::RefAttributePair* pair = ss.getAttributePair(type);
        key.mix(pair ? pair->first.get() : nullptr);
        key.mix(pair ? pair->second : 0u);
        return pair ? pair->first.get() : nullptr;
    };
    if (const auto* cull = static_cast<const osg::CullFace*>(attribute(osg::StateAttribute::CULLFACE)))
        key.mix(cull->getMode());
    if (const auto* front = static_cast<const osg::FrontFace*>(attribute(osg::StateAttribute::FRONTFACE)))
        key.mix(front->getMode());
    if (const auto* polygon = static_cast<const osg::PolygonMode*>(attribute(osg::StateAttribute::POLYGONMODE)))
    {
        key.mix(polygon->getMode(osg::PolygonMode::FRONT));
        key.mix(polygon->getMode(osg::PolygonMode::BACK));
    }
    if (const auto* depth = static_cast<const osg::Depth*>(attribute(osg::StateAttribute::DEPTH)))
    {
        key.mix(depth->getFunction());
        key.mix(depth->getWriteMask());
        key.mixDouble(depth->getZNear());
        key.mixDouble(depth->getZFar());
    }
    if (const auto* mask = static_cast<const osg::ColorMask*>(attribute(osg::StateAttribute::COLORMASK)))
        key.mix((mask->getRedMask() ? 1u : 0u) | (mask->getGreenMask() ? 2u : 0u) | (mask->getBlueMask() ? 4u : 0u) |
                (mask->getAlphaMask() ? 8u : 0u));
    attribute(osg::StateAttribute::PROGRAM);
    return key.value;
}
} // namespace osgVis
