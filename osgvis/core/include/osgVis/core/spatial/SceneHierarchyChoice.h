// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// What the modules that can walk a renderer's hierarchy (octree, mask, cdt; visibility API, Luka
/// §3.3) decide at setScene, written once so they agree: the renderer's hierarchy is walked when
/// the module's options allow it and it passes HierarchyIndex's checks, else the module builds its
/// own tree; problem() keeps the reason either way. During a cull, traverse() pairs the traversal's
/// enters and leaves with HierarchyIndex::Walk, whose buffers are kept from cull to cull.
#include <osgVis/core/spatial/HierarchyIndex.h>

#include <cstddef>
#include <memory>
#include <string>

namespace osgVis::core
{
class SceneHierarchyChoice
{
public:
    /// `orderedWalk` false: walk() accepts siblings in any order (a module that judges each box
    /// on its own); true: it refuses Disjoint siblings out of front-to-back order (cdt).
    explicit SceneHierarchyChoice(bool orderedWalk) : _walk(_index, Vec3(0.0), orderedWalk) {}
    // _walk refers to _index: neither may move.
    SceneHierarchyChoice(const SceneHierarchyChoice&) = delete;
    SceneHierarchyChoice& operator=(const SceneHierarchyChoice&) = delete;

    /// Takes scene.hierarchy when `wanted` and usable; the problem is kept also when it is taken
    /// (walked as Overlapping although declared Disjoint). Not taken: the module builds its own tree.
    void choose(const Scene& scene, bool wanted);
    /// Indexes the module's own tree in place of the renderer's (cdt walks both through the index);
    /// walks() and problem() stay as choose() left them.
    void indexOwnTree(const TraversalHierarchy& own, const Scene& scene) { _index.build(own, scene); }

    /// True when the renderer's hierarchy was taken.
    bool walks() const { return _hierarchy != nullptr; }
    /// The renderer's hierarchy when taken, else nullptr.
    const TraversalHierarchy* hierarchy() const { return _hierarchy.get(); }
    const HierarchyIndex& index() const { return _index; }
    /// Why the renderer's hierarchy was not taken or is walked as Overlapping ("" when neither).
    const std::string& problem() const { return _problem; }

    /// The walk over index(), restarted at `eye` (a warm walk allocates nothing).
    HierarchyIndex::Walk& walk(const Vec3& eye)
    {
        _walk.restart(eye);
        return _walk;
    }

    /// Runs the renderer's traversal from `eye` (walks() must be true). onNode(node, recorded, depth)
    /// is called for every node the walk accepts and returns whether to go below it; onStray() for
    /// every node it refuses, whose subtree is then skipped. Each accepted node is left once.
    template <class OnNode, class OnStray> void traverse(const Vec3& eye, OnNode&& onNode, OnStray&& onStray)
    {
        HierarchyIndex::Walk& w = walk(eye);
        auto enter = [&](const HierarchyNode& node) -> bool
        {
            const HierarchyIndex::Node* found = w.enter(node);
            if (!found)
            {
                onStray();
                return false;
            }
            if (onNode(node, *found, w.depth() - 1))
                return true;
            w.leave(); // its children are skipped: the traversal calls no leave for it
            return false;
        };
        auto leave = [&](const HierarchyNode&) { w.leave(); };
        LambdaVisitor<decltype(enter), decltype(leave)> visitor(enter, leave);
        _hierarchy->traverse(eye, visitor);
    }

private:
    std::shared_ptr<const TraversalHierarchy> _hierarchy; ///< kept alive while walked
    HierarchyIndex _index;
    std::string _problem;
    HierarchyIndex::Walk _walk; ///< over _index (declared after it)
};
} // namespace osgVis::core
