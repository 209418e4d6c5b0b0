// SPDX-License-Identifier: MIT
#include "EffectiveState.h"

#include <osg/CullFace>
#include <osg/Depth>
#include <osg/FrontFace>
#include <osg/StateSet>

namespace osgVis::oracle
{
namespace
{
using Values = osg::StateAttribute::Values;

// The one inheritance rule of osg::State: a later (deeper) value replaces the current one unless the
// current one was set with OVERRIDE and the later one is not PROTECTED.
bool replaces(bool currentOverrides, unsigned newValue)
{
    return !currentOverrides || (newValue & Values::PROTECTED) != 0;
}
} // namespace

osg::StateAttribute::GLModeValue effectiveMode(const osg::NodePath& path, osg::StateAttribute::GLMode mode)
{
    osg::StateAttribute::GLModeValue value = Values::INHERIT;
    bool overrides = false;
    for (const osg::Node* node : path)
    {
        const osg::StateSet* stateSet = node->getStateSet();
        if (!stateSet)
            continue;
        const osg::StateAttribute::GLModeValue v = stateSet->getMode(mode);
        if (v == Values::INHERIT || !replaces(overrides, v))
            continue;
        value = v;
        overrides = (v & Values::OVERRIDE) != 0;
    }
    return value;
}

bool effectiveModeOn(const osg::NodePath& path, osg::StateAttribute::GLMode mode)
{
    return (effectiveMode(path, mode) & Values::ON) != 0;
}

const osg::StateAttribute* effectiveAttribute(const osg::NodePath& path, osg::StateAttribute::Type type,
                                              unsigned member)
{
    const osg::StateAttribute* attribute = nullptr;
    bool overrides = false;
    for (const osg::Node* node : path)
    {
        const osg::StateSet* stateSet = node->getStateSet();
        if (!stateSet)
            continue;
        const osg::StateSet::RefAttributePair* pair = stateSet->getAttributePair(type, member);
        if (!pair || !pair->first || !replaces(overrides, pair->second))
            continue;
        attribute = pair->first.get();
        overrides = (pair->second & Values::OVERRIDE) != 0;
    }
    return attribute;
}

namespace
{
bool inDepthSortedBin(const osg::NodePath& path)
{
    std::string binName;
    bool overrides = false;
    for (const osg::Node* node : path)
    {
        const osg::StateSet* stateSet = node->getStateSet();
        if (!stateSet || !stateSet->useRenderBinDetails())
            continue;
        const unsigned mode = stateSet->getRenderBinMode();
        if (overrides && (mode & osg::StateSet::PROTECTED_RENDERBIN_DETAILS) == 0)
            continue;
        binName = stateSet->getBinName();
        overrides = (mode & osg::StateSet::OVERRIDE_RENDERBIN_DETAILS) != 0;
    }
    return binName == "DepthSortedBin";
}
} // namespace

bool drawsWithoutOccluding(const osg::NodePath& path)
{
    if (effectiveModeOn(path, GL_BLEND) || effectiveModeOn(path, GL_ALPHA_TEST) || inDepthSortedBin(path))
        return true;
    const auto* depth = static_cast<const osg::Depth*>(effectiveAttribute(path, osg::StateAttribute::DEPTH));
    return depth && !depth->getWriteMask();
}

FaceCulling effectiveFaceCulling(const osg::NodePath& path)
{
    FaceCulling culling;
    if (!effectiveModeOn(path, GL_CULL_FACE))
        return culling;
    const auto* cullFace = static_cast<const osg::CullFace*>(effectiveAttribute(path, osg::StateAttribute::CULLFACE));
    const osg::CullFace::Mode mode = cullFace ? cullFace->getMode() : osg::CullFace::BACK;
    const auto* frontFace =
        static_cast<const osg::FrontFace*>(effectiveAttribute(path, osg::StateAttribute::FRONTFACE));
    const bool clockwiseIsFront = frontFace && frontFace->getMode() == osg::FrontFace::CLOCKWISE;
    const bool front = mode == osg::CullFace::FRONT || mode == osg::CullFace::FRONT_AND_BACK;
    const bool back = mode == osg::CullFace::BACK || mode == osg::CullFace::FRONT_AND_BACK;
    culling.cullsCounterClockwise = clockwiseIsFront ? back : front;
    culling.cullsClockwise = clockwiseIsFront ? front : back;
    return culling;
}
} // namespace osgVis::oracle
