// SPDX-License-Identifier: MIT
#include "BakeProgressBar.h"

#include <string>

namespace osgVis::pvstool
{
namespace
{
constexpr std::chrono::milliseconds redrawInterval(200); // at most five redraws a second
constexpr int barWidth = 30;

std::string minutesSeconds(double seconds)
{
    const long total = long(seconds + 0.5);
    char text[32];
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
    return text;
}
} // namespace

BakeProgressBar::BakeProgressBar(std::FILE* out, bool live)
    : _out(out), _live(live), _start(std::chrono::steady_clock::now()), _lastDraw(_start - redrawInterval)
{
}

bool BakeProgressBar::due(bool last)
{
    const auto now = std::chrono::steady_clock::now();
    if (now - _lastDraw < redrawInterval && !last)
        return false;
    _lastDraw = now;
    return true;
}

void BakeProgressBar::update(std::size_t done, std::size_t total)
{
    if (!_live)
        return;
    std::lock_guard<std::mutex> lock(_mutex);
    if (due(done >= total))
        draw(done, total, std::chrono::duration<double>(std::chrono::steady_clock::now() - _start).count());
}

void BakeProgressBar::updateUnits(std::size_t unitsDone, std::size_t units, std::size_t cellsDone, std::size_t cells,
                                  std::size_t cellsThisRun)
{
    if (!_live)
        return;
    std::lock_guard<std::mutex> lock(_mutex);
    if (!due(unitsDone >= units))
        return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - _start).count();
    const double fraction = cells ? double(cellsDone) / double(cells) : 1.0;
    std::string bar(std::size_t(fraction * barWidth), '#');
    bar.resize(barWidth, '.');
    const double rate = elapsed > 0.0 ? double(cellsThisRun) / elapsed : 0.0;
    const std::string eta = rate > 0.0 ? minutesSeconds(double(cells - cellsDone) / rate) : "?";
    std::fprintf(_out, "\rbaking [%s] %3d%% %zu/%zu units, %zu/%zu cells, %.3g cells/s, ETA %s  ", bar.c_str(),
                 int(fraction * 100.0), unitsDone, units, cellsDone, cells, rate, eta.c_str());
    std::fflush(_out);
    _drawn = true;
}

void BakeProgressBar::draw(std::size_t done, std::size_t total, double elapsed)
{
    const double fraction = total ? double(done) / double(total) : 1.0;
    const int filled = int(fraction * barWidth);
    std::string bar(std::size_t(filled), '#');
    bar.resize(barWidth, '.');
    // The ETA assumes the remaining cells take as long as the finished ones did on average.
    const std::string eta = done ? minutesSeconds(elapsed * double(total - done) / double(done)) : "?";
    std::fprintf(_out, "\rbaking [%s] %3d%% %zu/%zu cells, ETA %s  ", bar.c_str(), int(fraction * 100.0), done, total,
                 eta.c_str());
    std::fflush(_out);
    _drawn = true;
}

void BakeProgressBar::interrupt()
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (_drawn)
        std::fputc('\n', _out);
    _drawn = false;
    std::fflush(_out);
}

void BakeProgressBar::finish(std::size_t cells, double seconds)
{
    std::lock_guard<std::mutex> lock(_mutex);
    if (_drawn)
        std::fputc('\n', _out);
    std::fprintf(_out, "baked %zu cells in %.2f s\n", cells, seconds);
    std::fflush(_out);
}
} // namespace osgVis::pvstool
