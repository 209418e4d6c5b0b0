// SPDX-License-Identifier: MIT
#include <osgVis/core/scene/SceneFingerprint.h>
#include <osgVis/core/scene/SceneTiles.h>

#include "TileFingerprints.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

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

// The grid sceneGeometryFingerprint snaps vertices to: 2^-20 of the scene's largest extent.
struct VertexGrid
{
    Vec3 origin{0.0};
    double step = 1.0;

    explicit VertexGrid(const Aabb& bounds)
    {
        if (bounds.empty())
            return;
        const Vec3 extent = bounds.extent();
        const double largest = std::max({extent.x, extent.y, extent.z});
        origin = bounds.min;
        if (largest > 0.0)
            step = std::ldexp(largest, -20);
    }

    // note: the marker lies outside the clamped range, so no finite coordinate hashes like NaN.
    std::uint64_t cell(float coordinate, int axis) const
    {
        constexpr double Limit = 4611686018427387904.0; // 2^62
        if (!std::isfinite(coordinate))
            return std::uint64_t(1) << 63;
        const double steps = std::round((double(coordinate) - origin[axis]) / step);
        return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::clamp(steps, -Limit, Limit)));
    }
};

void addObject(Fnv1a& hash, const SceneObject& object)
{
    for (int axis = 0; axis < 3; ++axis)
    {
        hash.add(object.bounds.min[axis]);
        hash.add(object.bounds.max[axis]);
    }
    hash.add(std::uint64_t(object.triangleCount));
    hash.add(std::uint64_t(object.flags & FingerprintFlags));
}
} // namespace

std::uint64_t sceneFingerprint(const Scene& scene)
{
    Fnv1a hash;
    hash.add(std::uint64_t(scene.objects.size()));
    for (const SceneObject& object : scene.objects)
        addObject(hash, object);
    return hash.value();
}

std::vector<std::uint64_t> tileFingerprintsOf(const Scene& scene, const SceneTiles& tiles)
{
    // One pass over the objects for all tiles: each tile's hash starts with its object count.
    const std::size_t rootSlot = tiles.files.size();
    const auto slotOf = [&](std::uint32_t tile) { return tile == RootTile ? rootSlot : std::size_t(tile); };
    const std::size_t objects = std::min(tiles.keys.size(), scene.objects.size());
    std::vector<std::uint64_t> counts(rootSlot + 1, 0);
    for (std::size_t id = 0; id < objects; ++id)
        if (const std::uint32_t tile = tiles.keys[id].tile; tile == RootTile || tile < rootSlot)
            ++counts[slotOf(tile)];
    std::vector<Fnv1a> hashes(rootSlot + 1);
    for (std::size_t slot = 0; slot <= rootSlot; ++slot)
        hashes[slot].add(counts[slot]);
    for (std::size_t id = 0; id < objects; ++id)
        if (const std::uint32_t tile = tiles.keys[id].tile; tile == RootTile || tile < rootSlot)
            addObject(hashes[slotOf(tile)], scene.objects[id]);
    std::vector<std::uint64_t> values(rootSlot + 1);
    for (std::size_t slot = 0; slot <= rootSlot; ++slot)
        values[slot] = hashes[slot].value();
    return values;
}

std::uint64_t tileFingerprint(const Scene& scene, const SceneTiles& tiles, std::uint32_t tile)
{
    const std::vector<std::uint64_t> values = tileFingerprintsOf(scene, tiles);
    if (tile == RootTile)
        return values.back();
    if (tile < tiles.files.size())
        return values[tile];
    std::uint64_t count = 0; // a tile the keys name without listing it (NoTile: the empty slots)
    for (const TileKey& key : tiles.keys)
        count += key.tile == tile;
    Fnv1a hash;
    hash.add(count);
    for (std::size_t id = 0; id < tiles.keys.size() && id < scene.objects.size(); ++id)
        if (tiles.keys[id].tile == tile)
            addObject(hash, scene.objects[id]);
    return hash.value();
}

std::uint64_t sceneGeometryFingerprint(const Scene& scene)
{
    Fnv1a hash;
    hash.add(sceneFingerprint(scene));
    const VertexGrid grid(scene.bounds());
    for (const SceneObject& object : scene.objects)
    {
        const std::uint64_t end = std::uint64_t(object.firstTriangle) + object.triangleCount;
        if (end > scene.triangles.size())
            throw std::invalid_argument("sceneGeometryFingerprint: object " + std::to_string(object.id) +
                                        " has triangles up to " + std::to_string(end) + " but the scene holds " +
                                        std::to_string(scene.triangles.size()) + " (extracted without triangles?)");
        for (std::uint64_t t = object.firstTriangle; t < end; ++t)
        {
            const Triangle& triangle = scene.triangles[t];
            for (const Vec3f* vertex : {&triangle.a, &triangle.b, &triangle.c})
                for (int axis = 0; axis < 3; ++axis)
                    hash.add(grid.cell((*vertex)[axis], axis));
        }
    }
    return hash.value();
}
} // namespace osgVis::core
