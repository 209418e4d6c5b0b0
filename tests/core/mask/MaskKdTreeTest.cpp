// SPDX-License-Identifier: MIT
#include <osgVis/core/mask/MaskKdTree.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>

using namespace osgVis::core;

namespace
{
constexpr std::uint32_t None = MaskKdTree::None;
const double notANumber = std::numeric_limits<double>::quiet_NaN();

bool usable(const Aabb& box)
{
    return !box.empty() && box.finite();
}

bool encloses(const Aabb& outer, const Aabb& inner)
{
    return outer.contains(inner.min) && outer.contains(inner.max);
}

Aabb boxAt(const Vec3& centre, double halfSize)
{
    return {centre - Vec3(halfSize), centre + Vec3(halfSize)};
}

// A city: 1000 buildings on a 1000 x 1000 footprint (x, y), heights 0..80 along `up`.
std::vector<Aabb> city(unsigned seed, int up)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ground(0.0, 980.0);
    std::uniform_real_distribution<double> side(5.0, 20.0);
    std::uniform_real_distribution<double> height(0.0, 80.0);
    const int across[2] = {up == 0 ? 1 : 0, up == 2 ? 1 : 2};
    std::vector<Aabb> boxes;
    for (int i = 0; i < 1000; ++i)
    {
        Vec3 lo(0.0), hi(0.0);
        lo[across[0]] = ground(rng);
        lo[across[1]] = ground(rng);
        hi[across[0]] = lo[across[0]] + side(rng);
        hi[across[1]] = lo[across[1]] + side(rng);
        hi[up] = height(rng);
        boxes.emplace_back(lo, hi);
    }
    return boxes;
}

// Unit boxes on an n x n grid in the z = 0 plane, 3 apart: the children of every node have
// disjoint boxes, so an object inserted at a box's place lands where that box is.
std::vector<Aabb> grid(int n)
{
    std::vector<Aabb> boxes;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            boxes.push_back(boxAt(Vec3(3.0 * i, 3.0 * j, 0.0), 0.5));
    return boxes;
}

std::vector<ObjectId> objectsBelow(const MaskKdTree& tree, std::uint32_t index)
{
    std::vector<ObjectId> ids;
    std::vector<std::uint32_t> stack{index};
    while (!stack.empty())
    {
        const MaskKdTree::Node& node = tree.node(stack.back());
        stack.pop_back();
        if (node.leaf())
            ids.insert(ids.end(), node.objects.begin(), node.objects.end());
        else
        {
            stack.push_back(node.left);
            stack.push_back(node.right);
        }
    }
    std::sort(ids.begin(), ids.end());
    return ids;
}

bool isBelow(const MaskKdTree& tree, std::uint32_t node, ObjectId id)
{
    for (std::uint32_t n = tree.leafOf(id); n != None; n = tree.node(n).parent)
    {
        if (n == node)
            return true;
    }
    return false;
}

std::uint32_t depth(const MaskKdTree& tree, std::uint32_t node)
{
    std::uint32_t d = 0;
    for (std::uint32_t n = tree.node(node).parent; n != None; n = tree.node(n).parent)
        ++d;
    return d;
}

// The first inner node at `wantedDepth` (depth-first, left first).
std::uint32_t innerNodeAtDepth(const MaskKdTree& tree, std::uint32_t wantedDepth)
{
    for (std::uint32_t i = 0; i < tree.nodes().size(); ++i)
    {
        if (!tree.node(i).leaf() && depth(tree, i) == wantedDepth)
            return i;
    }
    return None;
}

