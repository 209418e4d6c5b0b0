// SPDX-License-Identifier: MIT
#pragma once
// Where osgVis's apps find osgVis's own osgDB plugins (.pvs, .gltf/.glb, the serializers).

namespace osgVis::apps
{
// Appends osgVis's plugin folders (the build tree's, the installed one, and the one beside the
// running executable's install prefix) to osgDB's library path, after the user's OSG_LIBRARY_PATH,
// so osgVis's formats load from the build tree and after installation. Call once at startup.
void addOsgVisPluginPaths();
} // namespace osgVis::apps
