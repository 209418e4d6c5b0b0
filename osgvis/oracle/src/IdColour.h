// SPDX-License-Identifier: MIT
#pragma once

#include <osg/Vec3f>
#include <osg/Vec4ub>

#include <cstdint>

namespace osgVis::oracle
{
// Object index i draws colour i+1 packed into 24 bits of RGB; 0 is the background.
constexpr std::uint32_t MaxIdObjects = (1u << 24) - 1;

inline osg::Vec3f idColour(std::uint32_t objectIndex)
{
    const std::uint32_t v = objectIndex + 1;
    // note: k/255 converts back to exactly k in an 8-bit normalised colour buffer (round to nearest)
    return osg::Vec3f(float(v & 0xffu) / 255.0f, float((v >> 8) & 0xffu) / 255.0f, float((v >> 16) & 0xffu) / 255.0f);
}

// An RGBA8 pixel read as a little-endian 32-bit word: R in the low byte. Returns index + 1, 0 = background.
inline std::uint32_t idPlusOneOfPixel(std::uint32_t rgba)
{
    return rgba & 0xffffffu;
}

// Triangle t draws t+1 in all 32 bits of RGBA, R the low byte, as an unsigned-byte vertex colour (so
// the values are exact); 0 is the background. Blending is off, so the alpha byte is written as given.
constexpr std::uint64_t MaxIdTriangles = 0xffffffffull - 1;

inline osg::Vec4ub triangleIdColour(std::uint32_t triangleIndex)
{
    const std::uint32_t v = triangleIndex + 1;
    return osg::Vec4ub(v & 0xffu, (v >> 8) & 0xffu, (v >> 16) & 0xffu, v >> 24);
}

// The four RGBA bytes of one pixel back to index + 1 (0 = background).
inline std::uint32_t triangleIdPlusOneOfPixel(const unsigned char* rgba)
{
    return std::uint32_t(rgba[0]) | std::uint32_t(rgba[1]) << 8 | std::uint32_t(rgba[2]) << 16 |
           std::uint32_t(rgba[3]) << 24;
}
} // namespace osgVis::oracle