// Every structural invariant, against the caller's record of which objects are in and where
// they are now (`bounds[id]`, `present[id]`). Returns the broken ones, one a line.
std::string brokenInvariants(const MaskKdTree& tree, const std::vector<Aabb>& bounds, const std::vector<bool>& present)
{
    std::ostringstream out;
    std::size_t expected = 0;
    for (std::size_t id = 0; id < bounds.size(); ++id)
        expected += present[id] && usable(bounds[id]);
    if (tree.empty())
    {
        if (expected != 0)
            out << "empty tree, " << expected << " objects expected\n";
        return out.str();
    }
    if (tree.node(tree.root()).parent != None)
        out << "root has a parent\n";

    std::vector<int> seen(bounds.size(), 0);
    std::vector<bool> reached(tree.nodes().size(), false);
    std::vector<std::uint32_t> stack{tree.root()};
    while (!stack.empty())
    {
        const std::uint32_t index = stack.back();
        stack.pop_back();
        if (reached[index])
            out << "node " << index << " reached twice\n";
        reached[index] = true;
        const MaskKdTree::Node& node = tree.node(index);
        if (node.leaf())
        {
            if (node.right != None)
                out << "leaf " << index << " has a right child\n";
            if (node.objectCount != node.objects.size())
                out << "leaf " << index << " count " << node.objectCount << " != " << node.objects.size() << "\n";
            for (const ObjectId id : node.objects)
            {
                if (id >= bounds.size() || !present[id])
                {
                    out << "absent object " << id << " in leaf " << index << "\n";
                    continue;
                }
                ++seen[id];
                if (tree.leafOf(id) != index)
                    out << "leafOf(" << id << ") = " << tree.leafOf(id) << ", held by " << index << "\n";
                for (std::uint32_t n = index; n != None; n = tree.node(n).parent)
                {
                    if (!encloses(tree.node(n).bounds, bounds[id]))
                        out << "node " << n << " does not contain object " << id << "\n";
                }
            }
            continue;
        }
        if (!node.objects.empty())
            out << "inner node " << index << " holds objects\n";
        for (const std::uint32_t child : {node.left, node.right})
        {
            if (child >= tree.nodes().size())
            {
                out << "node " << index << " has a bad child\n";
                continue;
            }
            if (tree.node(child).parent != index)
                out << "child " << child << " does not name parent " << index << "\n";
            if (!tree.node(child).bounds.empty() && !encloses(node.bounds, tree.node(child).bounds))
                out << "node " << index << " does not contain child " << child << "\n";
            stack.push_back(child);
        }
        if (node.left < tree.nodes().size() && node.right < tree.nodes().size() &&
            node.objectCount != tree.node(node.left).objectCount + tree.node(node.right).objectCount)
            out << "inner node " << index << " count " << node.objectCount << " is not its children's\n";
    }
    for (std::size_t i = 0; i < reached.size(); ++i)
    {
        if (!reached[i])
            out << "node " << i << " unreachable\n";
    }
    for (std::size_t id = 0; id < bounds.size(); ++id)
    {
        const int want = present[id] && usable(bounds[id]) ? 1 : 0;
        if (seen[id] != want)
            out << "object " << id << " in " << seen[id] << " leaves, expected " << want << "\n";
        if (!want && tree.contains(static_cast<ObjectId>(id)))
            out << "left-out object " << id << " contained\n";
    }
    if (tree.node(tree.root()).objectCount != expected)
        out << "root count " << tree.node(tree.root()).objectCount << " != " << expected << "\n";
    return out.str();
}

std::vector<bool> allPresent(std::size_t n)
{
    return std::vector<bool>(n, true);
}
} // namespace

TEST(MaskKdTree, PlanarNeverSplitsAlongTheUpAxis)
{
    for (const int up : {2, 1})
    {
        SCOPED_TRACE(up);
        const std::vector<Aabb> boxes = city(11, up);
        MaskKdTree tree;
        tree.build(boxes, allPresent(boxes.size()), MaskKdTree::Split::Planar, 4);
        ASSERT_EQ(tree.splitAxisCount(), 2);
        EXPECT_EQ(tree.splitAxes()[2], up);
        int inner = 0;
        for (const MaskKdTree::Node& node : tree.nodes())
        {
            if (node.leaf())
                continue;
            ++inner;
            EXPECT_NE(node.axis, up);
        }
        EXPECT_GE(inner, 1000 / 4 - 1);
        EXPECT_EQ(brokenInvariants(tree, boxes, allPresent(boxes.size())), "");
    }
}

TEST(MaskKdTree, FullSplitsATallColumnAlongZ)
{
    // 32 unit boxes stacked along z at the same (x, y).
    std::vector<Aabb> boxes;
    for (int k = 0; k < 32; ++k)
        boxes.push_back(boxAt(Vec3(0.0, 0.0, 2.0 * k), 0.5));
    MaskKdTree tree;
    tree.build(boxes, allPresent(boxes.size()), MaskKdTree::Split::Full, 4);
    EXPECT_EQ(tree.splitAxisCount(), 3);
    ASSERT_FALSE(tree.node(tree.root()).leaf());
    for (const MaskKdTree::Node& node : tree.nodes())
    {
        if (node.leaf())
        {
            EXPECT_EQ(node.objects.size(), 4u);
        }
        else
        {
            EXPECT_EQ(node.axis, 2);
        }
    }
    // The median split: the lower 16 boxes on the left, the upper 16 on the right.
    const MaskKdTree::Node& root = tree.node(tree.root());
    EXPECT_EQ(root.splitPosition, 32.0);
    std::vector<ObjectId> lower(16);
    for (ObjectId i = 0; i < 16; ++i)
        lower[i] = i;
    EXPECT_EQ(objectsBelow(tree, root.left), lower);
    EXPECT_EQ(tree.node(root.left).bounds.max.z, 30.5);
}

