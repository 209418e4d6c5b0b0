// SPDX-License-Identifier: MIT
// osgVis::readQ3Solids on hand-made IBSP levels: which world brushes become boxes (in the bsp
// plugin's coordinates, y negated, so the y faces' bits swap), which only bound unproven space,
// which count for nothing (water, clip, movers), the spawn points as eye points; malformed levels
// refused with the fault named, never a crash; and the counts on a real OpenArena level.
#include <osgVis/Q3Solids>

#include "AppProcess.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <vector>

namespace
{
using osgVis::core::Aabb;
using osgVis::core::SolidSpace;
using osgVis::core::Vec3;

constexpr double S = 0.0254;        // the plugin's metres per Quake unit
constexpr double Margin = 0.0625;   // Quake units around every unproven bound

enum : std::int32_t
{
    SURF_SKY = 0x4,
    SURF_NODRAW = 0x80,
    CONTENTS_SOLID = 0x1,
    CONTENTS_WATER = 0x20,
    CONTENTS_PLAYERCLIP = 0x10000,
    CONTENTS_DETAIL = 0x8000000,
    CONTENTS_TRANSLUCENT = 0x20000000,
};

class Writer
{
public:
    void i32(std::int32_t v) { raw(&v, 4); }
    void f32(float v) { raw(&v, 4); }
    void raw(const void* data, std::size_t n)
    {
        const auto* b = static_cast<const std::uint8_t*>(data);
        bytes.insert(bytes.end(), b, b + n);
    }
    std::vector<std::uint8_t> bytes;
};

// The lumps readQ3Solids reads, written as an IBSP 46 file (the other lumps empty, at the end).
struct Level
{
    struct Shader
    {
        std::string name;
        std::int32_t surface, contents;
    };
    struct Model
    {
        std::array<float, 3> mins, maxs;
        std::int32_t firstBrush, brushCount;
    };
    struct Brush
    {
        std::int32_t firstSide, sideCount, shader;
    };
    struct Side
    {
        std::int32_t plane, shader;
    };
    std::string entities;
    std::vector<Shader> shaders;
    std::vector<std::array<float, 4>> planes; // normal, dist
    std::vector<Model> models;
    std::vector<Brush> brushes;
    std::vector<Side> sides;

    // A brush of the sides (plane normal, dist, side shader) given; returns its index.
    int brush(std::int32_t shader, const std::vector<std::pair<std::array<float, 4>, std::int32_t>>& brushSides)
    {
        brushes.push_back({std::int32_t(sides.size()), std::int32_t(brushSides.size()), shader});
        for (const auto& [plane, sideShader] : brushSides)
        {
            planes.push_back(plane);
            sides.push_back({std::int32_t(planes.size() - 1), sideShader});
        }
        return int(brushes.size() - 1);
    }
    // An axial box brush, Quake coordinates; side shaders in the order -x, +x, -y, +y, -z, +z.
    int box(std::int32_t shader, Vec3 lo, Vec3 hi, std::array<std::int32_t, 6> sideShaders)
    {
        return brush(shader, {{{-1, 0, 0, float(-lo.x)}, sideShaders[0]},
                              {{1, 0, 0, float(hi.x)}, sideShaders[1]},
                              {{0, -1, 0, float(-lo.y)}, sideShaders[2]},
                              {{0, 1, 0, float(hi.y)}, sideShaders[3]},
                              {{0, 0, -1, float(-lo.z)}, sideShaders[4]},
                              {{0, 0, 1, float(hi.z)}, sideShaders[5]}});
    }

