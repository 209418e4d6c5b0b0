// SPDX-License-Identifier: MIT
#pragma once
// The `q3-pvs-approx` mode: a Quake 3 level culled by the cells it carries (the stated cells a
// format may bring): the eye's BSP leaf gives its cluster, q3map2's cluster PVS the clusters it
// may see, and an object is kept when a leaf of a visible cluster holds its face. It is the map
// compiler's answer, measured against the oracle like every mode, and the bar the automatic
// `cellportal` bake is to reach on these levels. It is approximate: q3map2's PVS is its own
// claim, and on OpenArena's ce1m7 the oracle sees objects it leaves out (on oa_dm4 it missed
// none). Objects no leaf holds (brush models: doors, platforms) are always kept, and so is
// everything when the eye is in solid space or outside the map.
#include <osgVis/SceneExtractor>

#include <osg/Node>

#include <string>

namespace osgVis::apps
{
/// Registers the module `q3-pvs-approx` (once; later calls do nothing). On a scene without a level filed
/// by attachQ3Pvs it keeps every object.
void registerQ3PvsMode();

/// Reads the cells of the level at `path` (a .bsp that OSG's bsp plugin loaded as `model`, whose
/// objects are `objects`) and files them for that scene. Returns what to tell the user: how many
/// clusters and objects, or why the level gives no cells (the file is not IBSP 46, or the plugin's
/// drawables do not match the file's faces). Throws nothing.
std::string attachQ3Pvs(const std::string& path, osg::Node& model, const ExtractedScene& objects);
} // namespace osgVis::apps