TEST(MaskKdTree, StopsWhenAllCentresCoincide)
{
    const std::vector<Aabb> boxes(20, boxAt(Vec3(1.0, 2.0, 3.0), 0.5));
    MaskKdTree tree;
    tree.build(boxes, allPresent(boxes.size()), MaskKdTree::Split::Full, 4);
    ASSERT_EQ(tree.nodes().size(), 1u);
    EXPECT_EQ(tree.node(0).objects.size(), 20u);
    // Planar: centres that differ only along the up axis cannot be split. Wide flat slabs stacked
    // along z (the footprint, 50 x 50, is wider than the stack is high, so z is up).
    std::vector<Aabb> slabs;
    for (int k = 0; k < 20; ++k)
        slabs.emplace_back(Vec3(0.0, 0.0, 2.0 * k), Vec3(50.0, 50.0, 2.0 * k + 1.0));
    MaskKdTree planar;
    planar.build(slabs, allPresent(slabs.size()), MaskKdTree::Split::Planar, 4);
    EXPECT_EQ(planar.nodes().size(), 1u);
    MaskKdTree full;
    full.build(slabs, allPresent(slabs.size()), MaskKdTree::Split::Full, 4);
    EXPECT_EQ(full.nodes().size(), 15u); // 20 -> 10 + 10 -> four 5s -> eight leaves of 2 or 3
}

TEST(MaskKdTree, EveryPresentObjectInExactlyOneLeafAndBoundsTight)
{
    std::vector<Aabb> boxes = city(3, 2);
    std::vector<bool> present = allPresent(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); i += 7)
        present[i] = false;
    boxes[10] = Aabb(Vec3(notANumber, 0.0, 0.0), Vec3(1.0));
    boxes[20] = Aabb();
    boxes[30] = Aabb(Vec3(0.0), Vec3(std::numeric_limits<double>::infinity()));
    MaskKdTree tree;
    tree.build(boxes, present, MaskKdTree::Split::Planar, 5);
    EXPECT_EQ(brokenInvariants(tree, boxes, present), "");
    EXPECT_EQ(tree.leafOf(7), None);
    EXPECT_EQ(tree.leafOf(10), None);
    EXPECT_EQ(tree.leafOf(20), None);
    EXPECT_EQ(tree.leafOf(30), None);
    EXPECT_EQ(tree.leafOf(5000), None);
    EXPECT_EQ(tree.node(tree.root()).objectCount, 1000u - 143u - 3u);
    // Tight at build: each node's box is exactly the union of the boxes below it.
    for (std::uint32_t i = 0; i < tree.nodes().size(); ++i)
    {
        Aabb union_;
        for (const ObjectId id : objectsBelow(tree, i))
            union_.expand(boxes[id]);
        EXPECT_EQ(tree.node(i).bounds.min, union_.min);
        EXPECT_EQ(tree.node(i).bounds.max, union_.max);
    }
    // A leaf never holds more than the limit unless all its centres coincide (they do not here).
    for (const MaskKdTree::Node& node : tree.nodes())
    {
        EXPECT_TRUE(!node.leaf() || node.objects.size() <= 5u);
    }
}