    std::vector<std::uint8_t> bytes() const
    {
        std::vector<Writer> lumps(17);
        lumps[0].raw(entities.data(), entities.size());
        lumps[0].bytes.push_back(0); // q3map2 ends the text with a NUL
        for (const Shader& shader : shaders)
        {
            char name[64] = {};
            std::strncpy(name, shader.name.c_str(), sizeof(name) - 1);
            lumps[1].raw(name, sizeof(name));
            lumps[1].i32(shader.surface), lumps[1].i32(shader.contents);
        }
        for (const auto& plane : planes)
            for (float v : plane)
                lumps[2].f32(v);
        for (const Model& model : models)
        {
            for (float v : model.mins)
                lumps[7].f32(v);
            for (float v : model.maxs)
                lumps[7].f32(v);
            lumps[7].i32(0), lumps[7].i32(0), lumps[7].i32(model.firstBrush), lumps[7].i32(model.brushCount);
        }
        for (const Brush& brush : brushes)
            lumps[8].i32(brush.firstSide), lumps[8].i32(brush.sideCount), lumps[8].i32(brush.shader);
        for (const Side& side : sides)
            lumps[9].i32(side.plane), lumps[9].i32(side.shader);

        Writer file;
        file.raw("IBSP", 4);
        file.i32(46);
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
};

enum ShaderIndex : std::int32_t
{
    Wall,
    Caulk,
    Water,
    Detail,
    Sky,
    Glass,
    Clip
};

// World brushes 0..7 and a mover (model 1) with brush 8; expectations in the tests below.
Level testLevel()
{
    Level level;
    level.shaders = {{"textures/base_wall/concrete", 0, CONTENTS_SOLID},
                     {"textures/common/caulk", SURF_NODRAW, CONTENTS_SOLID},
                     {"textures/liquids/clear_calm1", 0, CONTENTS_WATER | CONTENTS_TRANSLUCENT},
                     {"textures/base_trim/pipe", 0, CONTENTS_SOLID | CONTENTS_DETAIL},
                     {"textures/skies/blue", SURF_SKY | SURF_NODRAW, CONTENTS_SOLID},
                     {"textures/base_wall/glass", 0, CONTENTS_SOLID | CONTENTS_TRANSLUCENT},
                     {"textures/common/clip", SURF_NODRAW, CONTENTS_PLAYERCLIP}};
    // 0: drawn box with its -y side caulked.
    level.box(Wall, {0, 16, -8}, {64, 48, 8}, {Wall, Wall, Caulk, Wall, Wall, Wall});
    // 1: a box with a second +x side of sky, a translucent +z side, and bevels lying outside it.
    level.brush(Wall, {{{-1, 0, 0, -100}, Wall},
                       {{1, 0, 0, 132}, Wall},
                       {{1, 0, 0, 132}, Sky},
                       {{0, -1, 0, 0}, Wall},
                       {{0, 1, 0, 32}, Wall},
                       {{0, 0, -1, 0}, Wall},
                       {{0, 0, 1, 32}, Glass},
                       {{0, 0, 1, 64}, Caulk},
                       {{-1, 0, 0, -50}, Caulk}});
    // 2: a box with a corner cut off by x + z <= 300: not axial, six axial sides.
    const float r = float(std::sqrt(0.5));
    level.brush(Wall, {{{-1, 0, 0, -200}, Wall},
                       {{1, 0, 0, 264}, Wall},
                       {{0, -1, 0, 0}, Wall},
                       {{0, 1, 0, 64}, Wall},
                       {{0, 0, -1, 0}, Wall},
                       {{0, 0, 1, 64}, Wall},
                       {{r, 0, r, 300 * r}, Wall}});
    // 3: a tetrahedron: only three axial sides.
    const float t = float(1 / std::sqrt(3.0));
    level.brush(Wall, {{{-1, 0, 0, -300}, Wall}, {{0, -1, 0, 0}, Wall}, {{0, 0, -1, 0}, Wall}, {{t, t, t, 400 * t}, Wall}});
    // 4: water; 5: a detail box; 6: player clip; 7: a box of no thickness.
    level.box(Water, {0, 0, 0}, {16, 16, 16}, {Water, Water, Water, Water, Water, Water});
    level.box(Detail, {0, 0, 100}, {16, 16, 116}, {Detail, Detail, Detail, Detail, Detail, Detail});
    level.box(Clip, {32, 0, 0}, {48, 16, 16}, {Clip, Clip, Clip, Clip, Clip, Clip});
    level.box(Wall, {0, 0, 200}, {16, 16, 200}, {Wall, Wall, Wall, Wall, Wall, Wall});
    // 8: a door.
    level.box(Wall, {500, 0, 0}, {532, 32, 32}, {Wall, Wall, Wall, Wall, Wall, Wall});
    level.models = {{{-512, -512, -512}, {1024, 1024, 1024}, 0, 8}, {{500, 0, 0}, {532, 32, 32}, 8, 1}};
    level.entities = "{\n\"classname\" \"worldspawn\"\n\"message\" \"test { level }\"\n}\n"
                     "{\n\"classname\" \"info_player_deathmatch\"\n\"origin\" \"32 -64 24\"\n\"angle\" \"90\"\n}\n"
                     "{\n\"origin\" \"10.5 20 -30\"\n\"classname\" \"team_CTF_bluespawn\"\n}\n"
                     "{\n\"classname\" \"light\"\n\"origin\" \"5 5 5\"\n\"light\" \"300\"\n}\n"
                     "{\n\"classname\" \"info_player_start\"\n}\n";
    return level;
}

SolidSpace read(const std::vector<std::uint8_t>& bytes) { return osgVis::readQ3Solids(bytes.data(), bytes.size(), "test.bsp"); }

std::string message(const std::vector<std::uint8_t>& bytes)
{
    try
    {
        read(bytes);
    }
    catch (const std::runtime_error& e)
    {
        return e.what();
    }
    return "no error";
}

// A box in Quake coordinates as the plugin's, grown by `margin` Quake units.
Aabb plugin(Vec3 lo, Vec3 hi, double margin = 0)
{
    lo -= Vec3(margin), hi += Vec3(margin);
    return Aabb(Vec3(lo.x * S, -hi.y * S, lo.z * S), Vec3(hi.x * S, -lo.y * S, hi.z * S));
}

void expectBox(const Aabb& actual, const Aabb& expected)
{
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_NEAR(actual.min[i], expected.min[i], 1e-9) << "min " << i;
        EXPECT_NEAR(actual.max[i], expected.max[i], 1e-9) << "max " << i;
    }
}

void setI32(std::vector<std::uint8_t>& bytes, std::size_t at, std::int32_t v) { std::memcpy(bytes.data() + at, &v, 4); }
std::int32_t getI32(const std::vector<std::uint8_t>& bytes, std::size_t at)
{
    std::int32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}
} // namespace

