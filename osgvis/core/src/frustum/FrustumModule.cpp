// SPDX-License-Identifier: MIT
// Hierarchical view-frustum culling with plane masking (Assarsson & Möller, "Optimized View Frustum
// Culling Algorithms for Bounding Boxes", 2000): a node inside a plane stops testing against it below.
#include <osgVis/core/frustum/FrustumModule.h>

namespace osgVis::core
{
void FrustumModule::setScene(const Scene& scene)
{
    _scene = &scene;
    std::vector<Aabb> boxes;
    boxes.reserve(scene.objects.size());
    for (const SceneObject& o : scene.objects)
        boxes.push_back(o.bounds);
    _tree.build(boxes);
    _changed.reset(scene.objects.size());
    _stack.clear();
    _stack.reserve(256);
}

void FrustumModule::cull(const View& view, VisibleSet& visible)
{
    if (_tree.empty())
        return;
    const std::vector<KdTree::Node>& nodes = _tree.nodes();
    const std::vector<std::uint32_t>& items = _tree.items();
    const Frustum& frustum = view.frustum;

    const auto clearRange = [&](std::uint32_t first, std::uint32_t count) {
        for (std::uint32_t i = first; i < first + count; ++i)
        {
            if (visible.test(items[i]) && !_changed.changed(items[i])) // moved: tested below
                visible.clear(items[i]);
        }
    };

    // Entries are (node index, plane mask) pairs.
    _stack.clear();
    _stack.push_back(0);
    _stack.push_back(0x3Fu);
    while (!_stack.empty())
    {
        unsigned mask = _stack.back();
        _stack.pop_back();
        const std::uint32_t index = _stack.back();
        _stack.pop_back();
        const KdTree::Node& node = nodes[index];

        const Containment c = frustum.classify(node.bounds, mask);
        if (c == Containment::Outside)
        {
            clearRange(node.firstItem, node.itemCount);
            continue;
        }
        if (c == Containment::Inside)
            continue; // every object below is kept as it came in
        if (node.leaf())
        {
            for (std::uint32_t i = node.firstItem; i < node.firstItem + node.itemCount; ++i)
            {
                const ObjectId id = items[i];
                unsigned objectMask = mask;
                if (visible.test(id) && !_changed.changed(id) && frustum.classify(_scene->objects[id].bounds, objectMask) == Containment::Outside)
                    visible.clear(id);
            }
            continue;
        }
        _stack.push_back(node.left);
        _stack.push_back(mask);
        _stack.push_back(node.right);
        _stack.push_back(mask);
    }
    for (ObjectId id : _changed.moved())
        if (visible.test(id) && frustum.classify(_scene->objects[id].bounds) == Containment::Outside)
            visible.clear(id);
}

void FrustumModule::sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes)
{
    const auto nothing = [](ObjectId) {};
    if (!_scene || !_changed.apply(scene.objects.size(), changes, nothing, nothing))
    {
        setScene(scene);
        return;
    }
    _scene = &scene;
}
} // namespace osgVis::core
