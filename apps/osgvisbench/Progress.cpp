// SPDX-License-Identifier: MIT
#include "Progress.h"

#include <iostream>

namespace osgVis::bench
{
Progress::Progress(std::string label, std::size_t total) : _label(std::move(label)), _total(total)
{
    std::cerr << _label << ": " << _total << " views" << std::endl;
}

void Progress::advance(std::size_t done)
{
    if (_total == 0)
        return;
    const unsigned tenth = unsigned(done * 10 / _total);
    if (tenth < _nextTenth)
        return;
    std::cerr << _label << ": " << tenth * 10 << "% (" << done << "/" << _total << ")" << std::endl;
    _nextTenth = tenth + 1;
}
} // namespace osgVis::bench