TEST(MaskKdTree, SameInputSameTree)
{
    std::vector<Aabb> boxes = city(5, 2);
    // Ties: many equal centres along x.
    for (std::size_t i = 0; i < boxes.size(); i += 3)
        boxes[i] = boxAt(Vec3(100.0, double(i), 10.0), 2.0);
    MaskKdTree a, b;
    a.build(boxes, allPresent(boxes.size()), MaskKdTree::Split::Full, 3);
    b.build(boxes, allPresent(boxes.size()), MaskKdTree::Split::Full, 3);
    ASSERT_EQ(a.nodes().size(), b.nodes().size());
    for (std::uint32_t i = 0; i < a.nodes().size(); ++i)
    {
        EXPECT_EQ(a.node(i).left, b.node(i).left);
        EXPECT_EQ(a.node(i).right, b.node(i).right);
        EXPECT_EQ(a.node(i).axis, b.node(i).axis);
        EXPECT_EQ(a.node(i).objects, b.node(i).objects);
        EXPECT_EQ(a.node(i).bounds.min, b.node(i).bounds.min);
        EXPECT_EQ(a.node(i).bounds.max, b.node(i).bounds.max);
    }
    // Centres equal to the split position are divided by id: the smaller ids go left.
    for (const MaskKdTree::Node& node : a.nodes())
    {
        if (node.leaf())
            continue;
        const auto onSplit = [&](std::uint32_t child) {
            std::vector<ObjectId> ids;
            for (const ObjectId id : objectsBelow(a, child))
            {
                if (boxes[id].center()[node.axis] == node.splitPosition)
                    ids.push_back(id);
            }
            return ids;
        };
        const std::vector<ObjectId> left = onSplit(node.left), right = onSplit(node.right);
        EXPECT_TRUE(left.empty() || right.empty() || left.back() < right.front()) << node.splitPosition;
    }
}

TEST(MaskKdTree, MarkNodeHidesExactlyTheSubtreeUntilItsTime)
{
    const std::vector<Aabb> boxes = grid(16);
    MaskKdTree tree;
    tree.build(boxes, allPresent(boxes.size()), MaskKdTree::Split::Planar, 4);
    const std::uint32_t marked = innerNodeAtDepth(tree, 2);
    ASSERT_NE(marked, None);
    tree.markNode(marked, 10.0);
    const std::vector<ObjectId> below = objectsBelow(tree, marked);
    EXPECT_EQ(below.size(), 64u);
    for (ObjectId id = 0; id < boxes.size(); ++id)
    {
        const bool isUnder = std::binary_search(below.begin(), below.end(), id);
        EXPECT_EQ(tree.hidden(id, 5.0), isUnder) << id;
        EXPECT_EQ(tree.hidden(id, 9.5), isUnder) << id;
        EXPECT_FALSE(tree.hidden(id, 10.0)) << id; // strictly later than t
        EXPECT_FALSE(tree.hidden(id, 12.0)) << id;
    }
    // An earlier mark does not shorten a later one; a single object's mark hides only it.
    tree.markNode(marked, 7.0);
    EXPECT_TRUE(tree.hidden(below[0], 9.0));
    const ObjectId outside = below.front() == 0 ? 255 : 0;
    tree.markObject(outside, 3.0);
    EXPECT_TRUE(tree.hidden(outside, 2.0));
    EXPECT_FALSE(tree.hidden(outside, 3.0));
    EXPECT_EQ(tree.objectStamp(outside), 3.0);
    tree.clearMarks();
    for (ObjectId id = 0; id < boxes.size(); ++id)
        EXPECT_FALSE(tree.hidden(id, 0.0)) << id;
}

TEST(MaskKdTree, InsertClearsOnlyTheInsertedObjectAndPushesStampsDown)
{
    std::vector<Aabb> boxes = grid(16);
    MaskKdTree tree;
    tree.build(boxes, allPresent(boxes.size()), MaskKdTree::Split::Planar, 4);
    const std::uint32_t marked = innerNodeAtDepth(tree, 1);
    tree.markNode(marked, 10.0);
    tree.markNode(tree.root(), 4.0);
    const std::vector<ObjectId> below = objectsBelow(tree, marked);
    // A new object on top of one below the marked node lands in that node's subtree.
    const ObjectId added = 256;
    const Aabb addedBox = boxAt(boxes[below[5]].center() + Vec3(0.0, 0.0, 1.0), 0.5);
    tree.insert(added, addedBox);
    boxes.push_back(addedBox);
    ASSERT_TRUE(isBelow(tree, marked, added));
    EXPECT_FALSE(tree.hidden(added, 0.0));
    for (ObjectId id = 0; id < 256; ++id)
    {
        const bool isUnder = std::binary_search(below.begin(), below.end(), id);
        EXPECT_TRUE(tree.hidden(id, 3.0)) << id;
        EXPECT_EQ(tree.hidden(id, 5.0), isUnder) << id;
        EXPECT_FALSE(tree.hidden(id, 10.0)) << id;
    }
    // The stamps on the path are cleared and live on in the siblings / leaf objects.
    for (std::uint32_t n = tree.leafOf(added); n != None; n = tree.node(n).parent)
        EXPECT_EQ(tree.node(n).stamp, 0.0) << n;
    EXPECT_EQ(tree.updatesSinceBuild(), 1u);
    EXPECT_EQ(brokenInvariants(tree, boxes, allPresent(boxes.size())), "");
}