TEST(Q3Solids, AxialWorldBrushesBecomeBoxesWithTheirDrawnFaces)
{
    const SolidSpace space = read(testLevel().bytes());
    ASSERT_EQ(space.boxes.size(), 2u);
    // Brush 0: x 0..64, y 16..48 (plugin -48..-16), z -8..8. Every face drawn but Quake's low y
    // face (caulk), which is the plugin's high y face: bits 0, 1, 2, 4, 5.
    expectBox(space.boxes[0].box, plugin({0, 16, -8}, {64, 48, 8}));
    EXPECT_EQ(space.boxes[0].box.max.y, -16 * S);
    EXPECT_EQ(int(space.boxes[0].opaqueFaces), 0b110111);
    // Brush 1: +x has a sky side too, +z is glass; the bevels at x 50 and z 64 lie outside: bits
    // 0 (-x), 2 and 3 (both y faces), 4 (-z).
    expectBox(space.boxes[1].box, plugin({100, 0, 0}, {132, 32, 32}));
    EXPECT_EQ(int(space.boxes[1].opaqueFaces), 0b011101);
}

TEST(Q3Solids, OtherSolidWorldBrushesOnlyBoundUnprovenSpace)
{
    const SolidSpace space = read(testLevel().bytes());
    // Brushes 2 (not axial: its axial sides' box), 3 (three axial sides: the world's bounds),
    // 5 (detail) and 7 (no thickness); not the water (4), the clip (6) or the door (model 1).
    ASSERT_EQ(space.unproven.size(), 4u);
    expectBox(space.unproven[0], plugin({200, 0, 0}, {264, 64, 64}, Margin));
    expectBox(space.unproven[1], plugin({-512, -512, -512}, {1024, 1024, 1024}, Margin));
    expectBox(space.unproven[2], plugin({0, 0, 100}, {16, 16, 116}, Margin));
    expectBox(space.unproven[3], plugin({0, 0, 200}, {16, 16, 200}, Margin));
    for (const osgVis::core::SolidBox& box : space.boxes)
        EXPECT_LT(box.box.max.x, 500 * S) << "the door's brush is no box";
}

