// SPDX-License-Identifier: MIT
// osgvisgen: writes a seeded test scene (.osgb or any format osgDB writes, or glTF through its own
// writer) and its walk beside it.
#include "GltfExport.h"

#include <CommandLine.h>

#include <osgVis/gen/Generator.h>
#include <osgVis/gen/PagedScene.h>
#include <osgVis/gen/SceneStats.h>

#include <osgDB/WriteFile>

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

namespace
{
using osgVis::apps::UsageError;

const char* usage =
    "usage: osgvisgen --kind office|city|tetra|floor|forest [--layout L] [--triangles N] [--seed S] -o SCENE\n"
    "       osgvisgen --kind K [...] --paged DIR [--tiles N] [--page-range M] [-o SCENE]\n"
    "       osgvisgen --adversarial NAME -o SCENE\n"
    "       osgvisgen --list | --help\n"
    "\n"
    "Writes a generated scene to SCENE (format by extension, e.g. scene.osgb) and its walk to the\n"
    "same path with the extension .walk (scene.walk), then prints one summary line. SCENE.gltf or\n"
    "SCENE.glb goes through osgvisgen's own minimal glTF writer: node hierarchy and matrices, and\n"
    "positions and triangles only (no materials, normals or colours; occluder, cell and portal\n"
    "markers are plain nodes there).\n"
    "\n"
    "  --kind K          office (furnished rooms and corridors), city (streets and buildings),\n"
    "                    tetra (tetrahedra on a plane) or floor (one office storey of 204 rooms, about\n"
    "                    2300 objects whatever N, walked along its corridors only) or forest (trees of\n"
    "                    closed surfaces: trunk, branches and leaf clumps each an object)\n"
    "  --layout L        forest only: single (one tree), line (six in a row) or dense (32 on a grid;\n"
    "                    the default); the layout does not depend on N\n"
    "  --triangles N     triangle budget, 1000 to 50000000 (floor: 60000 to 50000000; default 100000,\n"
    "                    floor 300000; forest 12000 a tree: 12000, 72000, 385000); only the tessellation\n"
    "                    of floor and forest changes; the scene lands within 10%\n"
    "  --seed S          random seed, 0 to 4294967295 (default 1); the same seed gives the same bytes\n"
    "  --adversarial NAME  one of the small adversarial scenes instead (see --list)\n"
    "  --paged DIR       also (or, without -o, only) write the scene as a paged database: DIR/root.osgb\n"
    "                    holds one osg::PagedLOD per tile stating the tile's bounding sphere, each tile\n"
    "                    is DIR/tile_NNNN.osgb (its drawables, whole, under their matrices), and the walk\n"
    "                    is DIR/root.walk; DIR is created if missing; stock osgviewer DIR/root.osgb\n"
    "                    pages it with OSG's DatabasePager, and DIR/culled.osgt (root.osgb under an\n"
    "                    osgVis::VisibilityGroup, octree) with osgVis's plugins on OSG_LIBRARY_PATH\n"
    "  --tiles N         at most N grid cells over the scene's two widest axes, 1 to 65536 (default 256;\n"
    "                    empty cells write no tile)\n"
    "  --page-range M    a tile loads while the eye is within M of its centre (default: any distance,\n"
    "                    so every tile in the frustum loads)\n"
    "  -o, --output SCENE  output path (required)\n"
    "  --list            list the scene kinds and adversarial scenes\n"
    "  --help            this text\n"
    "\n"
    "Presets (layout, tessellation, walk speed, projection) are frozen: see docs/scenes.md.\n";

bool isGltfPath(const std::string& path)
{
    const std::string extension = std::filesystem::path(path).extension().string();
    return extension == ".gltf" || extension == ".glb" || extension == ".GLTF" || extension == ".GLB";
}

std::string walkPathFor(const std::string& scenePath)
{
    const std::size_t slash = scenePath.find_last_of('/');
    const std::size_t dot = scenePath.find_last_of('.');
    const bool hasExtension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return (hasExtension ? scenePath.substr(0, dot) : scenePath) + ".walk";
}

struct Options
{
    std::optional<std::string> kind;
    std::optional<std::string> adversarial;
    std::optional<std::string> layout;      // forest only
    std::optional<std::uint64_t> triangles; // default per kind
    std::uint32_t seed = 1;
    std::string output;
    std::optional<std::string> paged; // directory of a paged database
    osgVis::gen::PagedOptions pagedOptions;
    bool list = false;
    bool help = false;
};

Options parse(int argc, char** argv)
{
    namespace gen = osgVis::gen;
    using osgVis::apps::parseUnsigned;
    Options o;
    const auto setOptional = [](std::optional<std::string>& target)
    { return [&target](const std::string& value) { target = value; }; };
    osgVis::apps::CommandLine line;
    line.flag({"--help", "-h"}, o.help)
        .flag({"--list"}, o.list)
        .value({"--kind"}, setOptional(o.kind))
        .value({"--adversarial"}, setOptional(o.adversarial))
        .value({"--layout"}, setOptional(o.layout))
        .value({"--triangles"}, [&](const std::string& value)
               { o.triangles = parseUnsigned("--triangles", value, gen::minTriangles, gen::maxTriangles); })
        .value({"--seed"}, [&](const std::string& value)
               { o.seed = std::uint32_t(parseUnsigned("--seed", value, 0, 4294967295u)); })
        .value({"-o", "--output"}, o.output)
        .value({"--paged"}, setOptional(o.paged))
        .value({"--tiles"}, [&](const std::string& value)
               { o.pagedOptions.tiles = unsigned(parseUnsigned("--tiles", value, 1, 65536)); })
        .value({"--page-range"},
               [&](const std::string& value)
               {
                   const double range = osgVis::apps::parseNumber("--page-range", value);
                   if (!(range > 0.0))
                       throw UsageError("--page-range needs a positive distance, got '" + value + "'");
                   o.pagedOptions.range = range;
               });
    line.parse(argc, argv);
    if (o.help || o.list)
        return o;
    if (o.kind && o.adversarial)
        throw UsageError("give either --kind or --adversarial, not both");
    if (!o.kind && !o.adversarial)
        throw UsageError("missing --kind (or --adversarial)");
    if (o.output.empty() && !o.paged)
        throw UsageError("missing output path (-o SCENE or --paged DIR)");
    if (o.paged && o.adversarial)
        throw UsageError("--paged goes with --kind only");
    if (o.layout && (!o.kind || *o.kind != "forest"))
        throw UsageError("--layout goes with --kind forest only");
    return o;
}

int run(const Options& o)
{
    namespace gen = osgVis::gen;
    if (o.help)
    {
        std::cout << usage;
        return 0;
    }
    if (o.list)
    {
        std::cout << "kinds:";
        for (const std::string& k : gen::sceneKindNames())
            std::cout << ' ' << k;
        std::cout << "\nforest layouts:";
        for (const std::string& l : gen::forestLayoutNames())
            std::cout << ' ' << l;
        std::cout << "\nadversarial:";
        for (const std::string& n : gen::adversarialSceneNames())
            std::cout << ' ' << n;
        std::cout << '\n';
        return 0;
    }

    const auto start = std::chrono::steady_clock::now();
    gen::GeneratedScene scene;
    std::string what;
    if (o.adversarial)
    {
        scene = gen::adversarialScene(*o.adversarial);
        what = "adversarial " + *o.adversarial;
    }
    else
    {
        gen::GenerateOptions options;
        options.kind = gen::parseSceneKind(*o.kind);
        if (o.layout)
            options.forestLayout = gen::parseForestLayout(*o.layout);
        options.triangles = o.triangles ? *o.triangles : gen::defaultTriangles(options.kind, options.forestLayout);
        options.seed = o.seed;
        scene = gen::generate(options);
        what = *o.kind +
               (options.kind == gen::SceneKind::Forest ? std::string(" ") + gen::forestLayoutName(options.forestLayout)
                                                       : "") +
               " seed " + std::to_string(o.seed);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const gen::SceneStats stats = gen::sceneStats(*scene.root);
    if (o.paged)
    {
        std::filesystem::create_directories(*o.paged);
        const gen::PagedSummary paged = gen::writePagedScene(*scene.root, *o.paged, o.pagedOptions);
        const std::string walkPath = walkPathFor(paged.rootPath);
        scene.walk.save(walkPath);
        std::printf("%s: %zu objects, %llu triangles in %zu tiles (%zu drawables, %.1f MB) -> %s (walk %s)\n",
                    what.c_str(), stats.objects, (unsigned long long)stats.triangles, paged.tiles, paged.drawables,
                    paged.bytes / 1e6,
                    paged.rootPath.c_str(), walkPath.c_str());
        if (o.output.empty())
            return 0;
    }

    std::string gltfError;
    if (isGltfPath(o.output))
    {
        if (!gen::writeGltf(*scene.root, o.output, gltfError))
        {
            std::cerr << "osgvisgen: " << gltfError << "\n";
            return 1;
        }
    }
    else if (!osgDB::writeNodeFile(*scene.root, o.output))
    {
        std::cerr << "osgvisgen: cannot write '" << o.output
                  << "' (missing directory, no permission, or no osgDB plugin for its extension)\n";
        return 1;
    }
    const std::string walkPath = walkPathFor(o.output);
    scene.walk.save(walkPath);

    std::printf("%s: %zu objects, %llu triangles, %zu walk views, generated in %.2f s -> %s (walk %s)\n", what.c_str(),
                stats.objects, (unsigned long long)stats.triangles, scene.walk.keys.size(), seconds, o.output.c_str(),
                walkPath.c_str());
    return 0;
}
} // namespace

int main(int argc, char** argv)
{
    try
    {
        return run(parse(argc, argv));
    }
    catch (const UsageError& e)
    {
        std::cerr << "osgvisgen: " << e.what() << "\n(osgvisgen --help for usage)\n";
        return 2;
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvisgen: " << e.what() << '\n';
        return 1;
    }
}