TEST(MaskKdTree, RemoveKeepsTheOthersStateAndIgnoresUnknownIds)
{
    std::vector<Aabb> boxes = grid(8);
    MaskKdTree tree;
    tree.build(boxes, allPresent(boxes.size()), MaskKdTree::Split::Full, 4);
    const std::uint32_t marked = innerNodeAtDepth(tree, 1);
    tree.markNode(marked, 10.0);
    const std::vector<ObjectId> below = objectsBelow(tree, marked);
    const Aabb rootBefore = tree.node(tree.root()).bounds;
    tree.remove(below[0]);
    EXPECT_FALSE(tree.contains(below[0]));
    EXPECT_FALSE(tree.hidden(below[0], 0.0));
    for (ObjectId id = 0; id < boxes.size(); ++id)
    {
        if (id != below[0])
        {
            EXPECT_EQ(tree.hidden(id, 5.0), std::binary_search(below.begin(), below.end(), id)) << id;
        }
    }
    // Lazy: the boxes do not shrink.
    EXPECT_EQ(tree.node(tree.root()).bounds.min, rootBefore.min);
    EXPECT_EQ(tree.node(tree.root()).bounds.max, rootBefore.max);
    std::vector<bool> present = allPresent(boxes.size());
    present[below[0]] = false;
    EXPECT_EQ(brokenInvariants(tree, boxes, present), "");

    tree.remove(below[0]);
    tree.remove(5000);
    EXPECT_EQ(tree.updatesSinceBuild(), 1u);
    EXPECT_EQ(brokenInvariants(tree, boxes, present), "");
}

TEST(MaskKdTree, MovingOutOfAndIntoStampedSubtrees)
{
    std::vector<Aabb> boxes = grid(16);
    MaskKdTree tree;
    tree.build(boxes, allPresent(boxes.size()), MaskKdTree::Split::Planar, 4);
    const MaskKdTree::Node& root = tree.node(tree.root());
    const std::uint32_t a = root.left, b = root.right;
    tree.markNode(a, 10.0);
    tree.markNode(b, 20.0);
    const std::vector<ObjectId> inA = objectsBelow(tree, a), inB = objectsBelow(tree, b);

    // From A into B: visible at once; A's others keep 10, B's others keep 20.
    const ObjectId fromA = inA[3];
    boxes[fromA] = boxAt(boxes[inB[7]].center() + Vec3(0.0, 0.0, 1.0), 0.5);
    tree.move(fromA, boxes[fromA]);
    ASSERT_TRUE(isBelow(tree, b, fromA));
    EXPECT_FALSE(tree.hidden(fromA, 0.0));
    // From B into A, having been marked on its own too.
    const ObjectId fromB = inB[11];
    tree.markObject(fromB, 30.0);
    boxes[fromB] = boxAt(boxes[inA[9]].center() + Vec3(0.0, 0.0, 1.0), 0.5);
    tree.move(fromB, boxes[fromB]);
    ASSERT_TRUE(isBelow(tree, a, fromB));
    EXPECT_FALSE(tree.hidden(fromB, 0.0));
    EXPECT_EQ(tree.objectStamp(fromB), 0.0);
    for (const ObjectId id : inA)
    {
        if (id != fromA)
        {
            EXPECT_TRUE(tree.hidden(id, 9.0)) << id;
            EXPECT_FALSE(tree.hidden(id, 10.0)) << id;
        }
    }
    for (const ObjectId id : inB)
    {
        if (id != fromB)
        {
            EXPECT_TRUE(tree.hidden(id, 19.0)) << id;
            EXPECT_FALSE(tree.hidden(id, 20.0)) << id;
        }
    }
    // Within a stamped subtree: the mover is cleared, nothing else is.
    const ObjectId within = inA[20];
    boxes[within].max.z += 5.0;
    tree.move(within, boxes[within]);
    EXPECT_FALSE(tree.hidden(within, 0.0));
    EXPECT_TRUE(tree.hidden(inA[21], 9.0));
    EXPECT_EQ(tree.updatesSinceBuild(), 3u);
    EXPECT_EQ(brokenInvariants(tree, boxes, allPresent(boxes.size())), "");
}

