// SPDX-License-Identifier: MIT
#include <osgVis/core/scene/Scene.h>

#include <algorithm>

namespace osgVis::core
{
Aabb Scene::bounds() const
{
    Aabb result;
    for (const SceneObject& o : objects)
    {
        if (o.bounds.finite())
            result.expand(o.bounds);
    }
    return result;
}

std::pair<std::size_t, std::size_t> Scene::trianglesOf(const SceneObject& object) const
{
    const std::size_t first = std::min<std::size_t>(object.firstTriangle, triangles.size());
    const std::size_t end = std::min<std::size_t>(first + object.triangleCount, triangles.size());
    return {first, end};
}

std::uint64_t Scene::totalTriangles() const
{
    std::uint64_t total = 0;
    for (const SceneObject& o : objects)
        total += o.triangleCount;
    return total;
}

ObjectId Scene::addObject(const Aabb& bounds, std::uint32_t triangleCount, std::uint32_t flags, std::string name)
{
    SceneObject o;
    o.id = static_cast<ObjectId>(objects.size());
    o.bounds = bounds;
    o.triangleCount = triangleCount;
    o.flags = flags;
    o.name = std::move(name);
    objects.push_back(std::move(o));
    return objects.back().id;
}
} // namespace osgVis::core
