// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Set of object ids as a bitset: the answer of a visibility query.
#include <osgVis/core/scene/Scene.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
class VisibleSet
{
public:
    VisibleSet() = default;
    explicit VisibleSet(std::size_t objectCount, bool allVisible = false) { reset(objectCount, allVisible); }

    void reset(std::size_t objectCount, bool allVisible = false);
    std::size_t capacity() const { return _size; }

    bool test(ObjectId id) const { return id < _size && ((_words[id >> 6] >> (id & 63)) & 1u); }
    void set(ObjectId id) { _words[id >> 6] |= (std::uint64_t(1) << (id & 63)); }
    void clear(ObjectId id) { _words[id >> 6] &= ~(std::uint64_t(1) << (id & 63)); }
    std::size_t count() const;
    /// How many of the ids [first, end) are in the set (ids past capacity() count as absent).
    std::size_t countRange(ObjectId first, ObjectId end) const;
    /// Calls f(id) for each id in the set, in ascending order: work grows with the words and the ids set.
    template <class F>
    void forEach(F&& f) const
    {
        for (std::size_t w = 0; w < _words.size(); ++w)
            for (std::uint64_t bits = _words[w]; bits; bits &= bits - 1)
                f(static_cast<ObjectId>(w * 64 + static_cast<std::size_t>(__builtin_ctzll(bits))));
    }
    /// this ∩= other
    void intersectWith(const VisibleSet& other);
    /// Ids in ascending order.
    std::vector<ObjectId> ids() const;
    bool operator==(const VisibleSet& o) const { return _size == o._size && _words == o._words; }

private:
    std::size_t _size = 0;
    std::vector<std::uint64_t> _words;
};
} // namespace osgVis::core