TEST(MaskKdTree, RebuildKeepsContentsAndClearsMarks)
{
    std::vector<Aabb> boxes = grid(10);
    std::vector<bool> present = allPresent(boxes.size());
    MaskKdTree tree;
    tree.build(boxes, present, MaskKdTree::Split::Planar, 4);
    boxes[3].max = boxes[3].min + Vec3(40.0, 2.0, 1.0);
    tree.move(3, boxes[3]);
    tree.remove(4);
    present[4] = false;
    boxes.push_back(boxAt(Vec3(100.0, 100.0, 0.0), 1.0));
    present.push_back(true);
    tree.insert(100, boxes[100]);
    tree.markNode(tree.root(), 50.0);
    tree.markObject(7, 60.0);
    ASSERT_EQ(tree.updatesSinceBuild(), 3u);

    tree.rebuild();
    EXPECT_EQ(tree.updatesSinceBuild(), 0u);
    EXPECT_EQ(brokenInvariants(tree, boxes, present), "");
    EXPECT_FALSE(tree.contains(4));
    EXPECT_TRUE(tree.contains(100));
    Aabb union_;
    for (std::size_t id = 0; id < boxes.size(); ++id)
    {
        if (present[id])
            union_.expand(boxes[id]);
        EXPECT_FALSE(tree.hidden(static_cast<ObjectId>(id), 0.0)) << id;
    }
    EXPECT_EQ(tree.node(tree.root()).bounds.min, union_.min);
    EXPECT_EQ(tree.node(tree.root()).bounds.max, union_.max);
    EXPECT_EQ(tree.objectStamp(7), 0.0);
}

TEST(MaskKdTree, LeftOutObjectsAreNeverContainedNorHidden)
{
    std::vector<Aabb> boxes = grid(4);
    boxes[2] = Aabb(Vec3(notANumber), Vec3(notANumber));
    MaskKdTree tree;
    tree.build(boxes, allPresent(boxes.size()), MaskKdTree::Split::Full, 2);
    tree.markNode(tree.root(), 100.0);
    tree.markObject(2, 100.0);
    EXPECT_FALSE(tree.contains(2));
    EXPECT_FALSE(tree.hidden(2, 0.0));
    EXPECT_TRUE(tree.hidden(3, 0.0));

    // Inserting with NaN bounds leaves it out; moving a contained object to NaN takes it out.
    tree.insert(40, Aabb(Vec3(0.0), Vec3(notANumber, 1.0, 1.0)));
    EXPECT_FALSE(tree.contains(40));
    EXPECT_FALSE(tree.hidden(40, 0.0));
    boxes[5] = Aabb(Vec3(0.0), Vec3(1.0, notANumber, 1.0));
    tree.move(5, boxes[5]);
    EXPECT_FALSE(tree.contains(5));
    EXPECT_FALSE(tree.hidden(5, 0.0));
    boxes.resize(41);
    std::vector<bool> present(boxes.size(), false);
    std::fill(present.begin(), present.begin() + 16, true);
    EXPECT_EQ(brokenInvariants(tree, boxes, present), "");
    // After a rebuild they are still out.
    tree.rebuild();
    EXPECT_FALSE(tree.contains(2));
    EXPECT_FALSE(tree.contains(5));
    EXPECT_FALSE(tree.contains(40));
    EXPECT_EQ(brokenInvariants(tree, boxes, present), "");
}

TEST(MaskKdTree, InsertIntoAnEmptyTreeAndBeyondTheArrays)
{
    MaskKdTree tree;
    tree.build({}, {}, MaskKdTree::Split::Planar, 2);
    EXPECT_TRUE(tree.empty());
    EXPECT_FALSE(tree.hidden(0, 0.0));
    std::vector<Aabb> boxes(300);
    std::vector<bool> present(boxes.size(), false);
    // A row along x: the grown leaves split (beyond 2 x 2 objects) along x, never along z.
    for (ObjectId id = 0; id < 300; id += 10)
    {
        boxes[id] = boxAt(Vec3(2.0 * id, 0.0, 0.0), 0.5);
        present[id] = true;
        tree.insert(id, boxes[id]);
    }
    EXPECT_EQ(tree.updatesSinceBuild(), 30u);
    EXPECT_EQ(brokenInvariants(tree, boxes, present), "");
    for (const MaskKdTree::Node& node : tree.nodes())
    {
        if (node.leaf())
        {
            EXPECT_LE(node.objects.size(), 4u);
        }
        else
        {
            EXPECT_EQ(node.axis, 0);
        }
    }
    EXPECT_EQ(tree.leafOf(15), None);
    EXPECT_EQ(tree.leafOf(1000), None);
}

