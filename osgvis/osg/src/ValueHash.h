// SPDX-License-Identifier: MIT
#pragma once
// Internal: FNV-1a over 64-bit words, for the keys the adapter compares between culls (state that
// decides occluder eligibility, geometry counters, marker data): equal inputs, equal keys.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <osg/Vec3d>

namespace osgVis
{
struct ValueHash
{
    std::uint64_t value = 1469598103934665603ull;

    void mix(std::uint64_t v) { value = (value ^ v) * 1099511628211ull; }
    void mix(const void* p) { mix(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(p))); }
    void mixDouble(double d)
    {
        std::uint64_t bits;
        std::memcpy(&bits, &d, sizeof bits);
        mix(bits);
    }
    void mix(const std::string& s)
    {
        for (char c : s)
            mix(static_cast<std::uint64_t>(static_cast<unsigned char>(c)));
        mix(std::uint64_t(s.size()));
    }
    void mix(const std::vector<osg::Vec3d>& polygon)
    {
        for (const osg::Vec3d& v : polygon)
            for (int i = 0; i < 3; ++i)
                mixDouble(v[i]);
        mix(std::uint64_t(polygon.size()));
    }
};
} // namespace osgVis
