// SPDX-License-Identifier: MIT
#include <osgVis/core/scene/VisibleSet.h>

#include <algorithm>
#include <bitset>

namespace osgVis::core
{
void VisibleSet::reset(std::size_t objectCount, bool allVisible)
{
    _size = objectCount;
    _words.assign((objectCount + 63) / 64, allVisible ? ~std::uint64_t(0) : 0);
    // note: bits past _size stay zero so count() and operator== need no masking.
    if (allVisible && (objectCount & 63))
        _words.back() = (std::uint64_t(1) << (objectCount & 63)) - 1;
}

std::size_t VisibleSet::count() const
{
    std::size_t n = 0;
    for (std::uint64_t w : _words)
        n += std::bitset<64>(w).count();
    return n;
}

void VisibleSet::intersectWith(const VisibleSet& other)
{
    const std::size_t shared = std::min(_words.size(), other._words.size());
    for (std::size_t i = 0; i < shared; ++i)
        _words[i] &= other._words[i];
    std::fill(_words.begin() + static_cast<std::ptrdiff_t>(shared), _words.end(), 0);
}

std::vector<ObjectId> VisibleSet::ids() const
{
    std::vector<ObjectId> result;
    result.reserve(count());
    for (std::size_t w = 0; w < _words.size(); ++w)
    {
        std::uint64_t bits = _words[w];
        while (bits)
        {
            const int bit = __builtin_ctzll(bits);
            result.push_back(static_cast<ObjectId>(w * 64 + bit));
            bits &= bits - 1;
        }
    }
    return result;
}
} // namespace osgVis::core
