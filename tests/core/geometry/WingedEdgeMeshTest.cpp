// SPDX-License-Identifier: MIT
// Winged-edge data from a renderer is untrusted: a closed cube gives its silhouettes (a square
// face-on, a hexagon from a corner); open, flipped, non-manifold and broken index lists are named
// and give no silhouette at all.
#include <osgVis/core/geometry/WingedEdgeMesh.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace osgVis::core;

namespace
{
// Unit cube [0,1]^3: vertex i has x = bit 0, y = bit 1, z = bit 2; 12 triangles CCW from outside.
std::vector<Vec3f> cubeCorners()
{
    std::vector<Vec3f> p;
    for (int i = 0; i < 8; ++i)
        p.emplace_back(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
    return p;
}

std::vector<std::uint32_t> cubeFaces()
{
    return {0, 2, 3, 0, 3, 1,  // z = 0, seen from below
            4, 5, 7, 4, 7, 6,  // z = 1
            0, 1, 5, 0, 5, 4,  // y = 0
            2, 6, 7, 2, 7, 3,  // y = 1
            0, 4, 6, 0, 6, 2,  // x = 0
            1, 3, 7, 1, 7, 5}; // x = 1
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> silhouetteFrom(const WingedEdgeMesh& mesh, const Vec3& eye)
{
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    mesh.silhouette(eye, edges);
    std::sort(edges.begin(), edges.end());
    return edges;
}
} // namespace

TEST(WingedEdgeMesh, ClosedCubeHasSquareAndHexagonSilhouettes)
{
    const WingedEdgeMesh cube(cubeCorners(), cubeFaces());
    ASSERT_TRUE(cube.closed()) << cube.problem();
    EXPECT_EQ(cube.edges().size(), 18u); // 12 cube edges + 6 face diagonals
    // Face-on from above: the top face's outline.
    using E = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
    EXPECT_EQ(silhouetteFrom(cube, {0.5, 0.5, 5.0}), (E{{4, 5}, {4, 6}, {5, 7}, {6, 7}}));
    // From beyond corner 7 (1,1,1): the hexagon through the six corners other than 0 and 7.
    EXPECT_EQ(silhouetteFrom(cube, {3.0, 3.0, 3.0}), (E{{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}}));
}

TEST(WingedEdgeMesh, OpenFlippedAndBrokenMeshesAreNamedAndGiveNoSilhouette)
{
    std::vector<std::uint32_t> open = cubeFaces();
    open.resize(open.size() - 6); // no x = 1 face
    std::vector<std::uint32_t> flipped = cubeFaces();
    std::swap(flipped[1], flipped[2]);
    std::vector<std::uint32_t> tripled = cubeFaces();
    tripled.insert(tripled.end(), {0, 2, 3});
    std::vector<std::uint32_t> outOfRange = cubeFaces();
    outOfRange[7] = 8;
    std::vector<std::uint32_t> repeated = cubeFaces();
    repeated[2] = repeated[1];
    std::vector<std::uint32_t> ragged = cubeFaces();
    ragged.pop_back();
    const struct
    {
        std::vector<std::uint32_t> indices;
        const char* problem;
    } cases[] = {
        {open, "edge 1-3 is used by 1 face"},
        {flipped, "edge 0-2 is used by 2 faces in the same direction"},
        {tripled, "edge 0-2 is used by 3 faces"},
        {outOfRange, "face 2 uses vertex 8 of 8"},
        {repeated, "face 0 repeats a vertex"},
        {ragged, "the index count is not a multiple of 3"},
        {{}, "no triangles"},
    };
    for (const auto& c : cases)
    {
        const WingedEdgeMesh mesh(cubeCorners(), c.indices);
        EXPECT_FALSE(mesh.closed());
        EXPECT_EQ(mesh.problem(), c.problem);
        EXPECT_TRUE(silhouetteFrom(mesh, {3.0, 3.0, 3.0}).empty());
        EXPECT_TRUE(mesh.edges().empty());
    }
}
