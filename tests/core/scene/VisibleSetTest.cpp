// SPDX-License-Identifier: MIT
#include <osgVis/core/scene/VisibleSet.h>

#include <gtest/gtest.h>

using namespace osgVis::core;

TEST(VisibleSet, ResetAllVisibleAtWordBoundaries)
{
    for (std::size_t n : {0u, 1u, 63u, 64u, 65u, 130u})
    {
        VisibleSet s(n, true);
        EXPECT_EQ(s.capacity(), n);
        EXPECT_EQ(s.count(), n);
        const std::vector<ObjectId> ids = s.ids();
        ASSERT_EQ(ids.size(), n);
        for (std::size_t i = 0; i < n; ++i)
            EXPECT_EQ(ids[i], i);
        EXPECT_FALSE(s.test(static_cast<ObjectId>(n))); // past the end
        EXPECT_EQ(VisibleSet(n, false).count(), 0u);
    }
}

TEST(VisibleSet, SetClearTest)
{
    VisibleSet s(100);
    s.set(3);
    s.set(64);
    s.set(99);
    s.set(64);
    EXPECT_EQ(s.ids(), (std::vector<ObjectId>{3, 64, 99}));
    s.clear(64);
    s.clear(5);
    EXPECT_TRUE(s.test(3));
    EXPECT_FALSE(s.test(64));
    EXPECT_EQ(s.count(), 2u);
    EXPECT_FALSE(s.test(InvalidObject));
}

TEST(VisibleSet, IntersectAndCompare)
{
    VisibleSet a(70), b(70);
    for (ObjectId i : {1u, 2u, 65u, 69u})
        a.set(i);
    for (ObjectId i : {2u, 3u, 69u})
        b.set(i);
    a.intersectWith(b);
    EXPECT_EQ(a.ids(), (std::vector<ObjectId>{2, 69}));

    VisibleSet c(70);
    c.set(2);
    c.set(69);
    EXPECT_TRUE(a == c);
    c.clear(2);
    EXPECT_FALSE(a == c);
    EXPECT_FALSE(VisibleSet(70) == VisibleSet(71));

    // A cleared-then-reset set equals a fresh one: no stale bits survive reset.
    c.reset(70, true);
    EXPECT_TRUE(c == VisibleSet(70, true));
}
