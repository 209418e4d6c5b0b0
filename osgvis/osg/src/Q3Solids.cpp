// SPDX-License-Identifier: MIT
// Reads a Quake 3 level's solid brushes and spawn points as core::SolidSpace (rules in
// include/osgVis/Q3Solids). Needs no OSG: the libFuzzer target compiles this file on its own.
#include <osgVis/Q3Solids>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <vector>

namespace osgVis
{
namespace
{
enum Lump
{
    EntitiesLump = 0,
    ShadersLump = 1,
    PlanesLump = 2,
    ModelsLump = 7,
    BrushesLump = 8,
    BrushSidesLump = 9,
    LumpCount = 17
};
constexpr std::size_t HeaderSize = 8 + 8 * LumpCount;
constexpr std::size_t ShaderSize = 72, PlaneSize = 16, ModelSize = 40, BrushSize = 12, BrushSideSize = 8;
constexpr double PluginScale = 0.0254;   // OSG's bsp plugin: metres from Quake units
constexpr double AxialTolerance = 1e-6;  // a normal component this close to 0 or ±1 is taken as exact
constexpr double UnprovenMargin = 0.0625; // Quake units added around every unproven bound

// q3map2's surface and content flags.
enum : std::uint32_t
{
    SURF_SKY = 0x4,
    SURF_NODRAW = 0x80,
    SURF_HINT = 0x100,
    SURF_SKIP = 0x200,
    SURF_NONSOLID = 0x4000,
    SURF_LIGHTFILTER = 0x8000,
    SURF_ALPHASHADOW = 0x10000,
    CONTENTS_SOLID = 0x1,
    CONTENTS_LAVA = 0x8,
    CONTENTS_SLIME = 0x10,
    CONTENTS_WATER = 0x20,
    CONTENTS_FOG = 0x40,
    CONTENTS_DETAIL = 0x8000000,
    CONTENTS_TRANSLUCENT = 0x20000000,
};
constexpr std::uint32_t NotDrawnOpaque =
    SURF_NODRAW | SURF_SKY | SURF_HINT | SURF_SKIP | SURF_LIGHTFILTER | SURF_ALPHASHADOW | SURF_NONSOLID;
constexpr std::uint32_t NotABox =
    CONTENTS_TRANSLUCENT | CONTENTS_WATER | CONTENTS_LAVA | CONTENTS_SLIME | CONTENTS_FOG | CONTENTS_DETAIL;

const char* const SpawnClasses[] = {"info_player_deathmatch", "info_player_start",  "team_CTF_redspawn",
                                    "team_CTF_bluespawn",     "team_CTF_redplayer", "team_CTF_blueplayer"};

// Bounds-checked little-endian reads from the file's bytes; every fault names the file.
class Reader
{
public:
    Reader(const std::uint8_t* data, std::size_t size, const std::string& name) : _data(data), _size(size), _name(name)
    {
    }

