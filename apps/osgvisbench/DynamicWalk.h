// SPDX-License-Identifier: MIT
#pragma once
// The scripted changes of a dynamic walk (osgvisbench --dynamic): cars (small boxes under DYNAMIC
// MatrixTransforms, so the extraction flags them OBJECT_DYNAMIC) drive along the walk's streets
// every frame; at a quarter and half of the frames new static buildings are dropped on existing
// buildings; at a third and two thirds of the frames existing buildings are deleted from the graph.
// Everything is a function of the frame index and the seed, so every mode and the oracle see the
// same scene at the same frame.
#include <osgVis/SceneExtractor>
#include <osgVis/core/scene/Walk.h>

#include <osg/Geode>
#include <osg/Group>
#include <osg/MatrixTransform>

#include <cstdint>
#include <vector>

namespace osgVis::bench
{
struct DynamicCounts
{
    std::uint64_t carMoves = 0;          // car transforms changed
    std::uint64_t buildingsDropped = 0;  // building boxes added
    std::uint64_t buildingsRemoved = 0;  // building drawables deleted
    std::uint64_t total() const { return carMoves + buildingsDropped + buildingsRemoved; }
};

class DynamicWalk
{
public:
    // `root` is the graph every mode and the oracle render (the model below it); `model` its
    // extraction before any change (buildings are the objects named "building", or every object
    // when none is); `streets` the full walk the cars drive along; `frames` the number of views.
    DynamicWalk(osg::Group& root, const ExtractedScene& model, const core::Walk& streets, std::size_t frames,
                std::uint32_t seed);

    // Puts the graph back as it was before frame 0 (cars at their frame-0 places).
    void reset();
    // Applies the changes up to and including `frame` (frames ascending since reset); returns
    // whether the graph changed.
    bool advanceTo(std::size_t frame);
    // What advanceTo applied since the last reset.
    const DynamicCounts& counts() const { return _counts; }

private:
    struct Removal
    {
        osg::ref_ptr<osg::Geode> geode;
        osg::ref_ptr<osg::Drawable> drawable;
    };
    void placeCars(std::size_t frame);
    void planBuildings(const ExtractedScene& model, std::uint32_t seed);

    osg::ref_ptr<osg::Group> _root;
    osg::ref_ptr<osg::Group> _traffic, _dropped;
    std::vector<osg::ref_ptr<osg::MatrixTransform>> _cars;
    std::vector<core::WalkKey> _streets;
    double _groundZ = 0.0;
    std::size_t _frames = 0;
    // Dropped in two waves (frames/4, frames/2), removed in two waves (frames/3, 2 frames/3).
    std::vector<osg::ref_ptr<osg::Node>> _drops[2];
    std::vector<Removal> _removals[2];
    std::size_t _next = 0; // first frame not applied yet
    DynamicCounts _counts;
};
} // namespace osgVis::bench
