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

std::size_t VisibleSet::countRange(ObjectId first, ObjectId end) const
{
    end = static_cast<ObjectId>(std::min<std::size_t>(end, _size));
    if (first >= end)
        return 0;
    const std::size_t lastWord = (end - 1) >> 6;
    std::size_t n = 0;
    for (std::size_t w = first >> 6; w <= lastWord; ++w)
    {
        std::uint64_t bits = _words[w];
        if (w == (first >> 6))
            bits &= ~std::uint64_t(0) << (first & 63);
        if (w == lastWord && (end & 63))
            bits &= (std::uint64_t(1) << (end & 63)) - 1;
        n += static_cast<std::size_t>(__builtin_popcountll(bits));
    }
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
    forEach([&](ObjectId id) { result.push_back(id); });
    return result;
}
} // namespace osgVis::core
