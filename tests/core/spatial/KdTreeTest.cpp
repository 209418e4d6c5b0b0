// SPDX-License-Identifier: MIT
#include <osgVis/core/spatial/KdTree.h>

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>

using namespace osgVis::core;

namespace
{
std::vector<Aabb> randomBoxes(std::size_t n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> position(-100.0, 100.0);
    std::uniform_real_distribution<double> size(0.1, 5.0);
    std::vector<Aabb> boxes;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3 lo(position(rng), position(rng), position(rng));
        boxes.emplace_back(lo, lo + Vec3(size(rng), size(rng), size(rng)));
    }
    return boxes;
}

bool encloses(const Aabb& outer, const Aabb& inner)
{
    return outer.contains(inner.min) && outer.contains(inner.max);
}

// A row of unit boxes along x: box i is centred at (3i, 0, 0).
std::vector<Aabb> row(int n)
{
    std::vector<Aabb> boxes;
    for (int i = 0; i < n; ++i)
        boxes.emplace_back(Vec3(3.0 * i - 0.5, -0.5, -0.5), Vec3(3.0 * i + 0.5, 0.5, 0.5));
    return boxes;
}

std::vector<std::uint32_t> leafOrder(const KdTree& tree, const Vec3& eye)
{
    std::vector<std::uint32_t> order;
    tree.traverseFrontToBack(eye, [&](std::uint32_t index) {
        const KdTree::Node& node = tree.nodes()[index];
        if (node.leaf())
        {
            for (std::uint32_t i = node.firstItem; i < node.firstItem + node.itemCount; ++i)
                order.push_back(tree.items()[i]);
        }
        return true;
    });
    return order;
}
} // namespace

TEST(KdTree, EveryItemExactlyOnceAndBoundsTight)
{
    std::vector<Aabb> boxes = randomBoxes(500, 7);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    boxes.push_back(Aabb());                           // empty: left out
    boxes.push_back(Aabb(Vec3(nan), Vec3(1.0)));       // non-finite: left out
    boxes.push_back(Aabb(Vec3(0.0), Vec3(std::numeric_limits<double>::infinity())));
    KdTree tree;
    tree.build(boxes, 4);
    ASSERT_FALSE(tree.empty());

    std::vector<std::uint32_t> items = tree.items();
    std::sort(items.begin(), items.end());
    std::vector<std::uint32_t> expected(500);
    for (std::uint32_t i = 0; i < 500; ++i)
        expected[i] = i;
    EXPECT_EQ(items, expected);

    std::vector<int> seenInLeaves(500, 0);
    for (const KdTree::Node& node : tree.nodes())
    {
        Aabb tight;
        for (std::uint32_t i = node.firstItem; i < node.firstItem + node.itemCount; ++i)
            tight.expand(boxes[tree.items()[i]]);
        EXPECT_EQ(node.bounds.min, tight.min);
        EXPECT_EQ(node.bounds.max, tight.max);
        if (node.leaf())
        {
            EXPECT_LE(node.itemCount, 4u);
            for (std::uint32_t i = node.firstItem; i < node.firstItem + node.itemCount; ++i)
                ++seenInLeaves[tree.items()[i]];
        }
        else
        {
            const KdTree::Node& left = tree.nodes()[node.left];
            const KdTree::Node& right = tree.nodes()[node.right];
            EXPECT_EQ(left.firstItem, node.firstItem);
            EXPECT_EQ(right.firstItem, left.firstItem + left.itemCount);
            EXPECT_EQ(left.itemCount + right.itemCount, node.itemCount);
            EXPECT_TRUE(encloses(node.bounds, left.bounds) && encloses(node.bounds, right.bounds));
        }
    }
    EXPECT_TRUE(std::all_of(seenInLeaves.begin(), seenInLeaves.end(), [](int n) { return n == 1; }));
}

TEST(KdTree, EmptyInputGivesEmptyTree)
{
    KdTree tree;
    tree.build({Aabb()});
    EXPECT_TRUE(tree.empty());
    int visits = 0;
    tree.traverseFrontToBack(Vec3(0.0), [&](std::uint32_t) { return ++visits, true; });
    EXPECT_EQ(visits, 0);
}

TEST(KdTree, FrontToBackAlongARow)
{
    //   eye ->  [0]  [1]  [2] ... [15]  <- eye
    KdTree tree;
    tree.build(row(16), 1);
    std::vector<std::uint32_t> ascending(16);
    for (std::uint32_t i = 0; i < 16; ++i)
        ascending[i] = i;
    EXPECT_EQ(leafOrder(tree, Vec3(-10, 0, 0)), ascending);
    std::vector<std::uint32_t> descending(ascending.rbegin(), ascending.rend());
    EXPECT_EQ(leafOrder(tree, Vec3(100, 1, 2)), descending);
}

TEST(KdTree, FrontToBackFromInsideTheRow)
{
    // Eye between box 7 (x = 21) and box 8 (x = 24): on each side, nearer boxes come first.
    KdTree tree;
    tree.build(row(16), 1);
    const std::vector<std::uint32_t> order = leafOrder(tree, Vec3(22.4, 0, 0));
    ASSERT_EQ(order.size(), 16u);
    std::vector<std::size_t> position(16);
    for (std::size_t i = 0; i < order.size(); ++i)
        position[order[i]] = i;
    for (std::uint32_t i = 0; i + 1 <= 7; ++i)
        EXPECT_LT(position[i + 1], position[i]) << "box " << i + 1 << " is in front of box " << i;
    for (std::uint32_t i = 8; i + 1 < 16; ++i)
        EXPECT_LT(position[i], position[i + 1]) << "box " << i << " is in front of box " << i + 1;
}

TEST(KdTree, VisitorCanSkipSubtrees)
{
    KdTree tree;
    tree.build(row(16), 1);
    int visits = 0;
    tree.traverseFrontToBack(Vec3(0.0), [&](std::uint32_t) { return ++visits, false; });
    EXPECT_EQ(visits, 1);
}
