// SPDX-License-Identifier: MIT
#pragma once
// The bake's progress on stderr: a bar with percentage and ETA, redrawn in place at most five
// times a second (only on a terminal, or when asked), and one closing line in every case.
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <mutex>

namespace osgVis::pvstool
{
class BakeProgressBar
{
public:
    // `live`: redraw the bar while baking (stderr is a terminal, or --progress).
    BakeProgressBar(std::FILE* out, bool live);
    // The bake's progress callback: `done` of `total` source cells searched.
    void update(std::size_t done, std::size_t total);
    // A bake in units: units and cells done of all (finished in earlier runs included), and the
    // cells this run baked, from which the rate and the ETA come.
    void updateUnits(std::size_t unitsDone, std::size_t units, std::size_t cellsDone, std::size_t cells,
                     std::size_t cellsThisRun);
    // The closing line: cells and seconds; ends the bar's line when one was drawn.
    void finish(std::size_t cells, double seconds);
    // The bake stopped short: ends the bar's line, if one was drawn, and says nothing more.
    void interrupt();

private:
    void draw(std::size_t done, std::size_t total, double elapsed);
    bool due(bool last); // a redraw now (never more than five a second, always the last one)

    std::FILE* _out;
    bool _live;
    bool _drawn = false;
    std::chrono::steady_clock::time_point _start, _lastDraw;
    std::mutex _mutex; // the bake never calls twice at once, but its calls come from worker threads
};
} // namespace osgVis::pvstool
