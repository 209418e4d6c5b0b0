// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// What the opaque module-side handles of osgVis/visapi.h are: read-only views of core objects
/// (and the candidate set, which a module may only shrink). A host builds them on the stack around
/// one callback; they never own what they point to.
#include <osgVis/visapi.h>

#include <osgVis/core/scene/Scene.h>
#include <osgVis/core/scene/View.h>
#include <osgVis/core/scene/ViewRegion.h>
#include <osgVis/core/scene/VisibleSet.h>

struct osgvis_scene
{
    const osgVis::core::Scene* scene;
};

struct osgvis_view
{
    const osgVis::core::View* view;
};

struct osgvis_region
{
    const osgVis::core::ViewRegion* region;
};

struct osgvis_visible
{
    osgVis::core::VisibleSet* set;
};
