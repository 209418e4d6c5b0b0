// SPDX-License-Identifier: MIT
#include <osgVis/core/scene/Walk.h>

#include <cstdio>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <sstream>

using namespace osgVis::core;

namespace
{
Walk parseText(const std::string& text)
{
    std::istringstream in(text);
    return Walk::parse(in, "w");
}

std::string errorOf(const std::string& text)
{
    try
    {
        parseText(text);
    }
    catch (const WalkError& e)
    {
        return e.what();
    }
    return "no error";
}

Walk sampleWalk()
{
    Walk walk;
    walk.width = 1920;
    walk.height = 1080;
    walk.projection.kind = WalkProjection::Kind::Frustum;
    walk.projection.left = -0.1 / 3.0;
    walk.projection.right = 0.07;
    walk.projection.bottom = -1e-3;
    walk.projection.top = 0.0123456789012345678;
    walk.projection.zNear = 0.1;
    walk.projection.zFar = 1234.5;
    walk.keys.push_back({0.0, {0.1, 0.2, 0.3}, {1.0 / 3.0, 2.0 / 3.0, -1e-300}, {0, 0, 1}});
    walk.keys.push_back({1.0 / 7.0, {-1e6, 3.14159265358979, 2.5e-8}, {0, 0, 0}, {0.1, 0.9, 0.3}});
    walk.keys.push_back({2.0, {5, 5, 5}, {6, 5, 5}, {0, -1, 0}});
    return walk;
}

void expectSame(const Walk& a, const Walk& b)
{
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.projection.kind, b.projection.kind);
    EXPECT_EQ(a.projection.fovY, b.projection.fovY);
    EXPECT_EQ(a.projection.left, b.projection.left);
    EXPECT_EQ(a.projection.right, b.projection.right);
    EXPECT_EQ(a.projection.bottom, b.projection.bottom);
    EXPECT_EQ(a.projection.top, b.projection.top);
    EXPECT_EQ(a.projection.zNear, b.projection.zNear);
    EXPECT_EQ(a.projection.zFar, b.projection.zFar);
    ASSERT_EQ(a.keys.size(), b.keys.size());
    for (std::size_t i = 0; i < a.keys.size(); ++i)
    {
        EXPECT_EQ(a.keys[i].time, b.keys[i].time);
        EXPECT_EQ(a.keys[i].eye, b.keys[i].eye);
        EXPECT_EQ(a.keys[i].center, b.keys[i].center);
        EXPECT_EQ(a.keys[i].up, b.keys[i].up);
    }
}

const std::string header = "osgvis-walk 1\nsize 640 480\nprojection perspective 60\nclip 0.1 100\n";
} // namespace

TEST(Walk, ParsesTheDocumentedExample)
{
    const Walk walk = parseText("osgvis-walk 1\n"
                                "# comments start with '#'\n"
                                "\n"
                                "size 1280 1024\n"
                                "projection perspective 45   # vertical field of view, degrees\n"
                                "clip 0.5 500\n"
                                "view 0.0  0 -10 2  0 0 2  0 0 1\n"
                                "view 0.5  1 -10 2  1 0 2  0 0 1\n");
    EXPECT_EQ(walk.width, 1280u);
    EXPECT_EQ(walk.height, 1024u);
    EXPECT_EQ(walk.projection.kind, WalkProjection::Kind::Perspective);
    EXPECT_EQ(walk.projection.fovY, 45.0);
    EXPECT_EQ(walk.projection.zNear, 0.5);
    EXPECT_EQ(walk.projection.zFar, 500.0);
    ASSERT_EQ(walk.keys.size(), 2u);
    EXPECT_EQ(walk.keys[1].time, 0.5);
    EXPECT_EQ(walk.keys[1].eye, Vec3(1, -10, 2));
    EXPECT_EQ(walk.keys[1].center, Vec3(1, 0, 2));
    EXPECT_EQ(walk.keys[1].up, Vec3(0, 0, 1));
}

