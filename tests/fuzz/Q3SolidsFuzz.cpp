// SPDX-License-Identifier: MIT
// libFuzzer entry point for osgVis::readQ3Solids (include/osgVis/Q3Solids): every input must give
// either a SolidSpace that keeps the reader's promises (finite boxes of positive extent, opaque
// bits in the low six only, finite non-empty unproven bounds, finite eye points) or a
// std::runtime_error naming the input; anything else (a crash, a sanitizer report, another
// exception) is a finding. Built with cmake -DOSGVIS_FUZZ=ON under clang; how to seed and run it:
// tests/fuzz/README.md.
#include <osgVis/Q3Solids>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace
{
bool finite(const osgVis::core::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const osgVis::core::Aabb& box) { return finite(box.min) && finite(box.max); }
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    try
    {
        const osgVis::core::SolidSpace space = osgVis::readQ3Solids(data, size, "fuzz");
        for (const osgVis::core::SolidBox& box : space.boxes)
            if (!finite(box.box) || !(box.box.min.x < box.box.max.x && box.box.min.y < box.box.max.y &&
                                      box.box.min.z < box.box.max.z) ||
                box.opaqueFaces >= 64)
                __builtin_trap();
        for (const osgVis::core::Aabb& bound : space.unproven)
            if (!finite(bound) || bound.empty())
                __builtin_trap();
        for (const osgVis::core::Vec3& eye : space.eyePoints)
            if (!finite(eye))
                __builtin_trap();
    }
    catch (const std::runtime_error& e)
    {
        if (std::strncmp(e.what(), "'fuzz' is no Quake 3 level osgVis can read: ", 44) != 0)
            __builtin_trap(); // an error that does not name the input
    }
    return 0;
}