// 10 000 random operations against a brute-force model: the model's hidden-until per object is
// the latest mark made while the object sat under the marked node (or on itself) since it last
// entered the tree. The push-down keeps that exact, so hidden() must equal the model, and in
// particular never says hidden for an object inserted or moved after its last mark.
class MaskKdTreeRandom : public ::testing::TestWithParam<MaskKdTree::Split>
{
};

TEST_P(MaskKdTreeRandom, OperationsMatchABruteForceModel)
{
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> place(0.0, 200.0);
    std::uniform_real_distribution<double> size(0.2, 6.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto randomBox = [&]() {
        if (unit(rng) < 0.02)
            return Aabb(Vec3(notANumber), Vec3(1.0));
        const Vec3 lo(place(rng), place(rng), 0.2 * place(rng));
        return Aabb(lo, lo + Vec3(size(rng), size(rng), size(rng)));
    };

    const std::uint32_t idSpace = 400;
    std::vector<Aabb> bounds(250);
    std::vector<bool> present(250);
    for (std::size_t id = 0; id < bounds.size(); ++id)
    {
        bounds[id] = randomBox();
        present[id] = unit(rng) < 0.8;
    }
    MaskKdTree tree;
    tree.build(bounds, present, GetParam(), 4);
    bounds.resize(idSpace);
    present.resize(idSpace, false);
    std::vector<double> until(idSpace, 0.0);
    const auto inTree = [&](ObjectId id) { return present[id] && usable(bounds[id]); };

    double now = 0.0;
    int mismatches = 0;
    int hiddenAnswers = 0; // the model said hidden: the run did exercise the marks
    for (int step = 0; step < 10000; ++step)
    {
        now += 0.01;
        const auto id = static_cast<ObjectId>(rng() % idSpace);
        const double op = unit(rng);
        if (op < 0.25)
        {
            bounds[id] = randomBox();
            present[id] = true;
            until[id] = 0.0;
            if (unit(rng) < 0.5)
                tree.insert(id, bounds[id]);
            else
                tree.move(id, bounds[id]);
        }
        else if (op < 0.35)
        {
            present[id] = false;
            until[id] = 0.0;
            tree.remove(id);
        }
        else if (op < 0.75 && !tree.empty())
        {
            const auto node = static_cast<std::uint32_t>(rng() % tree.nodes().size());
            const double stamp = now + 2.0 * unit(rng);
            tree.markNode(node, stamp);
            for (const ObjectId below : objectsBelow(tree, node))
                until[below] = std::max(until[below], stamp);
        }
        else if (op < 0.9)
        {
            const double stamp = now + 2.0 * unit(rng);
            tree.markObject(id, stamp);
            if (inTree(id))
                until[id] = std::max(until[id], stamp);
        }
        else if (op < 0.901)
        {
            tree.rebuild();
            std::fill(until.begin(), until.end(), 0.0);
        }
        ASSERT_EQ(tree.contains(id), inTree(id)) << "step " << step;
        const bool expected = inTree(id) && until[id] > now;
        mismatches += tree.hidden(id, now) != expected;
        hiddenAnswers += expected;
        if (step % 250 == 0)
        {
            for (ObjectId other = 0; other < idSpace; ++other)
            {
                const bool expected = inTree(other) && until[other] > now;
                if (tree.hidden(other, now) != expected)
                {
                    ++mismatches;
                    ADD_FAILURE() << "step " << step << " object " << other << " hidden " << !expected;
                }
            }
            ASSERT_EQ(brokenInvariants(tree, bounds, present), "") << "step " << step;
        }
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(hiddenAnswers, 1000);
    EXPECT_EQ(brokenInvariants(tree, bounds, present), "");
}

INSTANTIATE_TEST_SUITE_P(MaskKdTree, MaskKdTreeRandom,
                         ::testing::Values(MaskKdTree::Split::Planar, MaskKdTree::Split::Full),
                         [](const ::testing::TestParamInfo<MaskKdTree::Split>& info) {
                             return info.param == MaskKdTree::Split::Planar ? "Planar" : "Full";
                         });