TEST(Q3Solids, SpawnPointsAreEyePoints)
{
    const SolidSpace space = read(testLevel().bytes());
    ASSERT_EQ(space.eyePoints.size(), 2u); // not the light; not the start without an origin
    EXPECT_NEAR(space.eyePoints[0].x, 32 * S, 1e-12);
    EXPECT_NEAR(space.eyePoints[0].y, 64 * S, 1e-12);
    EXPECT_NEAR(space.eyePoints[0].z, 24 * S, 1e-12);
    EXPECT_NEAR(space.eyePoints[1].x, 10.5 * S, 1e-12);
    EXPECT_NEAR(space.eyePoints[1].y, -20 * S, 1e-12);
    EXPECT_NEAR(space.eyePoints[1].z, -30 * S, 1e-12);
}

TEST(Q3Solids, ReadsFilesNamingThemInErrors)
{
    const std::vector<std::uint8_t> bytes = testLevel().bytes();
    const auto path = std::filesystem::temp_directory_path() / "osgvis-q3solids.bsp";
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    const SolidSpace space = osgVis::readQ3Solids(path.string());
    EXPECT_EQ(space.boxes.size(), 2u);
    EXPECT_EQ(space.unproven.size(), 4u);
    EXPECT_EQ(space.eyePoints.size(), 2u);

    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), 100);
    try
    {
        osgVis::readQ3Solids(path.string());
        ADD_FAILURE() << "a truncated file was read";
    }
    catch (const std::runtime_error& e)
    {
        EXPECT_NE(std::string(e.what()).find("'" + path.string() + "'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("too short for a header"), std::string::npos) << e.what();
    }
    EXPECT_THROW(osgVis::readQ3Solids("/nonexistent/level.bsp"), std::runtime_error);
}

TEST(Q3Solids, EveryTruncationIsRefused)
{
    const std::vector<std::uint8_t> bytes = testLevel().bytes();
    for (std::size_t size = 0; size < bytes.size(); ++size)
    {
        // The empty lumps lie at the end of the file, so every cut leaves one outside it.
        const std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + std::ptrdiff_t(size));
        EXPECT_THROW(read(cut), std::runtime_error) << size << " bytes";
    }
    EXPECT_THROW(osgVis::readQ3Solids(nullptr, 0), std::runtime_error);
}

