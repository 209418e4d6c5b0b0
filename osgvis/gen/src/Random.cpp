// SPDX-License-Identifier: MIT
#include "Random.h"

namespace osgVis::gen
{
double Random::unit()
{
    const std::uint32_t a = _engine() >> 5; // 27 bits
    const std::uint32_t b = _engine() >> 6; // 26 bits
    return (double(a) * 67108864.0 + double(b)) * (1.0 / 9007199254740992.0);
}

std::uint32_t Random::below(std::uint32_t n)
{
    return std::uint32_t((std::uint64_t(_engine()) * n) >> 32);
}
} // namespace osgVis::gen