TEST(Walk, WriteParseRoundTripIsExact)
{
    for (WalkProjection::Kind kind :
         {WalkProjection::Kind::Perspective, WalkProjection::Kind::Frustum, WalkProjection::Kind::Ortho})
    {
        Walk walk = sampleWalk();
        walk.projection.kind = kind;
        walk.projection.fovY = 100.0 / 3.0;
        std::ostringstream first;
        walk.write(first);
        const Walk back = parseText(first.str());
        if (kind == WalkProjection::Kind::Perspective)
        {
            // Perspective writes no left/right/bottom/top: compare what it stores.
            EXPECT_EQ(back.projection.fovY, walk.projection.fovY);
            walk.projection.left = back.projection.left;
            walk.projection.right = back.projection.right;
            walk.projection.bottom = back.projection.bottom;
            walk.projection.top = back.projection.top;
        }
        else
        {
            walk.projection.fovY = back.projection.fovY;
        }
        expectSame(walk, back);
        std::ostringstream second;
        back.write(second);
        EXPECT_EQ(first.str(), second.str());
    }
}

TEST(Walk, SaveAndLoad)
{
    const std::string path = testing::TempDir() + "osgvis_walk_test.walk";
    const Walk walk = sampleWalk();
    walk.save(path);
    expectSame(walk, Walk::load(path));
    std::remove(path.c_str());
}

TEST(Walk, UnreadableFilesAreReported)
{
    try
    {
        Walk::load("/nonexistent/dir/x.walk");
        FAIL() << "no exception";
    }
    catch (const WalkError& e)
    {
        EXPECT_STREQ(e.what(), "cannot open walk file '/nonexistent/dir/x.walk'");
    }
    EXPECT_THROW(sampleWalk().save("/nonexistent/dir/x.walk"), WalkError);
}

