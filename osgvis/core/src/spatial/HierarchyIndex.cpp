// SPDX-License-Identifier: MIT
// Checks a renderer's hierarchy before a module walks it (visibility API, Luka §3.3: "ordered
// traversal by callback"); docs/visapi.md says what is checked and why each check is needed.
#include <osgVis/core/spatial/HierarchyIndex.h>

#include <algorithm>
#include <sstream>

namespace osgVis::core
{
namespace
{
bool inside(const Aabb& inner, const Aabb& outer)
{
    return outer.contains(inner.min) && outer.contains(inner.max);
}

// Interiors overlap (touching faces are fine: a kd split plane is shared by both sides).
bool overlapInside(const Aabb& a, const Aabb& b)
{
    for (int k = 0; k < 3; ++k)
        if (!(a.min[k] < b.max[k] && b.min[k] < a.max[k]))
            return false;
    return true;
}

// `earlier` lies in front of `later` for every ray from the eye: some axis plane separates them
// with the eye on earlier's side (a ray is monotonic along that axis, so it meets earlier first).
bool frontToBack(const Aabb& earlier, const Aabb& later, const Vec3& eye)
{
    for (int k = 0; k < 3; ++k)
    {
        if (earlier.max[k] <= later.min[k] && eye[k] <= later.min[k])
            return true;
        if (earlier.min[k] >= later.max[k] && eye[k] >= later.max[k])
            return true;
    }
    return false;
}

struct Recorder : HierarchyVisitor
{
    HierarchyIndex::Node* nodes;
    std::uint32_t nodeCount;
    const Scene& scene;
    std::vector<ObjectId>& objects;
    std::vector<bool>& held;
    std::vector<std::uint32_t>& declared;
    std::vector<std::uint32_t>& parents;
    std::vector<std::uint32_t> stack;
    std::vector<std::uint32_t> order; // node ids as entered
    std::string unusable, notDisjoint;
    bool disjoint;

    Recorder(HierarchyIndex::Node* n, std::uint32_t count, const Scene& s, std::vector<ObjectId>& o, std::vector<bool>& h,
             std::vector<std::uint32_t>& d, std::vector<std::uint32_t>& p, bool dis)
        : nodes(n), nodeCount(count), scene(s), objects(o), held(h), declared(d), parents(p), disjoint(dis)
    {
    }

    void fail(std::string& where, const std::string& why)
    {
        if (where.empty())
            where = why;
    }

    bool enter(const HierarchyNode& node) override
    {
        std::ostringstream why;
        if (node.id >= nodeCount || nodes[node.id].recorded)
        {
            why << "node id " << node.id << (node.id >= nodeCount ? " is not below the node count " : " is met twice (count ")
                << nodeCount << (node.id >= nodeCount ? "" : ")");
            fail(unusable, why.str());
            return false;
        }
        if (node.region.empty() || !node.region.finite() || (node.objectCount > 0 && !node.objects))
        {
            why << "node " << node.id << " has an empty or non-finite region, or no object array";
            fail(unusable, why.str());
            return false;
        }
        HierarchyIndex::Node& n = nodes[node.id];
        n.recorded = true;
        order.push_back(node.id);
        n.region = node.region;
        n.firstObject = std::uint32_t(objects.size());
        declared[node.id] = std::uint32_t(node.objectCount);
        parents[node.id] = stack.empty() ? HierarchyIndex::None : stack.back();
        if (!stack.empty())
        {
            HierarchyIndex::Node& parent = nodes[stack.back()];
            ++parent.childCount;
            if (disjoint && !inside(node.region, parent.region))
            {
                why << "node " << node.id << " is not inside its parent " << stack.back();
                fail(notDisjoint, why.str());
            }
        }
        for (std::size_t i = 0; i < node.objectCount; ++i)
        {
            const ObjectId id = node.objects[i];
            if (id >= scene.objects.size() || held[id])
            {
                why << "object " << id << (id >= scene.objects.size() ? " does not exist" : " is held twice")
                    << " (node " << node.id << ")";
                fail(unusable, why.str());
                continue;
            }
            const SceneObject& object = scene.objects[id];
            // Objects no module may cull stay outside the index: nothing clears them.
            if (object.bounds.empty() || !object.bounds.finite() || (object.flags & OBJECT_ALWAYS_VISIBLE))
                continue;
            if (disjoint && !inside(object.bounds, node.region))
            {
                why << "object " << id << " is not inside node " << node.id << " that holds it";
                fail(notDisjoint, why.str());
            }
            held[id] = true;
            objects.push_back(id);
        }
        n.heldCount = std::uint32_t(objects.size()) - n.firstObject;
        stack.push_back(node.id);
        return true;
    }