TEST(Q3Solids, MalformedLevelsAreRefusedWithTheFault)
{
    const Level good = testLevel();
    const std::vector<std::uint8_t> bytes = good.bytes();
    const auto expectFault = [](const std::vector<std::uint8_t>& broken, const std::string& fault)
    {
        const std::string m = message(broken);
        EXPECT_NE(m.find("'test.bsp' is no Quake 3 level osgVis can read: "), std::string::npos) << m;
        EXPECT_NE(m.find(fault), std::string::npos) << "expected \"" << fault << "\", got: " << m;
    };

    // Header and lumps.
    std::vector<std::uint8_t> b = bytes;
    b[0] = 'V';
    expectFault(b, "not IBSP version 46");
    b = bytes;
    setI32(b, 8 + 8 * 9, std::int32_t(bytes.size())); // brush sides start at the end of the file
    expectFault(b, "lump 9 (brush sides) lies outside the file");
    b = bytes;
    setI32(b, 8 + 8 * 2, -16);
    expectFault(b, "lump 2 (planes) lies outside the file");
    b = bytes;
    setI32(b, 12 + 8 * 8, std::numeric_limits<std::int32_t>::max());
    expectFault(b, "lump 8 (brushes) lies outside the file");
    b = bytes;
    setI32(b, 12 + 8 * 2, getI32(bytes, 12 + 8 * 2) - 4);
    expectFault(b, "lump 2 (planes) is not a whole number of 16-byte records");

    // Indices out of range.
    Level level = good;
    level.sides[3].plane = std::int32_t(level.planes.size());
    expectFault(level.bytes(), "brush side 3 names plane " + std::to_string(level.planes.size()) + ", which the level lacks");
    level = good;
    level.sides[5].shader = -1;
    expectFault(level.bytes(), "brush side 5 names shader -1, which the level lacks");
    level = good;
    level.brushes[2].shader = 99;
    expectFault(level.bytes(), "brush 2 names shader 99, which the level lacks");
    level = good;
    level.brushes[8].sideCount = 100;
    expectFault(level.bytes(), "brush 8 names sides the level lacks");
    level = good;
    level.models[1].brushCount = 2;
    expectFault(level.bytes(), "model 1 names brushes the level lacks");
    level = good;
    level.models.clear();
    expectFault(level.bytes(), "no world model");

    // Numbers that are not finite.
    level = good;
    level.planes[2][3] = std::numeric_limits<float>::quiet_NaN();
    expectFault(level.bytes(), "plane 2 is not finite");
    level = good;
    level.planes.push_back({0, std::numeric_limits<float>::infinity(), 0, 0}); // a plane no brush uses
    expectFault(level.bytes(), "plane " + std::to_string(level.planes.size() - 1) + " is not finite");
    level = good;
    level.models[0].maxs[1] = std::numeric_limits<float>::infinity();
    expectFault(level.bytes(), "the world model's bounds are not finite");

    // Entity text.
    const std::pair<std::string, std::string> badEntities[] = {
        {"{ \"classname\" \"worldspawn }", "entity 0 has an unterminated quote"},
        {"{ \"classname\" \"worldspawn\" } { \"classname\" \"light\" ", "entity 1 has an unterminated brace"},
        {"{ \"classname\" \"worldspawn\" \"message\" }", "entity 0 has a stray character where a quoted value should be"},
        {"{ \"classname\" \"worldspawn\" } x", "stray character where entity 1 should begin"},
        {"{ classname \"worldspawn\" }", "entity 0 has a stray character where a quoted key should be"},
        {"{ \"origin\" \"1 2\" }", "entity 0 has an origin that is not three finite numbers"},
        {"{ \"origin\" \"1 2 3 4\" }", "entity 0 has an origin that is not three finite numbers"},
        {"{ } { \"classname\" \"light\" \"origin\" \"1 nan 3\" }", "entity 1 has an origin that is not three finite numbers"},
        {"{ \"origin\" \"1 2 1e999\" }", "entity 0 has an origin that is not three finite numbers"},
        {"{ \"origin\" \"1 2 3x\" }", "entity 0 has an origin that is not three finite numbers"},
    };
    for (const auto& [text, fault] : badEntities)
    {
        level = good;
        level.entities = text;
        expectFault(level.bytes(), fault);
    }
    // Text after the NUL that ends it is not read; white space and "+" before numbers are.
    level = good;
    level.entities = std::string("{ \"classname\" \"info_player_start\" \"origin\" \" +1\t2 3 \" }") + '\0' + "{ garbage";
    const SolidSpace space = read(level.bytes());
    ASSERT_EQ(space.eyePoints.size(), 1u);
    EXPECT_NEAR(space.eyePoints[0].y, -2 * S, 1e-12);
}

TEST(Q3Solids, RealOpenArenaLevel)
{
    const std::string pk3 = "/usr/share/games/openarena/baseoa/pak6-patch088.pk3";
    if (!std::filesystem::exists(pk3))
        GTEST_SKIP() << pk3 << " is not installed (Debian package openarena-088-data)";
    const std::filesystem::path dir = osgVis::test::scratchDirectory("osg", "q3solids");
    const osgVis::test::AppRun unzip = osgVis::test::runApp("unzip", "-o -q '" + pk3 + "' maps/oa_koth1.bsp -d '" + dir.string() + "'");
    if (unzip.exitCode != 0)
        GTEST_SKIP() << "cannot extract maps/oa_koth1.bsp with unzip: " << unzip.output;

    const SolidSpace space = osgVis::readQ3Solids((dir / "maps/oa_koth1.bsp").string());
    std::size_t sealed = 0;
    for (const osgVis::core::SolidBox& box : space.boxes)
    {
        sealed += box.opaqueFaces == 0x3f;
        EXPECT_TRUE(box.box.finite());
        EXPECT_GT(box.box.extent().x, 0.0);
        EXPECT_GT(box.box.extent().y, 0.0);
        EXPECT_GT(box.box.extent().z, 0.0);
        EXPECT_LT(int(box.opaqueFaces), 64);
    }
    std::cout << "oa_koth1: " << space.boxes.size() << " boxes (" << sealed << " with all 6 faces opaque), "
              << space.unproven.size() << " unproven, " << space.eyePoints.size() << " eye points\n";
    EXPECT_GE(space.boxes.size(), 100u);
    EXPECT_GE(space.eyePoints.size(), 1u);
    for (const Aabb& bound : space.unproven)
        EXPECT_TRUE(bound.finite() && !bound.empty());
}
