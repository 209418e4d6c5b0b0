// SPDX-License-Identifier: MIT
#pragma once
// Scene colours: a base colour per kind of thing, varied per instance so screenshots show where one
// object ends and the next begins.
#include "Random.h"

#include <osg/Vec4>

#include <algorithm>

namespace osgVis::gen
{
inline osg::Vec4 varied(const osg::Vec4& base, Random& rng, double spread)
{
    const double shade = rng.uniform(-spread, spread);
    auto channel = [&](float c) { return float(std::clamp(c + shade + rng.uniform(-0.3, 0.3) * spread, 0.0, 1.0)); };
    return {channel(base.r()), channel(base.g()), channel(base.b()), base.a()};
}

namespace palette
{
const osg::Vec4 wall{0.85f, 0.82f, 0.74f, 1.0f};
const osg::Vec4 floor{0.45f, 0.36f, 0.30f, 1.0f};
const osg::Vec4 corridorFloor{0.36f, 0.42f, 0.38f, 1.0f};
const osg::Vec4 ceiling{0.94f, 0.94f, 0.92f, 1.0f};
const osg::Vec4 desk{0.62f, 0.46f, 0.30f, 1.0f};
const osg::Vec4 chair{0.22f, 0.27f, 0.52f, 1.0f};
const osg::Vec4 chairRed{0.55f, 0.20f, 0.20f, 1.0f};
const osg::Vec4 shelf{0.76f, 0.66f, 0.50f, 1.0f};
const osg::Vec4 ground{0.30f, 0.42f, 0.28f, 1.0f};
const osg::Vec4 street{0.32f, 0.32f, 0.34f, 1.0f};
const osg::Vec4 building{0.70f, 0.68f, 0.66f, 1.0f};
const osg::Vec4 lamp{0.15f, 0.15f, 0.15f, 1.0f};
const osg::Vec4 tetra{0.80f, 0.55f, 0.25f, 1.0f};
const osg::Vec4 bark{0.40f, 0.28f, 0.18f, 1.0f};
const osg::Vec4 leaves{0.25f, 0.50f, 0.20f, 1.0f};
const osg::Vec4 target{0.90f, 0.20f, 0.20f, 1.0f};   // adversarial: the object a culler must keep
const osg::Vec4 occluder{0.40f, 0.55f, 0.80f, 1.0f}; // adversarial: what hides (or seems to hide) it
} // namespace palette
} // namespace osgVis::gen
