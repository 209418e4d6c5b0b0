// SPDX-License-Identifier: MIT
// osgVis::Q3Bsp on a hand-made two-leaf level: the tree finds the leaf of a point (in the bsp
// plugin's coordinates), visdata says which cluster sees which, leaves name their faces, polygon
// faces give q3map2's own triangles, and broken files are refused with the file named.
#include <osgVis/Q3Bsp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace
{
class Writer
{
public:
    void i32(std::int32_t v) { raw(&v, 4); }
    void f32(float v) { raw(&v, 4); }
    void u8(std::uint8_t v) { raw(&v, 1); }
    void raw(const void* data, std::size_t n)
    {
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        this->bytes.insert(this->bytes.end(), bytes, bytes + n);
    }
    std::vector<std::uint8_t> bytes;
};

// A level split by the plane x = 0 (Quake units): leaf 0 (cluster 0) in front holds face 0, leaf 1
// (cluster 1) behind holds face 1; cluster 0 sees only itself, cluster 1 sees both. Both faces
// are polygon faces of four vertices with their triangles in meshverts.
std::vector<std::uint8_t> twoLeafLevel(const char* magic = "IBSP", std::int32_t version = 46)
{
    std::vector<Writer> lumps(17);
    lumps[2].f32(1), lumps[2].f32(0), lumps[2].f32(0), lumps[2].f32(0);  // plane x = 0
    lumps[3].i32(0), lumps[3].i32(-1), lumps[3].i32(-2);                // node: front leaf 0, back leaf 1
    for (int i = 0; i < 6; ++i)
        lumps[3].i32(0);
    for (int leaf = 0; leaf < 2; ++leaf)
    {
        lumps[4].i32(leaf); // cluster
        for (int i = 0; i < 7; ++i)
            lumps[4].i32(0); // area, mins, maxs
        lumps[4].i32(leaf), lumps[4].i32(1), lumps[4].i32(0), lumps[4].i32(0); // one leafface each
    }
    lumps[5].i32(0), lumps[5].i32(1);
    for (int v = 0; v < 8; ++v)
        for (int i = 0; i < 11; ++i)
            lumps[10].f32(float(v + i)); // positions etc.: only the count matters here
    for (int index : {0, 1, 2, 0, 2, 3})
        lumps[11].i32(index);
    for (int face = 0; face < 2; ++face)
    {
        lumps[13].i32(0), lumps[13].i32(0), lumps[13].i32(1);     // texture, effect, type polygon
        lumps[13].i32(4 * face), lumps[13].i32(4);                // vertices
        lumps[13].i32(0), lumps[13].i32(6);                       // meshverts
        for (int i = 0; i < 5 + 12 + 2; ++i)
            lumps[13].i32(0);
    }
    lumps[16].i32(2), lumps[16].i32(1), lumps[16].u8(0b01), lumps[16].u8(0b11);

    Writer file;
    file.raw(magic, 4);
    file.i32(version);
    std::int32_t offset = 8 + 17 * 8;
    for (const Writer& lump : lumps)
    {
        file.i32(offset);
        file.i32(std::int32_t(lump.bytes.size()));
        offset += std::int32_t(lump.bytes.size());
    }
    for (const Writer& lump : lumps)
        file.raw(lump.bytes.data(), lump.bytes.size());
    return file.bytes;
}

std::string writeLevel(const std::string& name, const std::vector<std::uint8_t>& bytes)
{
    const auto path = std::filesystem::temp_directory_path() / name;
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path.string();
}
} // namespace

TEST(Q3Bsp, LeavesClustersVisibilityAndFaceTriangles)
{
    const osgVis::Q3Bsp level = osgVis::Q3Bsp::read(writeLevel("osgvis-two-leaves.bsp", twoLeafLevel()));
    // The plugin's coordinates: Quake units × 0.0254, y negated.
    EXPECT_EQ(level.clusterAt(osgVis::core::Vec3(0.254, 0.5, 0.0)), 0);
    EXPECT_EQ(level.clusterAt(osgVis::core::Vec3(-0.254, -0.5, 0.0)), 1);
    EXPECT_EQ(level.clusterCount(), 2);
    EXPECT_TRUE(level.clusterSees(0, 0));
    EXPECT_FALSE(level.clusterSees(0, 1));
    EXPECT_TRUE(level.clusterSees(1, 0));
    EXPECT_TRUE(level.clusterSees(1, 1));
    ASSERT_EQ(level.faceClusters().size(), 2u);
    EXPECT_EQ(level.faceClusters()[0], std::vector<int>{0});
    EXPECT_EQ(level.faceClusters()[1], std::vector<int>{1});
    EXPECT_EQ(level.drawableFaces(), (std::vector<int>{0, 1}));
    EXPECT_TRUE(level.isPolygonFace(1));
    EXPECT_EQ(level.faceTriangles(1), (std::vector<std::uint32_t>{4, 5, 6, 4, 6, 7}));
    EXPECT_TRUE(level.faceTriangles(2).empty());
}

TEST(Q3Bsp, BrokenFilesAreRefusedNamingTheFile)
{
    const auto message = [](const std::string& path)
    {
        try
        {
            osgVis::Q3Bsp::read(path);
        }
        catch (const std::runtime_error& e)
        {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string valve = writeLevel("osgvis-valve.bsp", twoLeafLevel("VBSP", 20));
    EXPECT_NE(message(valve).find("not IBSP version 46"), std::string::npos) << message(valve);
    EXPECT_NE(message(valve).find(valve), std::string::npos);

    std::vector<std::uint8_t> truncated = twoLeafLevel();
    truncated.resize(truncated.size() - 30);
    const std::string cut = writeLevel("osgvis-cut.bsp", truncated);
    EXPECT_NE(message(cut).find("outside the file"), std::string::npos) << message(cut);
    EXPECT_NE(message("/nonexistent/level.bsp").find("cannot open"), std::string::npos);
}
