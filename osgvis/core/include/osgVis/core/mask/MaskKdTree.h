// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The kd-tree of the mask method: nodes with their 3-D boxes and object counts, the marks of the
/// time-stamp temporal coherence, and lazy updates for scenes that change during the walk.
///
/// Two ways to split: Planar (2-D, only along the two horizontal axes; a node's box still carries
/// the heights of what it holds — the paper's 2.5-D city input) and Full (3-D, all three axes).
/// Splits are at the median object centre along the node's longest splittable axis.
///
/// Time stamps: stamp(node) = the walk time until which the whole subtree is known to be hidden;
/// 0 = no knowledge. A query asks whether an object is hidden at time t: it is when the object's
/// own stamp or any ancestor's stamp is later than t. Nothing is ever unmarked explicitly: old
/// stamps simply expire.
///
/// Lazy updates: insert() drops an object into the leaf whose box is nearest its centre and
/// grows the boxes on the way up; remove() takes it out of its leaf without shrinking any box;
/// move() is remove + insert. Each of them clears the object's own stamp; insert (and so move)
/// also clears the stamps of every ancestor of the leaf it enters, pushing each stamp down to the
/// children first (and a leaf's to its other objects), so what was known about everything else is
/// kept exactly. remove needs no ancestor clearing: nothing new appears in the subtree it leaves.
/// Boxes therefore only grow until the next rebuild(), which the owner calls when
/// updatesSinceBuild() gets large.
///
/// An object that is not in the tree (left out, removed, unknown id) is never hidden(): the owner
/// must draw what the tree cannot vouch for.
#include <osgVis/core/geometry/Aabb.h>
#include <osgVis/core/scene/Scene.h>

#include <cstdint>
#include <vector>

namespace osgVis::core
{
class MaskKdTree
{
public:
    enum class Split
    {
        Planar, ///< along the two axes of largest scene extent
        Full,   ///< along x, y and z
    };
    static constexpr std::uint32_t None = ~std::uint32_t(0);

    struct Node
    {
        Aabb bounds;                       ///< holds every object below (may be loose after updates)
        std::uint32_t left = None, right = None, parent = None;
        std::uint32_t objectCount = 0;     ///< objects in the subtree
        std::vector<ObjectId> objects;     ///< leaves only
        double stamp = 0.0;                ///< hidden until this walk time (0: unknown)
        std::uint8_t axis = 0;             ///< inner nodes: the split axis (0 x, 1 y, 2 z)
        double splitPosition = 0.0;        ///< inner nodes: the median centre the split was made at
        bool leaf() const { return left == None; }
    };

    /// Objects with empty or non-finite bounds are left out (the owner must keep them visible), and
    /// so are those with present[id] == false; ids beyond present.size() count as present.
    void build(const std::vector<Aabb>& objectBounds, const std::vector<bool>& present, Split split,
               std::uint32_t maxLeafObjects = 4);
    /// Rebuild from the current contents (after many lazy updates).
    void rebuild();

    bool empty() const { return _nodes.empty(); }
    const std::vector<Node>& nodes() const { return _nodes; }
    const Node& node(std::uint32_t i) const { return _nodes[i]; }
    std::uint32_t root() const { return 0; }
    Split split() const { return _split; }
    /// The axes a node may be split along: the first splitAxisCount() entries of splitAxes()
    /// (Planar: the two of largest scene extent, Full: x, y, z).
    const int* splitAxes() const { return _axes; }
    int splitAxisCount() const { return _axisCount; }
    /// The leaf holding `id`, or None (left out / removed / unknown id).
    std::uint32_t leafOf(ObjectId id) const;
    bool contains(ObjectId id) const { return leafOf(id) != None; }

    /// insert of an id already in the tree moves it; empty or non-finite bounds leave it out.
    /// Calls visit(id) for every object in the subtree of `node`.
    template <class Visit>
    void forEachObjectBelow(std::uint32_t node, Visit&& visit) const
    {
        const Node& n = _nodes[node];
        if (!n.leaf())
        {
            forEachObjectBelow(n.left, visit);
            forEachObjectBelow(n.right, visit);
            return;
        }
        for (ObjectId id : n.objects)
            visit(id);
    }

    void insert(ObjectId id, const Aabb& bounds);
    void remove(ObjectId id);
    void move(ObjectId id, const Aabb& bounds);
    std::uint32_t updatesSinceBuild() const { return _updates; }

    /// Marks. markNode: the whole subtree is hidden until `until`; markObject: one object is.
    void markNode(std::uint32_t node, double until);
    void markObject(ObjectId id, double until);
    /// True when the object's own stamp or a stamp on its leaf or any ancestor is later than `time`.
    bool hidden(ObjectId id, double time) const;
    double objectStamp(ObjectId id) const { return id < _objectStamp.size() ? _objectStamp[id] : 0.0; }
    /// Forget every mark (e.g. after the view direction changed sharply and the marks are kept but
    /// a new critical frame recomputes them anyway, or after a rebuild).
    void clearMarks();

private:
    std::uint32_t buildNode(std::vector<ObjectId>& ids, std::size_t first, std::size_t count, std::uint32_t parent);
    bool splitNode(std::uint32_t node, std::vector<ObjectId>& ids, std::size_t first, std::size_t count);
    void chooseSplitAxes(const Aabb& sceneBounds);
    void clearStampsUpFrom(std::uint32_t node);
    void growUpFrom(std::uint32_t node, const Aabb& bounds);
    void ensureObject(ObjectId id);
    void detach(ObjectId id);
    void attach(ObjectId id, const Aabb& bounds);

    Split _split = Split::Full;
    int _axes[3] = {0, 1, 2};
    int _axisCount = 3;
    std::uint32_t _maxLeafObjects = 4;
    std::uint32_t _updates = 0;
    std::vector<Node> _nodes;
    std::vector<Aabb> _objectBounds;
    std::vector<std::uint32_t> _leafOf;
    std::vector<double> _objectStamp;
};
} // namespace osgVis::core
