// SPDX-License-Identifier: MIT
#pragma once
// Figures of a headless run, per view and summed up, written as report.json and report.txt.
#include <osg/Stats>

#include <cstdint>
#include <string>
#include <vector>

namespace osgVis::viewer
{
struct FrameFigures
{
    // From the osgVis adapter's statistics; absent in mode "osg" (no osgVis node culls there).
    bool hasOsgVis = false;
    double visibleObjects = 0.0;
    double drawnTriangles = 0.0;
    double cullMilliseconds = 0.0;
    // From OSG's own scene and rendering statistics, in every mode.
    double osgDrawables = 0.0;
    double osgTriangles = 0.0;
    double osgCullMilliseconds = 0.0;
};

// Reads one frame's figures from a camera's osg::Stats (scene, rendering and osgVis collected).
FrameFigures readFrameFigures(const osg::Stats& stats, unsigned frameNumber);

struct RunReport
{
    std::string scene;
    std::string walk;
    std::string mode;
    unsigned width = 0, height = 0;
    std::size_t objects = 0;
    std::uint64_t sceneTriangles = 0;
    std::vector<FrameFigures> frames;
    double totalSeconds = 0.0;

    // Writes OUTDIR/report.json and OUTDIR/report.txt; throws std::runtime_error on failure.
    void write(const std::string& directory) const;
};
} // namespace osgVis::viewer