    void leave(const HierarchyNode&) override
    {
        HierarchyIndex::Node& n = nodes[stack.back()];
        n.subtreeEnd = std::uint32_t(objects.size());
        for (std::uint32_t i = n.firstObject; i < n.subtreeEnd; ++i)
            n.contents.expand(scene.objects[objects[i]].bounds);
        stack.pop_back();
    }
};
} // namespace

void HierarchyIndex::build(const TraversalHierarchy& hierarchy, const Scene& scene)
{
    const std::uint32_t count = hierarchy.nodeCount();
    _nodes.assign(count, Node{});
    _objects.clear();
    _held.assign(scene.objects.size(), false);
    _declared.assign(count, 0);
    _parents.assign(count, None);
    const bool declaredDisjoint = hierarchy.layout() == HierarchyLayout::Disjoint;
    Recorder recorder(_nodes.data(), count, scene, _objects, _held, _declared, _parents, declaredDisjoint);
    const Aabb all = scene.bounds();
    hierarchy.traverse(all.empty() ? Vec3(0.0) : all.center(), recorder);
    // Children grouped by parent, each group in the order the traversal entered them.
    const std::vector<std::uint32_t>& entered = recorder.order;
    _childIds.clear();
    _roots.clear();
    std::uint32_t offset = 0;
    for (std::uint32_t id = 0; id < count; ++id)
    {
        _nodes[id].firstChild = offset;
        offset += _nodes[id].childCount;
    }
    _childIds.assign(offset, None);
    std::vector<std::uint32_t> filled(count, 0);
    for (std::uint32_t id : entered)
    {
        const std::uint32_t parent = _parents[id];
        if (parent == None)
            _roots.push_back(id);
        else
            _childIds[_nodes[parent].firstChild + filled[parent]++] = id;
    }
    if (declaredDisjoint && recorder.unusable.empty())
    {
        // Siblings of one parent may not overlap.
        for (std::uint32_t p = 0; p < count && recorder.notDisjoint.empty(); ++p)
        {
            const std::uint32_t* children = _childIds.data() + _nodes[p].firstChild;
            for (std::uint32_t i = 0; i < _nodes[p].childCount; ++i)
                for (std::uint32_t j = i + 1; j < _nodes[p].childCount; ++j)
                    if (overlapInside(_nodes[children[i]].region, _nodes[children[j]].region))
                    {
                        std::ostringstream why;
                        why << "sibling nodes " << std::min(children[i], children[j]) << " and "
                            << std::max(children[i], children[j]) << " overlap";
                        recorder.fail(recorder.notDisjoint, why.str());
                    }
        }
    }
    if (recorder.unusable.empty() && _objects.empty())
        recorder.fail(recorder.unusable, "the hierarchy holds no object the scene could cull");
    _usable = recorder.unusable.empty();
    _layout = declaredDisjoint && recorder.notDisjoint.empty() ? HierarchyLayout::Disjoint : HierarchyLayout::Overlapping;
    _problem = !_usable ? recorder.unusable
                        : (declaredDisjoint && !recorder.notDisjoint.empty() ? "declared disjoint, but " + recorder.notDisjoint : "");
    if (!_usable)
    {
        _nodes.clear();
        _objects.clear();
        _childIds.clear();
        _roots.clear();
        _held.assign(scene.objects.size(), false);
    }
}

HierarchyIndex::Walk::Walk(const HierarchyIndex& index, const Vec3& eye, bool ordered)
    : _index(index), _eye(eye), _ordered(ordered)
{
}

const HierarchyIndex::Node* HierarchyIndex::Walk::enter(const HierarchyNode& node)
{
    if (node.id >= _index._nodes.size())
        return nullptr;
    const Node& n = _index._nodes[node.id];
    const std::uint32_t parent = _stack.empty() ? None : _stack.back().id;
    if (!n.recorded || _index._parents[node.id] != parent || _index._declared[node.id] != node.objectCount ||
        node.region.min != n.region.min || node.region.max != n.region.max)
        return nullptr;
    if (!_stack.empty())
    {
        // Every later sibling lies behind every earlier one: cover drawn in an earlier one's
        // region hides the later ones without depth (docs/cdt.md).
        if (_ordered && _index._layout == HierarchyLayout::Disjoint)
            for (std::size_t i = _stack.back().enteredBegin; i < _entered.size(); ++i)
                if (!frontToBack(_index._nodes[_entered[i]].region, n.region, _eye))
                    return nullptr;
        _entered.push_back(node.id);
    }
    _stack.push_back({node.id, _entered.size()});
    return &n;
}

void HierarchyIndex::Walk::leave()
{
    if (_stack.empty())
        return;
    _entered.resize(_stack.back().enteredBegin);
    _stack.pop_back();
}
} // namespace osgVis::core
