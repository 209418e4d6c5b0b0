// SPDX-License-Identifier: MIT
#include <osgVis/core/scene/SceneFingerprint.h>

#include <cstring>

namespace osgVis::core
{
namespace
{
// FNV-1a, 64 bit: tiny, stable across platforms, good enough to tell models apart (not a defence
// against someone forging a model).
class Fnv1a
{
public:
    void add(const void* data, std::size_t size)
    {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i)
        {
            _hash ^= bytes[i];
            _hash *= 0x100000001b3ull;
        }
    }
    void add(std::uint64_t value)
    {
        unsigned char bytes[8];
        for (int i = 0; i < 8; ++i)
            bytes[i] = static_cast<unsigned char>(value >> (8 * i)); // little-endian whatever the host
        add(bytes, 8);
    }
    void add(double value)
    {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &value, sizeof bits);
        add(bits);
    }
    std::uint64_t value() const { return _hash; }

private:
    std::uint64_t _hash = 0xcbf29ce484222325ull;
};

// Flags that change what a bake may assume about an object; OBJECT_OCCLUDER only names a
// candidate and does not change the geometry.
constexpr std::uint32_t FingerprintFlags = OBJECT_DYNAMIC | OBJECT_TRANSPARENT | OBJECT_ALWAYS_VISIBLE |
                                           OBJECT_NO_AUTO_OCCLUDER | OBJECT_CULL_BACK | OBJECT_CULL_FRONT;
} // namespace

std::uint64_t sceneFingerprint(const Scene& scene)
{
    Fnv1a hash;
    hash.add(std::uint64_t(scene.objects.size()));
    for (const SceneObject& object : scene.objects)
    {
        for (int axis = 0; axis < 3; ++axis)
        {
            hash.add(object.bounds.min[axis]);
            hash.add(object.bounds.max[axis]);
        }
        hash.add(std::uint64_t(object.triangleCount));
        hash.add(std::uint64_t(object.flags & FingerprintFlags));
    }
    return hash.value();
}
} // namespace osgVis::core