TEST(Walk, MalformedInputNamesLineAndProblem)
{
    const std::string view = "view 0  0 0 0  0 0 -1  0 1 0\n";
    const struct
    {
        std::string text, message;
    } cases[] = {
        {"", "w:1: missing header 'osgvis-walk 1'"},
        {"# only a comment\n\n", "w:2: missing header 'osgvis-walk 1'"},
        {"size 640 480\n", "w:1: missing header 'osgvis-walk 1', got 'size'"},
        {"osgvis-walk\n", "w:1: header expects 'osgvis-walk <version>'"},
        {"osgvis-walk 2\n", "w:1: unsupported walk version '2' (expected 1)"},
        {"osgvis-walk 1\nfov 60\n", "w:2: unknown keyword 'fov'"},
        {"osgvis-walk 1\nsize 640\n", "w:2: 'size' expects 2 values, got 1"},
        {"osgvis-walk 1\nsize 0 480\n", "w:2: size must be between 1 and 1000000, got 0"},
        {"osgvis-walk 1\nsize 640 4.5\n", "w:2: '4.5' is not an integer"},
        {"osgvis-walk 1\nsize 640 480\nsize 640 480\n", "w:3: duplicate 'size'"},
        {"osgvis-walk 1\nprojection fisheye 1\n",
         "w:2: unknown projection 'fisheye' (expected perspective, frustum or ortho)"},
        {"osgvis-walk 1\nprojection\n", "w:2: 'projection' expects a kind: perspective, frustum or ortho"},
        {"osgvis-walk 1\nprojection perspective\n",
         "w:2: 'projection perspective' expects 1 value (fovY degrees), got 0"},
        {"osgvis-walk 1\nprojection perspective 180\n", "w:2: perspective fovY must be in (0, 180) degrees, got 180"},
        {"osgvis-walk 1\nprojection ortho -1 1 -1\n",
         "w:2: 'projection ortho' expects 4 values (left right bottom top), got 3"},
        {"osgvis-walk 1\nprojection frustum 1 -1 -1 1\n",
         "w:2: projection frustum needs left < right and bottom < top"},
        {"osgvis-walk 1\nclip 0 100\n", "w:2: clip needs 0 < near < far, got near 0 far 100"},
        {"osgvis-walk 1\nclip 10 5\n", "w:2: clip needs 0 < near < far, got near 10 far 5"},
        {"osgvis-walk 1\nclip 0.1 abc\n", "w:2: 'abc' is not a number"},
        {"osgvis-walk 1\nclip 0.1 100x\n", "w:2: '100x' is not a number"},
        {"osgvis-walk 1\nclip 0.1 nan\n", "w:2: 'nan' is not a finite number"},
        {"osgvis-walk 1\nclip 0.1 inf\n", "w:2: 'inf' is not a finite number"},
        {"osgvis-walk 1\nclip 0.1 1e999\n", "w:2: '1e999' is not a finite number"},
        {header + "view 0  0 0 0  0 0 -1  0 1\n", "w:5: 'view' expects 10 values, got 9"},
        {header + "view 0  0 0 0  0 0 -1  0 1 0 7\n", "w:5: 'view' expects 10 values, got 11"},
        {header + "view 0  0 0 0  0 0 0  0 1 0\n", "w:5: view eye equals center"},
        {header + "view 0  0 0 0  0 0 -1  0 0 0\n", "w:5: view up vector is zero or parallel to the view direction"},
        {header + "view 0  0 0 0  0 0 -1  0 0 2\n", "w:5: view up vector is zero or parallel to the view direction"},
        {header + "view 1  0 0 0  0 0 -1  0 1 0\nview 1  0 0 0  0 0 -1  0 1 0\n",
         "w:6: view time 1 is not after the previous view time 1"},
        {header + "view 1  0 0 0  0 0 -1  0 1 0\n# gap\nview 0.5  0 0 0  0 0 -1  0 1 0\n",
         "w:7: view time 0.5 is not after the previous view time 1"},
        {header, "w:4: walk has no views"},
        {"osgvis-walk 1\nprojection perspective 60\nclip 0.1 100\n" + view, "w:4: missing 'size'"},
        {"osgvis-walk 1\nsize 640 480\nclip 0.1 100\n" + view, "w:4: missing 'projection'"},
        {"osgvis-walk 1\nsize 640 480\nprojection perspective 60\n" + view, "w:4: missing 'clip'"},
    };
    for (const auto& c : cases)
        EXPECT_EQ(errorOf(c.text), c.message) << "input:\n" << c.text;
    EXPECT_EQ(errorOf(header + view), "no error");
}

TEST(Walk, MatricesFollowGlm)
{
    Walk walk = parseText(header + "view 0  1 2 3  1 2 0  0 1 0\n");
    EXPECT_EQ(walk.aspect(), 640.0 / 480.0);
    EXPECT_EQ(walk.projection.matrix(walk.aspect()),
              glm::perspective(glm::radians(60.0), 640.0 / 480.0, 0.1, 100.0));
    walk.projection.kind = WalkProjection::Kind::Frustum;
    EXPECT_EQ(walk.projection.matrix(2.0), glm::frustum(-1.0, 1.0, -1.0, 1.0, 0.1, 100.0));
    walk.projection.kind = WalkProjection::Kind::Ortho;
    EXPECT_EQ(walk.projection.matrix(2.0), glm::ortho(-1.0, 1.0, -1.0, 1.0, 0.1, 100.0));

    // The eye maps to the origin and the look-at point onto the -z axis.
    const Mat4 view = walk.keys[0].viewMatrix();
    const Vec4 eye = view * Vec4(1, 2, 3, 1);
    const Vec4 center = view * Vec4(1, 2, 0, 1);
    EXPECT_NEAR(glm::length(Vec3(eye)), 0.0, 1e-12);
    EXPECT_NEAR(center.x, 0.0, 1e-12);
    EXPECT_NEAR(center.y, 0.0, 1e-12);
    EXPECT_NEAR(center.z, -3.0, 1e-12);
}
