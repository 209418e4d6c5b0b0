// SPDX-License-Identifier: MIT
#pragma once
// Progress lines on stderr, about every 10% of a pass, so a long run shows it is alive without
// drowning the table on stdout.
#include <cstddef>
#include <string>

namespace osgVis::bench
{
class Progress
{
public:
    Progress(std::string label, std::size_t total);
    // Call after item `done` (1-based count of finished items).
    void advance(std::size_t done);

private:
    std::string _label;
    std::size_t _total;
    unsigned _nextTenth = 1;
};
} // namespace osgVis::bench
