// SPDX-License-Identifier: MIT
#include "PvsBitsetCodec.h"

namespace osgVis::core
{
namespace
{
// Calls visit(run) for each run of the canonical coding of `set`, clear run first.
template <typename Visit> void forEachRun(const VisibleSet& set, Visit&& visit)
{
    std::uint64_t runStart = 0; // first bit of the run being grown
    std::uint64_t position = 0; // first bit after the ids seen so far
    bool inSetRun = false;
    for (ObjectId id : set.ids())
    {
        if (inSetRun && id == position)
        {
            ++position;
            continue;
        }
        if (inSetRun)
        {
            visit(position - runStart); // the set run ends where the ids skip
            runStart = position;
        }
        visit(std::uint64_t(id) - runStart); // clear run before this id (empty only at bit 0)
        runStart = id;
        position = std::uint64_t(id) + 1;
        inSetRun = true;
    }
    if (inSetRun)
    {
        visit(position - runStart);
        runStart = position;
    }
    if (runStart < set.capacity())
        visit(set.capacity() - runStart);
}
} // namespace

void encodeBitset(const VisibleSet& set, PvsByteWriter& out)
{
    std::uint64_t runs = 0;
    forEachRun(set, [&](std::uint64_t) { ++runs; });
    out.varint(runs);
    forEachRun(set, [&](std::uint64_t run) { out.varint(run); });
}

VisibleSet decodeBitset(PvsByteReader& in, std::uint64_t capacity)
{
    const std::uint64_t runs = in.varint();
    in.requireItems(runs, 1);
    // First pass validates on a copy of the reader, so nothing is allocated for a bad capacity.
    PvsByteReader check = in;
    std::uint64_t covered = 0;
    for (std::uint64_t r = 0; r < runs; ++r)
    {
        const std::uint64_t run = check.varint();
        // note: only a leading clear run may be empty, and only when a set run follows, so every set
        // has exactly one coding and re-encoding a decoded file gives the same bytes.
        if (run == 0 && (r > 0 || runs == 1))
            check.fail("empty run " + std::to_string(r) + " in a bitset");
        if (run > capacity - covered)
            check.fail("bitset runs exceeding its capacity of " + std::to_string(capacity) + " bits");
        covered += run;
    }
    if (covered != capacity)
        check.fail("bitset runs covering " + std::to_string(covered) + " of its " + std::to_string(capacity) + " bits");
    VisibleSet set(capacity);
    std::uint64_t position = 0;
    for (std::uint64_t r = 0; r < runs; ++r)
    {
        const std::uint64_t run = in.varint();
        if (r % 2 == 1)
            for (std::uint64_t id = position; id < position + run; ++id)
                set.set(static_cast<ObjectId>(id));
        position += run;
    }
    return set;
}
} // namespace osgVis::core
