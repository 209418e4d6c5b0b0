// SPDX-License-Identifier: MIT
#pragma once
// The osgVis graphs the serializer tests write and read, and the demo scene of data/osgvis-demo.osgt.
// Coordinates are multiples of 1/8 so that ascii files (6 significant digits) keep them exactly.
#include <osgVis/VisibilityGroup>

#include <osg/ref_ptr>

namespace osgVis::test
{
// Every osgVis node with every property away from its default:
//
//   VisibilityGroup "root"  modes frustum+octree, async (7 frames, slack 0.25), no triangles kept
//   ├── Occluder "screen"   2 polygons; child box "screen-box"
//   ├── Cell "left"         [-4,0]×[-2,2]×[0,3]; child box "left-box"
//   ├── Cell "right"        [0,4]×[-2,2]×[0,3]; child box "right-box"
//   ├── Portal "door"       x=0 square joining left and right
//   └── box "free-box"
osg::ref_ptr<VisibilityGroup> makeRoundTripScene();

// osgviewer's home eye looks at the bound's centre from its -Y side, Z up: seen from there a wall
// (an Occluder: a drawn slab and its front polygon) hides the ten boxes lined up behind it.
//
//        y
//        ^   □ □ □ □ □ □ □ □ □ □     boxes, y in [5, 5.5]
//        |
//        +== wall ================   x and z in [-8, 8], y in [0, 0.25]
//        |
//       eye (home, far on -Y)
osg::ref_ptr<VisibilityGroup> makeDemoScene();
} // namespace osgVis::test
