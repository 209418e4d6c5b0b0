// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Do no harm: a view's culling backs off by itself where it costs more than it saves. A culling
/// chain pays for itself only when the drawing it saves outweighs its own cull time, which depends
/// on the scene, the view and the machine (on a level of a few thousand triangles a GPU draws faster
/// than any occlusion test runs). The governor compares, from the frame times the renderer measures,
/// frames culled by the chain with frames where the chain is skipped and every object is handed to
/// the renderer's own culling, and keeps whichever is faster.
///
/// Frames come in blocks of `blockFrames`. Most blocks use the preferred choice; every
/// `probeEvery`-th block tries the other one. Once the block after a probe is over, the ratio of the
/// probe's mean frame time to the mean of the blocks just before and after it (the same stretch of
/// the walk; a steady drift of the scene's cost cancels) updates a running estimate; when the other choice has been faster by more than `margin` on average, it becomes the
/// preferred one. While the preferred choice wins by more than four margins, the probes grow rarer
/// (the cycle doubles up to `maxProbeEvery` blocks), so watching costs less where the answer is
/// clear; any closer result brings the cycle back to `probeEvery`. A frame's time is the interval
/// that ends at the next call, so it is counted for the
/// choice that frame used, and the first frame of each block (which may carry the previous choice's
/// work) is left out. Skipping the chain never hides an object, so either choice is conservative.
#include <cstdint>

namespace osgVis::core
{
struct BackOffOptions
{
    bool enabled = true;
    unsigned blockFrames = 8;  ///< frames per block (at least 2)
    unsigned probeEvery = 8;   ///< every how many blocks the other choice is tried (at least 2)...
    unsigned maxProbeEvery = 32; ///< ...doubling up to this while the preferred choice is clearly faster
    double margin = 0.03;      ///< how much faster (fraction) the other choice must be, on average
    double smoothing = 0.5;    ///< weight of the newest probe in the running estimate, (0, 1]
};

class BackOff
{
public:
    explicit BackOff(const BackOffOptions& options = {});

    /// Call once per frame, before culling, with the wall time (seconds) since the previous call
    /// (or any value on the first call). Returns true when this frame should cull with the chain,
    /// false when it should skip it and let every object through.
    bool useChain(double secondsSincePreviousCall);

    bool enabled() const { return _options.enabled; }
    /// Whether the preferred choice is currently to skip the chain (the chain costs more than it saves).
    bool backedOff() const { return _preferChain == false; }
    /// Mean frame time (ms) of the latest block with the chain and without it; 0 before there is one.
    double chainFrameMs() const { return _chainMs; }
    double skipFrameMs() const { return _skipMs; }
    /// How many times the preference changed.
    std::uint32_t switches() const { return _switches; }

private:
    void finishBlock();

    BackOffOptions _options;
    bool _preferChain = true;
    bool _currentChoice = true; // the choice of the frame now being timed
    unsigned _block = 0;        // index of the current block within the probe cycle
    unsigned _cycle = 0;        // blocks per probe cycle, probeEvery..maxProbeEvery
    unsigned _frameInBlock = 0;
    bool _first = true;
    double _sum = 0.0;          // frame times of the current block (first frame left out)
    unsigned _counted = 0;
    double _previousBlockMean = 0.0; // the latest preferred block
    double _probeMean = 0.0;         // the latest probe block, until the block after it ends
    double _estimate = 0.0;          // running mean of log(probe / preferred)
    double _chainMs = 0.0, _skipMs = 0.0;
    std::uint32_t _switches = 0;
};
} // namespace osgVis::core
