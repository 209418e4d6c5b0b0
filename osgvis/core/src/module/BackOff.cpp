// SPDX-License-Identifier: MIT
// Do no harm: frame-time A/B between culling with the chain and skipping it (docs/backoff.md).
#include <osgVis/core/module/BackOff.h>

#include <algorithm>
#include <cmath>

namespace osgVis::core
{
BackOff::BackOff(const BackOffOptions& options) : _options(options)
{
    _options.blockFrames = std::max(2u, _options.blockFrames);
    _options.probeEvery = std::max(2u, _options.probeEvery);
    _options.maxProbeEvery = std::max(_options.probeEvery, _options.maxProbeEvery);
    _cycle = _options.probeEvery;
    _options.smoothing = std::clamp(_options.smoothing, 1e-3, 1.0);
}

bool BackOff::useChain(double seconds)
{
    if (!_options.enabled)
        return true;
    if (!_first)
    {
        // The interval just ended is the previous frame's, the _frameInBlock-th of the current block;
        // the block's first frame may carry the other choice's work, so it is left out.
        if (_frameInBlock >= 2 && std::isfinite(seconds) && seconds > 0.0)
        {
            _sum += seconds;
            ++_counted;
        }
        if (_frameInBlock == _options.blockFrames)
            finishBlock();
    }
    _first = false;
    ++_frameInBlock;
    _currentChoice = _block == _cycle - 1 ? !_preferChain : _preferChain;
    return _currentChoice;
}

void BackOff::finishBlock()
{
    const double mean = _counted ? _sum / _counted : 0.0;
    const bool probe = _block == _cycle - 1;
    (_currentChoice ? _chainMs : _skipMs) = 1000.0 * mean;
    if (probe)
        _probeMean = mean;
    else
    {
        // The block after a probe: the probe against the mean of its two neighbours, which cancels
        // a scene that gets steadily cheaper or dearer along the walk.
        if (_probeMean > 0.0 && _previousBlockMean > 0.0 && mean > 0.0)
        {
            const double s = _options.smoothing;
            _estimate = (1.0 - s) * _estimate + s * std::log(_probeMean / (0.5 * (_previousBlockMean + mean)));
            if (_estimate < std::log(1.0 - _options.margin))
            {
                _preferChain = !_preferChain;
                _estimate = 0.0;
                ++_switches;
                _cycle = _options.probeEvery;
            }
            else if (_estimate > std::log(1.0 + 4.0 * _options.margin))
                _cycle = std::min(2 * _cycle, _options.maxProbeEvery);
            else
                _cycle = _options.probeEvery;
        }
        _probeMean = 0.0;
        _previousBlockMean = mean;
    }
    _block = (_block + 1) % _cycle;
    _frameInBlock = 0;
    _sum = 0.0;
    _counted = 0;
}
} // namespace osgVis::core
