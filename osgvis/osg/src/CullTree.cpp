// SPDX-License-Identifier: MIT
// The cull tree of an extraction (CullTree.h): built from the objects' paths, once per extraction.
#include "CullTree.h"

#include "Extraction.h"

#include <unordered_map>

namespace osgVis
{
namespace
{
struct ChildKey
{
    std::uint32_t parent;
    const osg::Node* node;
    bool operator==(const ChildKey& other) const { return parent == other.parent && node == other.node; }
};

struct ChildKeyHash
{
    std::size_t operator()(const ChildKey& key) const
    {
        return std::hash<const void*>()(key.node) ^ (std::size_t(key.parent) * 0x9e3779b97f4a7c15ull);
    }
};

// Whether `node`'s subtree draws nothing but its objects; memoized, as subtrees may be shared.
bool closedSubtree(const osg::Node& node, std::unordered_map<const osg::Node*, bool>& memo)
{
    if (const osg::Drawable* drawable = node.asDrawable())
        return plainCullCallback(*drawable);
    const auto found = memo.find(&node);
    if (found != memo.end())
        return found->second;
    bool closed = plainNodeType(node) && !node.getCullCallback();
    if (const osg::Group* group = node.asGroup(); closed && group)
        for (unsigned i = 0; closed && i < group->getNumChildren(); ++i)
            closed = group->getChild(i)->getNodeMask() != 0 && closedSubtree(*group->getChild(i), memo);
    memo.emplace(&node, closed);
    return closed;
}

// Appends `ids` (ascending) to tree.runs as runs of consecutive ids.
void appendRuns(CullTree& tree, CullTree::Node& node, const std::vector<core::ObjectId>& ids)
{
    node.firstRun = static_cast<std::uint32_t>(tree.runs.size());
    for (core::ObjectId id : ids)
        if (tree.runs.size() > node.firstRun && tree.runs.back().second == id)
            ++tree.runs.back().second;
        else
            tree.runs.push_back({id, id + 1});
    node.runCount = static_cast<std::uint32_t>(tree.runs.size()) - node.firstRun;
    node.idCount = static_cast<std::uint32_t>(ids.size());
}
} // namespace

bool enterableNode(const osg::Node& node)
{
    return node.asGroup() && plainNodeType(node) && !node.getCullCallback();
}

std::shared_ptr<const CullTree> buildCullTree(const ExtractedScene& scene, const osg::Node& root)
{
    auto tree = std::make_shared<CullTree>();
    tree->nodes.push_back({});
    tree->nodes[0].node = &root;
    std::vector<std::vector<core::ObjectId>> ids(1);
    std::unordered_map<ChildKey, std::uint32_t, ChildKeyHash> index;
    for (core::ObjectId id = 0; id < scene.refs.size(); ++id)
    {
        if (scene.removed(id))
            continue;
        const osg::NodePath& path = scene.refs[id].path;
        std::uint32_t at = 0;
        ids[0].push_back(id);
        // note: the tree ends at a node the walk cannot enter; the ids below it still count for the
        // nodes above (a node holding such a node is never closed, so they only decide "all visible")
        for (std::size_t depth = 1; depth < path.size() && (depth == 1 || enterableNode(*path[depth - 1])); ++depth)
        {
            const auto [entry, added] = index.try_emplace({at, path[depth]}, std::uint32_t(tree->nodes.size()));
            if (added)
            {
                tree->nodes.push_back({});
                tree->nodes.back().node = path[depth];
                ids.emplace_back();
            }
            at = entry->second;
            ids[at].push_back(id);
        }
    }
    std::unordered_map<const osg::Node*, bool> closed;
    for (std::uint32_t n = 0; n < tree->nodes.size(); ++n)
    {
        CullTree::Node& node = tree->nodes[n];
        appendRuns(*tree, node, ids[n]);
        node.closed = closedSubtree(*node.node, closed);
        node.enterable = enterableNode(*node.node);
        // note: the root's children are listed whatever its kind: the group that culls them is the root
        const osg::Group* group = node.enterable || n == 0 ? node.node->asGroup() : nullptr;
        if (!group)
            continue;
        node.firstChild = static_cast<std::uint32_t>(tree->children.size());
        node.childCount = group->getNumChildren();
        for (unsigned i = 0; i < group->getNumChildren(); ++i)
        {
            const auto child = index.find({n, group->getChild(i)});
            tree->children.push_back(child == index.end() ? CullTree::None : child->second);
        }
    }
    return tree;
}
} // namespace osgVis
