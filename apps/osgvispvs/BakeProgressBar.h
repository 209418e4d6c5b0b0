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
    // The closing line: cells and seconds; ends the bar's line when one was drawn.
    void finish(std::size_t cells, double seconds);

private:
    void draw(std::size_t done, std::size_t total, double elapsed);

    std::FILE* _out;
    bool _live;
    bool _drawn = false;
    std::chrono::steady_clock::time_point _start, _lastDraw;
    std::mutex _mutex; // the bake never calls twice at once, but its calls come from worker threads
};
} // namespace osgVis::pvstool