    std::int32_t i32(std::size_t at) const
    {
        need(at, 4);
        std::int32_t v;
        std::memcpy(&v, _data + at, 4); // little-endian, as the format and x86 are
        return v;
    }
    double f32(std::size_t at) const
    {
        need(at, 4);
        float v;
        std::memcpy(&v, _data + at, 4);
        return double(v);
    }
    std::uint8_t u8(std::size_t at) const
    {
        need(at, 1);
        return _data[at];
    }
    // Offset and record count of a lump.
    std::pair<std::size_t, std::size_t> lump(int index, const char* what, std::size_t recordSize) const
    {
        const std::int32_t offset = i32(8 + 8 * std::size_t(index)), length = i32(12 + 8 * std::size_t(index));
        const std::string lumpName = "lump " + std::to_string(index) + " (" + what + ")";
        if (offset < 0 || length < 0 || std::size_t(offset) > _size || std::size_t(length) > _size - std::size_t(offset))
            fail(lumpName + " lies outside the file");
        if (std::size_t(length) % recordSize != 0)
            fail(lumpName + " is not a whole number of " + std::to_string(recordSize) + "-byte records");
        return {std::size_t(offset), std::size_t(length) / recordSize};
    }
    [[noreturn]] void fail(const std::string& why) const
    {
        throw std::runtime_error("'" + _name + "' is no Quake 3 level osgVis can read: " + why);
    }
    std::size_t size() const { return _size; }

private:
    void need(std::size_t at, std::size_t n) const
    {
        if (at > _size || n > _size - at)
            fail("truncated");
    }
    const std::uint8_t* _data;
    std::size_t _size;
    const std::string& _name;
};

struct Plane
{
    double normal[3];
    double dist;
};
struct Shader
{
    std::uint32_t surfaceFlags, contentFlags;
};
struct Brush
{
    std::size_t firstSide, sideCount, shader;
};
struct Side
{
    std::size_t plane, shader;
};

// The box face a side's plane bounds when it is axial: 2*axis for a normal along -axis (the low
// face), 2*axis+1 along +axis (the high face), in Quake coordinates; -1 when it is not axial.
int axialFace(const Plane& plane)
{
    for (int axis = 0; axis < 3; ++axis)
    {
        const double n = plane.normal[axis];
        if (std::abs(std::abs(n) - 1.0) > AxialTolerance)
            continue;
        bool others = true;
        for (int other = 0; other < 3; ++other)
            others = others && (other == axis || std::abs(plane.normal[other]) <= AxialTolerance);
        return others ? 2 * axis + (n > 0.0 ? 1 : 0) : -1;
    }
    return -1;
}
// The coordinate on its axis that an axial side bounds: x <= dist for +x, x >= -dist for -x.
double faceCoordinate(const Plane& plane, int face)
{
    return (face & 1) ? plane.dist : -plane.dist;
}

// A box in Quake coordinates to the plugin's: scaled, y negated (so y's min and max swap).
core::Aabb toPlugin(const double lo[3], const double hi[3])
{
    return core::Aabb(core::Vec3(lo[0] * PluginScale, -hi[1] * PluginScale, lo[2] * PluginScale),
                      core::Vec3(hi[0] * PluginScale, -lo[1] * PluginScale, hi[2] * PluginScale));
}

bool sameKey(const std::string& a, const char* b)
{
    const std::size_t n = std::strlen(b);
    if (a.size() != n)
        return false;
    for (std::size_t i = 0; i < n; ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

// Three finite numbers separated by white space, as in "origin" "-64 128 24.5".
bool parseVector(const std::string& text, double out[3])
{
    const char* p = text.data();
    const char* const end = text.data() + text.size();
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    for (int i = 0; i < 3; ++i)
    {
        while (p < end && space(*p))
            ++p;
        if (p < end && *p == '+')
            ++p;
        const std::from_chars_result r = std::from_chars(p, end, out[i]);
        if (r.ec != std::errc() || r.ptr == p || !std::isfinite(out[i]) || (r.ptr < end && !space(*r.ptr)))
            return false;
        p = r.ptr;
    }
    while (p < end && space(*p))
        ++p;
    return p == end;
}

// The entity text: `{ "key" "value" ... }` blocks; the origins of spawn points as eye points.
void readEntities(const Reader& r, std::size_t offset, std::size_t length, std::vector<core::Vec3>& eyePoints)
{
    std::size_t end = offset;
    while (end < offset + length && r.u8(end) != 0) // the text ends at its first NUL
        ++end;
    std::size_t at = offset;
    std::size_t entity = 0;
    const auto skipSpace = [&] {
        while (at < end && r.u8(at) <= ' ')
            ++at;
    };
    const auto quoted = [&](const char* what) {
        if (r.u8(at) != '"')
            r.fail("entity " + std::to_string(entity) + " has a stray character where a quoted " + what + " should be");
        std::string text;
        for (++at; at < end && r.u8(at) != '"'; ++at)
            text.push_back(char(r.u8(at)));
        if (at >= end)
            r.fail("entity " + std::to_string(entity) + " has an unterminated quote");
        ++at;
        return text;
    };
    for (;; ++entity)
    {
        skipSpace();
        if (at >= end)
            return;
        if (r.u8(at) != '{')
            r.fail("the entity text has a stray character where entity " + std::to_string(entity) + " should begin");
        ++at;
        std::string classname;
        bool haveClassname = false, haveOrigin = false;
        double origin[3] = {0, 0, 0};
        for (;;)
        {
            skipSpace();
            if (at >= end)
                r.fail("entity " + std::to_string(entity) + " has an unterminated brace");
            if (r.u8(at) == '}')
            {
                ++at;
                break;
            }
            const std::string key = quoted("key");
            skipSpace();
            if (at >= end)
                r.fail("entity " + std::to_string(entity) + " has an unterminated brace");
            const std::string value = quoted("value");
            if (sameKey(key, "origin"))
            {
                double v[3];
                if (!parseVector(value, v))
                    r.fail("entity " + std::to_string(entity) + " has an origin that is not three finite numbers");
                if (!haveOrigin) // the game reads a key's first value
                    std::copy(v, v + 3, origin);
                haveOrigin = true;
            }
            else if (sameKey(key, "classname") && !haveClassname)
            {
                classname = value;
                haveClassname = true;
            }
        }
        if (haveOrigin &&
            std::any_of(std::begin(SpawnClasses), std::end(SpawnClasses), [&](const char* c) { return classname == c; }))
            eyePoints.emplace_back(origin[0] * PluginScale, -origin[1] * PluginScale, origin[2] * PluginScale);
    }
}

// The header: the magic and version of a Quake 3 level.
void checkHeader(const Reader& r)
{
    if (r.size() < HeaderSize)
        r.fail("too short for a header");
    if (!(r.u8(0) == 'I' && r.u8(1) == 'B' && r.u8(2) == 'S' && r.u8(3) == 'P') || r.i32(4) != 46)
        r.fail("not IBSP version 46 (Quake 3)");
}

std::vector<Shader> readShaders(const Reader& r)
{
    const auto [shaders, shaderCount] = r.lump(ShadersLump, "shaders", ShaderSize);
    std::vector<Shader> shaderList(shaderCount);
    for (std::size_t i = 0; i < shaderCount; ++i)
        shaderList[i] = {std::uint32_t(r.i32(shaders + i * ShaderSize + 64)),
                         std::uint32_t(r.i32(shaders + i * ShaderSize + 68))};
    return shaderList;
}

std::vector<Plane> readPlanes(const Reader& r)
{
    const auto [planes, planeCount] = r.lump(PlanesLump, "planes", PlaneSize);
    std::vector<Plane> planeList(planeCount);
    for (std::size_t i = 0; i < planeCount; ++i)
    {
        const std::size_t at = planes + i * PlaneSize;
        Plane& p = planeList[i];
        p = {{r.f32(at), r.f32(at + 4), r.f32(at + 8)}, r.f32(at + 12)};
        if (!std::isfinite(p.normal[0]) || !std::isfinite(p.normal[1]) || !std::isfinite(p.normal[2]) ||
            !std::isfinite(p.dist))
            r.fail("plane " + std::to_string(i) + " is not finite");
    }
    return planeList;
}

std::vector<Side> readSides(const Reader& r, std::size_t planeCount, std::size_t shaderCount)
{
    const auto [sides, sideCount] = r.lump(BrushSidesLump, "brush sides", BrushSideSize);
    std::vector<Side> sideList(sideCount);
    for (std::size_t i = 0; i < sideCount; ++i)
    {
        const std::int32_t plane = r.i32(sides + i * BrushSideSize), shader = r.i32(sides + i * BrushSideSize + 4);
        if (plane < 0 || std::size_t(plane) >= planeCount)
            r.fail("brush side " + std::to_string(i) + " names plane " + std::to_string(plane) + ", which the level lacks");
        if (shader < 0 || std::size_t(shader) >= shaderCount)
            r.fail("brush side " + std::to_string(i) + " names shader " + std::to_string(shader) + ", which the level lacks");
        sideList[i] = {std::size_t(plane), std::size_t(shader)};
    }
    return sideList;
}

std::vector<Brush> readBrushes(const Reader& r, std::size_t sideCount, std::size_t shaderCount)
{
    const auto [brushes, brushCount] = r.lump(BrushesLump, "brushes", BrushSize);
    std::vector<Brush> brushList(brushCount);
    for (std::size_t i = 0; i < brushCount; ++i)
    {
        const std::size_t at = brushes + i * BrushSize;
        const std::int32_t first = r.i32(at), count = r.i32(at + 4), shader = r.i32(at + 8);
        if (first < 0 || count < 0 || std::size_t(first) + std::size_t(count) > sideCount)
            r.fail("brush " + std::to_string(i) + " names sides the level lacks");
        if (shader < 0 || std::size_t(shader) >= shaderCount)
            r.fail("brush " + std::to_string(i) + " names shader " + std::to_string(shader) + ", which the level lacks");
        brushList[i] = {std::size_t(first), std::size_t(count), std::size_t(shader)};
    }
    return brushList;
}

// Model 0: its bounds, grown for rounding (the unproven bound of a brush that has no box), and its brushes.
struct WorldModel
{
    double lo[3], hi[3];
    std::size_t firstBrush, brushCount;
};

// Checks every model's brushes, though only the world's make solids.
WorldModel readWorldModel(const Reader& r, std::size_t brushCount)
{
    const auto [models, modelCount] = r.lump(ModelsLump, "models", ModelSize);
    if (modelCount == 0)
        r.fail("it has no world model (model 0)");
    for (std::size_t i = 0; i < modelCount; ++i)
    {
        const std::size_t at = models + i * ModelSize;
        const std::int32_t first = r.i32(at + 32), count = r.i32(at + 36);
        if (first < 0 || count < 0 || std::size_t(first) + std::size_t(count) > brushCount)
            r.fail("model " + std::to_string(i) + " names brushes the level lacks");
    }
    WorldModel world;
    for (int axis = 0; axis < 3; ++axis)
    {
        const double a = r.f32(models + 4 * std::size_t(axis)), b = r.f32(models + 12 + 4 * std::size_t(axis));
        if (!std::isfinite(a) || !std::isfinite(b))
            r.fail("the world model's bounds are not finite");
        world.lo[axis] = std::min(a, b) - UnprovenMargin;
        world.hi[axis] = std::max(a, b) + UnprovenMargin;
    }
    world.firstBrush = std::size_t(r.i32(models + 32));
    world.brushCount = std::size_t(r.i32(models + 36));
    return world;
}

// The level's records the solids are made from, all read and checked.
struct Level
{
    std::vector<Shader> shaders;
    std::vector<Plane> planes;
    std::vector<Side> sides;
    std::vector<Brush> brushes;
};

// The box of the brush's axial sides, in Quake coordinates (infinite where no side bounds it);
// false when some side is not axial.
bool axialSideBox(const Level& level, const Brush& brush, double lo[3], double hi[3])
{
    std::fill(lo, lo + 3, -std::numeric_limits<double>::infinity());
    std::fill(hi, hi + 3, std::numeric_limits<double>::infinity());
    bool allAxial = true;
    for (std::size_t s = brush.firstSide; s < brush.firstSide + brush.sideCount; ++s)
    {
        const Plane& plane = level.planes[level.sides[s].plane];
        const int face = axialFace(plane);
        if (face < 0)
        {
            allAxial = false;
            continue;
        }
        const int axis = face / 2;
        if (face & 1)
            hi[axis] = std::min(hi[axis], faceCoordinate(plane, face));
        else
            lo[axis] = std::max(lo[axis], faceCoordinate(plane, face));
    }
    return allAxial;
}

// A brush whose sides are all axial and bound the box lo..hi (Quake coordinates) as a SolidBox.
core::SolidBox solidBox(const Level& level, const Brush& brush, const double lo[3], const double hi[3])
{
    // Quake face f's bit: every side lying in its plane is drawn opaque.
    std::array<bool, 6> opaque{true, true, true, true, true, true};
    for (std::size_t s = brush.firstSide; s < brush.firstSide + brush.sideCount; ++s)
    {
        const Plane& plane = level.planes[level.sides[s].plane];
        const int face = axialFace(plane);
        const double bound = (face & 1) ? hi[face / 2] : lo[face / 2];
        if (faceCoordinate(plane, face) != bound)
            continue; // outside the box: bounds no face
        const Shader& shader = level.shaders[level.sides[s].shader];
        if ((shader.surfaceFlags & NotDrawnOpaque) || (shader.contentFlags & CONTENTS_TRANSLUCENT))
            opaque[std::size_t(face)] = false;
    }
    // Negating y turns Quake's low y face (bit 2) into the plugin's high one (bit 3).
    static constexpr int PluginBit[6] = {0, 1, 3, 2, 4, 5};
    core::SolidBox box;
    box.box = toPlugin(lo, hi);
    for (int face = 0; face < 6; ++face)
        if (opaque[std::size_t(face)])
            box.opaqueFaces = std::uint8_t(box.opaqueFaces | (1u << PluginBit[face]));
    return box;
}

// A world brush into `space`: a box when it is one, else (when solid) an unproven bound.
void addWorldBrush(const Level& level, const Brush& brush, const WorldModel& world, core::SolidSpace& space)
{
    const std::uint32_t contents = level.shaders[brush.shader].contentFlags;
    if (!(contents & CONTENTS_SOLID))
        return;
    // The box of the brush's axial sides, in Quake coordinates.
    double lo[3], hi[3];
    const bool allAxial = axialSideBox(level, brush, lo, hi);
    bool bounded = true, positive = true;
    for (int axis = 0; axis < 3; ++axis)
    {
        bounded = bounded && std::isfinite(lo[axis]) && std::isfinite(hi[axis]);
        positive = positive && hi[axis] > lo[axis];
    }

    if (!(contents & NotABox) && allAxial && bounded && positive)
    {
        space.boxes.push_back(solidBox(level, brush, lo, hi));
        return;
    }

    // Proves nothing: a bound around it, for the faces it may have cost their fragments.
    if (bounded)
    {
        for (int axis = 0; axis < 3; ++axis)
        {
            const double a = std::min(lo[axis], hi[axis]), c = std::max(lo[axis], hi[axis]);
            lo[axis] = a - UnprovenMargin;
            hi[axis] = c + UnprovenMargin;
        }
        space.unproven.push_back(toPlugin(lo, hi));
    }
    else
        space.unproven.push_back(toPlugin(world.lo, world.hi));
}
} // namespace

core::SolidSpace readQ3Solids(const void* data, std::size_t size, const std::string& name)
{
    const Reader r(static_cast<const std::uint8_t*>(data), data ? size : 0, name);
    checkHeader(r);

    // Every record is read and checked before any solid is made.
    Level level;
    level.shaders = readShaders(r);
    level.planes = readPlanes(r);
    level.sides = readSides(r, level.planes.size(), level.shaders.size());
    level.brushes = readBrushes(r, level.sides.size(), level.shaders.size());
    const WorldModel world = readWorldModel(r, level.brushes.size());

    core::SolidSpace space;
    const auto [entities, entitiesLength] = r.lump(EntitiesLump, "entities", 1);
    readEntities(r, entities, entitiesLength, space.eyePoints);

    for (std::size_t b = world.firstBrush; b < world.firstBrush + world.brushCount; ++b)
        addWorldBrush(level, level.brushes[b], world, space);
    return space;
}

core::SolidSpace readQ3Solids(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error("cannot open '" + path + "'");
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), {}};
    if (in.bad())
        throw std::runtime_error("cannot read '" + path + "'");
    return readQ3Solids(bytes.data(), bytes.size(), path);
}
} // namespace osgVis
