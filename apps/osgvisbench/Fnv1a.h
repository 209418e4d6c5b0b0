// SPDX-License-Identifier: MIT
#pragma once
// FNV-1a 64, the bench's one hash: per-view set digests (Metrics) and oracle cache keys (OracleCache).
// Tiny and stable across runs and platforms; not a defence against forged input.
#include <cstddef>
#include <cstdint>

namespace osgVis::bench
{
constexpr std::uint64_t Fnv1aSeed = 0xcbf29ce484222325ull;

inline std::uint64_t fnv1a(std::uint64_t hash, const void* data, std::size_t size)
{
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i)
        hash = (hash ^ bytes[i]) * 0x100000001b3ull;
    return hash;
}
} // namespace osgVis::bench
