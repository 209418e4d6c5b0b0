// SPDX-License-Identifier: MIT
// What HierarchyIndex finds in a renderer's hierarchy before a module trusts it: a kd-tree passes
// as disjoint with its subtree contents; overlapping siblings, a child outside its parent and an
// object outside its node make it overlapping; duplicate ids make it unusable; a walk that strays
// (another order, another structure) is refused.
#include <osgVis/core/spatial/HierarchyIndex.h>

#include <gtest/gtest.h>

using namespace osgVis::core;

namespace
{
/// A root with two children given as boxes; each child holds one object.
struct TwoChildren : TraversalHierarchy
{
    Aabb root{{0, 0, 0}, {10, 10, 10}}, low{{0, 0, 0}, {5, 10, 10}}, high{{5, 0, 0}, {10, 10, 10}};
    std::uint32_t lowId = 1, highId = 2;
    ObjectId lowObject = 0, highObject = 1;
    HierarchyLayout declared = HierarchyLayout::Disjoint;
    bool farFirst = false;

    HierarchyLayout layout() const override { return declared; }
    std::uint32_t nodeCount() const override { return 3; }
    void traverse(const Vec3& eye, HierarchyVisitor& visitor) const override
    {
        const HierarchyNode r{0, root, nullptr, 0};
        const HierarchyNode a{lowId, low, &lowObject, 1};
        const HierarchyNode b{highId, high, &highObject, 1};
        if (!visitor.enter(r))
            return;
        const bool lowFirst = (eye.x < 5.0) != farFirst;
        for (const HierarchyNode* n : {lowFirst ? &a : &b, lowFirst ? &b : &a})
            if (visitor.enter(*n))
                visitor.leave(*n);
        visitor.leave(r);
    }
};

Scene twoObjects()
{
    Scene scene;
    scene.addObject({{1, 1, 1}, {2, 2, 2}}, 12);
    scene.addObject({{6, 1, 1}, {9, 3, 2}}, 12);
    return scene;
}

/// Enters everything, following the walk; counts refusals.
struct Follower : HierarchyVisitor
{
    HierarchyIndex::Walk walk;
    int refused = 0;
    Follower(const HierarchyIndex& index, const Vec3& eye) : walk(index, eye) {}
    bool enter(const HierarchyNode& node) override
    {
        if (walk.enter(node))
            return true;
        ++refused;
        return false;
    }
    void leave(const HierarchyNode&) override { walk.leave(); }
};
} // namespace

TEST(HierarchyIndex, KdSplitIsDisjointWithTightContents)
{
    const Scene scene = twoObjects();
    TwoChildren h;
    HierarchyIndex index;
    index.build(h, scene);
    ASSERT_TRUE(index.usable()) << index.problem();
    EXPECT_EQ(index.layout(), HierarchyLayout::Disjoint);
    EXPECT_EQ(index.problem(), "");
    EXPECT_TRUE(index.holds(0) && index.holds(1));
    const HierarchyIndex::Node& root = index.node(0);
    EXPECT_EQ(root.subtreeEnd - root.firstObject, 2u);
    EXPECT_EQ(root.heldCount, 0u);
    EXPECT_EQ(root.childCount, 2u);
    EXPECT_EQ(root.contents.min, Vec3(1, 1, 1));
    EXPECT_EQ(root.contents.max, Vec3(9, 3, 2));
    EXPECT_TRUE(index.node(1).leaf());
    for (const Vec3 eye : {Vec3(-3, 5, 5), Vec3(13, 5, 5), Vec3(5, 5, 5)})
    {
        Follower follow(index, eye);
        h.traverse(eye, follow);
        EXPECT_EQ(follow.refused, 0) << eye.x;
    }
}

TEST(HierarchyIndex, WrongClaimsOfDisjointnessMakeItOverlapping)
{
    const Scene scene = twoObjects();
    struct Case
    {
        const char* problem;
        void (*spoil)(TwoChildren&);
    };
    const Case cases[] = {
        {"declared disjoint, but sibling nodes 1 and 2 overlap", [](TwoChildren& h) { h.low.max.x = 6; }},
        {"declared disjoint, but node 2 is not inside its parent 0", [](TwoChildren& h) { h.high.max.x = 11; }},
        {"declared disjoint, but object 1 is not inside node 2 that holds it", [](TwoChildren& h) { h.high.min.x = 7; }},
    };
    for (const Case& c : cases)
    {
        TwoChildren h;
        c.spoil(h);
        HierarchyIndex index;
        index.build(h, scene);
        EXPECT_TRUE(index.usable());
        EXPECT_EQ(index.layout(), HierarchyLayout::Overlapping);
        EXPECT_EQ(index.problem(), c.problem);
    }
    TwoChildren bvh;
    bvh.low.max.x = 6;
    bvh.declared = HierarchyLayout::Overlapping;
    HierarchyIndex index;
    index.build(bvh, scene);
    EXPECT_EQ(index.problem(), "") << "overlap is what an overlapping hierarchy says";
}

TEST(HierarchyIndex, DuplicateOrUnknownIdsMakeItUnusable)
{
    const Scene scene = twoObjects();
    const struct
    {
        const char* problem;
        void (*spoil)(TwoChildren&);
    } cases[] = {
        {"node id 1 is met twice (count 3)", [](TwoChildren& h) { h.highId = 1; }},
        {"node id 7 is not below the node count 3", [](TwoChildren& h) { h.highId = 7; }},
        // The check walks from the scene's centre (x = 5): the high child comes first.
        {"object 0 is held twice (node 1)", [](TwoChildren& h) { h.highObject = 0; }},
        {"object 5 does not exist (node 2)", [](TwoChildren& h) { h.highObject = 5; }},
    };
    for (const auto& c : cases)
    {
        TwoChildren h;
        c.spoil(h);
        HierarchyIndex index;
        index.build(h, scene);
        EXPECT_FALSE(index.usable());
        EXPECT_EQ(index.problem(), c.problem);
        EXPECT_FALSE(index.holds(0));
    }
}

TEST(HierarchyIndex, WalkRefusesSiblingsOutOfOrderAndAnotherStructure)
{
    const Scene scene = twoObjects();
    TwoChildren h;
    HierarchyIndex index;
    index.build(h, scene);
    h.farFirst = true;
    Follower backwards(index, {-3, 5, 5});
    h.traverse({-3, 5, 5}, backwards);
    EXPECT_EQ(backwards.refused, 1) << "the near child after the far one";

    // An eye on the split plane: no ray from it crosses the plane, so either order holds.
    Follower onPlane(index, {5, 5, 5});
    h.traverse({5, 5, 5}, onPlane);
    EXPECT_EQ(onPlane.refused, 0);

    TwoChildren moved;
    moved.high.max.z = 9; // another region than the one recorded
    Follower other(index, {-3, 5, 5});
    moved.traverse({-3, 5, 5}, other);
    EXPECT_EQ(other.refused, 1);
}
