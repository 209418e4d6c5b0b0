// SPDX-License-Identifier: MIT
// A consumer written before the core moved into folders (osgVis 0.1): it includes the old flat
// paths, which still work for one release and say where each header went. Walk.h is included
// twice (directly and again below) to show the warning comes once per translation unit.
#include <osgVis/core/Walk.h>
#include <osgVis/core/ModuleRegistry.h>
#include <osgVis/core/OctreeModule.h>
#include <osgVis/core/PvsFormat.h>
#include <osgVis/core/Walk.h>

#include <iostream>
#include <sstream>
#include <type_traits>

int main()
{
    std::istringstream text("osgvis-walk 1\nsize 64 64\nprojection perspective 60\nclip 0.1 100\n"
                            "view 0  0 0 0  0 1 0  0 0 1\n");
    const osgVis::core::Walk walk = osgVis::core::Walk::parse(text);
    const std::unique_ptr<osgVis::core::VisibilityModule> octree = osgVis::core::createModule("octree");
    const bool pvsErrorIsRuntimeError = std::is_base_of_v<std::runtime_error, osgVis::core::PvsFormatError>;
    std::cout << "old paths: " << walk.keys.size() << " key, module " << (octree ? "octree" : "none")
              << (pvsErrorIsRuntimeError ? "" : ", bad PvsFormatError") << "\n";
    const bool ok = walk.keys.size() == 1 && octree && pvsErrorIsRuntimeError;
    std::cout << (ok ? "old paths ok\n" : "old paths FAILED\n");
    return ok ? 0 : 1;
}
