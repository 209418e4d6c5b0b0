// SPDX-License-Identifier: MIT
#pragma once
// Everyday OSG application patterns for the "same image" matrix (SameImageMatrixTest.cpp): each one
// builds a fresh, deterministic scene around a group it is handed (a plain osg::Group for the
// reference, an osgVis::VisibilityGroup, or a plain group culled by osgVis::CullVisitor) and animates
// the graph and the camera as pure functions of the frame index, so every run of a pattern sees the
// same graphs and the same views.
//
// The base scene (top view; eye near the origin looking down +y, z up, 45° vertical field of view,
// 128 × 96, near 1, far 200): an opaque grey wall x ∈ [-8, 8], y ∈ [20, 21], z ∈ [-6, 6] hides a
// 3 × 3 grid of boxes at y = 40 and a large box at y = 90; a box at x = 16, y = 40 peeks out past the
// wall's right edge as the eye moves; boxes stand in front of the wall and beside it; three are out
// of view (behind the eye, far left, far above). Flat colours, lighting off. The eye moves by up to
// 1.5 m and turns by up to 5° every frame, always where the wall hides the grid.
//
//            □ (0, 90)                      hidden (large)
//         □ □ □  (x = -5, 0, 5; y = 40)  □ (16, 40) peeking
//   (-60, 20) □    ▔▔▔▔▔▔▔▔▔▔ wall, y = 20        □ (12.5, 26) beside
//                  □ (-4, 14) in front
//                    ◉ eye
//                    □ (0, -20) behind the eye
#include <osg/Group>
#include <osg/Node>
#include <osg/Vec4i>
#include <osgViewer/Viewer>

#include <functional>
#include <string>
#include <vector>

namespace osgVis::test::sameimage
{
constexpr unsigned Width = 128, Height = 96;
constexpr unsigned FrameCount = 30;
// Objects (drawables) of the base scene, and those of them outside the view in every frame.
constexpr unsigned BaseObjects = 17;
constexpr unsigned BaseOutOfView = 3;

// What one run builds its scene around.
struct Build
{
    // The group the pattern's content goes under.
    osg::ref_ptr<osg::Group> group;
    // A further group for patterns that nest one (the same kind as `group` for the reference and the
    // VisibilityGroup door; a VisibilityGroup under osgVis::CullVisitor).
    std::function<osg::ref_ptr<osg::Group>()> makeInnerGroup;
};

// One run's scene: the graph and what changes it, frame by frame.
struct Scene
{
    osg::ref_ptr<osg::Node> root; // the viewer's scene data; holds Build::group somewhere
    // The camera's settings, once, after the harness gave it its context, viewport, projection and
    // view (setUpCapturingCamera: fixed near/far, no small-feature culling) and before osgVis's cull
    // visitors are installed and the viewer is realized (slaves are added here).
    std::function<void(osgViewer::Viewer&)> setUpViewer;
    // The graph at frame `frame` (0 ≤ frame < FrameCount), set before the frame is drawn.
    std::function<void(unsigned frame)> animate;
    // The camera (view, and projection, viewport, state where the pattern changes them) at `frame`.
    std::function<void(osgViewer::Viewer&, unsigned frame)> view;
    // The part of the frame to compare (x, y, width, height), where the viewport does not cover the
    // whole context: what lies outside it is whatever an earlier frame left there.
    std::function<osg::Vec4i(unsigned frame)> comparedRegion;
    // A context with these many stencil bits and multisample samples instead of the plain one.
    unsigned stencilBits = 0;
    unsigned samples = 0;
};

struct Pattern
{
    std::string name; // a gtest parameter name: letters, digits and underscores
    std::string what; // one line: the application pattern
    std::function<Scene(const Build&)> build;
    // The base scene as it stands: occlusion modes must report that they culled something.
    bool checksCulling = false;
};

const std::vector<Pattern>& patterns();

// The base scene's projection (the harness sets it before Scene::setUpViewer): perspective 45°, 4:3,
// near 1, far 200.
void standardProjection(osg::Camera& camera);
// The base scene's view at `frame`: the eye on its path (Scene::view's default).
void standardView(osgViewer::Viewer& viewer, unsigned frame);
} // namespace osgVis::test::sameimage
