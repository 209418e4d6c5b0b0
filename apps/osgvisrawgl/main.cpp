// SPDX-License-Identifier: MIT
// osgvisrawgl: a renderer that is not OSG, hosting osgVis through its C interface only. It reads a
// glTF model with tinygltf into its own scene (RawScene.h), hands every object to an osgvis_context
// (bounds, flags, world triangles), culls each view of a walk with osgvis_cull and draws
// osgvis_visible_ids with OpenGL 3.3 core (RawRenderer.h). It links osgVis::Core, GLFW and tinygltf,
// never OSG: culling goes through <osgVis/visapi.h>; the walk file is read by the core's
// OSG-free Walk parser. docs/visapi.md, "A renderer that is not OSG", has the comparison with the OSG
// adapter that this program exists for.
#include "RawHierarchy.h"
#include "RawOptions.h"
#include "RawRenderer.h"
#include "RawScene.h"

#include <CommandLine.h>

#include <osgVis/core/scene/Walk.h>
#include <osgVis/visapi.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

namespace
{
using namespace osgVis::rawgl;

struct RunError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

void require(osgvis_status status)
{
    if (status != OSGVIS_OK)
        throw RunError(osgvis_last_error());
}

struct ContextDeleter
{
    void operator()(osgvis_context* context) const { osgvis_context_destroy(context); }
};
using Context = std::unique_ptr<osgvis_context, ContextDeleter>;

// One mode: its own context (scene copy, module chain and temporal state) and its figures.
struct ModeRun
{
    std::string name;
    Context context;
    bool conservative = true; // approximate modes say so in their name (docs/visapi.md)
    std::ofstream dump;
    std::vector<double> cullMs;
    double visibleSum = 0;
    std::size_t differingPixels = 0, viewsWithDifferences = 0;
};

Context makeContext(const RawScene& scene, const std::string& mode, RawHierarchy* hierarchy)
{
    osgvis_context* raw = nullptr;
    require(osgvis_context_create(&raw));
    Context context(raw);
    for (const RawObject& object : scene.objects)
    {
        osgvis_object_desc desc{};
        std::copy(object.boundsMin, object.boundsMin + 3, desc.bounds_min);
        std::copy(object.boundsMax, object.boundsMax + 3, desc.bounds_max);
        desc.flags = object.flags;
        desc.triangle_count = object.triangleCount();
        desc.triangles = object.worldTriangles.empty() ? nullptr : object.worldTriangles.data();
        desc.name = object.identity.c_str();
        require(osgvis_scene_add_object(context.get(), &desc, nullptr));
    }
    if (hierarchy)
    {
        const osgvis_hierarchy_desc desc = hierarchy->desc();
        require(osgvis_scene_set_hierarchy(context.get(), &desc));
    }
    require(osgvis_context_set_mode(context.get(), mode.c_str()));
    return context;
}

// FNV-1a over the bits of an object's world triangles: equal hashes, equal triangles.
std::uint64_t triangleHash(const std::vector<float>& triangles)
{
    std::uint64_t hash = 1469598103934665603ull;
    for (float value : triangles)
    {
        std::uint32_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        for (int b = 0; b < 4; ++b)
        {
            hash ^= (bits >> (8 * b)) & 0xffu;
            hash *= 1099511628211ull;
        }
    }
    return hash;
}

void writeObjects(const std::filesystem::path& path, const RawScene& scene)
{
    std::ofstream out(path);
    out << "# osgvis-objects 1\n# objects " << scene.objects.size() << "\n";
    char line[512];
    for (const RawObject& o : scene.objects)
    {
        std::snprintf(line, sizeof line,
                      " flags %u triangles %u bounds %.17g %.17g %.17g %.17g %.17g %.17g hash %016llx", o.flags,
                      o.triangleCount(), o.boundsMin[0], o.boundsMin[1], o.boundsMin[2], o.boundsMax[0], o.boundsMax[1],
                      o.boundsMax[2], static_cast<unsigned long long>(triangleHash(o.worldTriangles)));
        out << o.identity << line << "\n";
    }
    if (!out)
        throw RunError("cannot write '" + path.string() + "'");
}

std::string walkPathFor(const RawOptions& options)
{
    if (!options.walk.empty())
        return options.walk;
    std::filesystem::path beside(options.model);
    beside.replace_extension(".walk");
    if (std::filesystem::exists(beside))
        return beside.string();
    throw RunError("no walk: '" + beside.string() + "' does not exist; give --walk FILE (osgvisbench --scene " +
                   options.model + " --save-walk FILE writes one)");
}

double median(std::vector<double> values)
{
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// The model, which must exist and hold something to draw.
RawScene loadScene(const std::string& model)
{
    if (!std::filesystem::is_regular_file(model))
        throw RunError("cannot read model '" + model + "': no such file");
    RawScene scene = loadRawScene(model);
    if (scene.objects.empty())
        throw RunError("model '" + model + "' has no mesh primitives: nothing to draw");
    return scene;
}

osgVis::core::Walk loadWalk(const RawOptions& options)
{
    try
    {
        return osgVis::core::Walk::load(walkPathFor(options));
    }
    catch (const osgVis::core::WalkError& e)
    {
        throw RunError(e.what());
    }
}

std::vector<ModeRun> makeModes(const RawOptions& options, const RawScene& scene, RawHierarchy* hierarchy)
{
    std::vector<ModeRun> modes;
    for (const std::string& name : options.modes)
    {
        ModeRun mode;
        mode.name = name;
        mode.conservative = name.find("approx") == std::string::npos;
        mode.context = makeContext(scene, name, hierarchy);
        modes.push_back(std::move(mode));
    }
    return modes;
}

// --dump-visible DIR: the objects, and per mode a file that each view's visible set is added to.
void openDumps(const std::string& dumpDir, const RawScene& scene, const osgVis::core::Walk& walk,
               std::vector<ModeRun>& modes)
{
    std::error_code error;
    std::filesystem::create_directories(dumpDir, error);
    if (!std::filesystem::is_directory(dumpDir))
        throw RunError("cannot create the folder '" + dumpDir + "'");
    writeObjects(std::filesystem::path(dumpDir) / "objects.txt", scene);
    for (ModeRun& mode : modes)
    {
        const std::filesystem::path path = std::filesystem::path(dumpDir) / (mode.name + ".visible");
        mode.dump.open(path);
        if (!mode.dump)
            throw RunError("cannot write '" + path.string() + "'");
        mode.dump << "# osgvis-visible 1\n# mode " << mode.name << " views " << walk.keys.size() << " objects "
                  << scene.objects.size() << "\n";
    }
}

// What the views of the walk share: buffers reused from view to view and mode to mode.
struct WalkFrames
{
    std::vector<std::uint8_t> unculled, culled;
    std::vector<std::uint32_t> ids;
    std::vector<bool> drawn;
    std::vector<std::string> names;
    std::size_t coveredPixels = 0, framePixels = 0; // of the unculled frames: is there anything to compare?
};

// Draws every object: the frame each mode's frame is compared with.
void renderUnculled(RawRenderer& renderer, const glm::dmat4& view, const glm::dmat4& projection, WalkFrames& frames)
{
    renderer.render(view, projection, {});
    renderer.readPixels(frames.unculled);
    for (std::size_t p = 0; p + 3 < frames.unculled.size(); p += 4)
        frames.coveredPixels += std::memcmp(&frames.unculled[p], RawRenderer::ClearColor, 4) != 0;
    frames.framePixels += frames.unculled.size() / 4;
}

osgvis_view_desc viewDesc(const osgVis::core::Walk& walk, const osgVis::core::WalkKey& key, const glm::dmat4& view,
                          const glm::dmat4& projection)
{
    osgvis_view_desc desc{};
    std::memcpy(desc.view_matrix, glm::value_ptr(view), sizeof desc.view_matrix);
    std::memcpy(desc.projection_matrix, glm::value_ptr(projection), sizeof desc.projection_matrix);
    desc.time = key.time;
    desc.viewport_width = walk.width;
    desc.viewport_height = walk.height;
    return desc;
}

// Culls view v in one mode: its figures, its visible set in frames.drawn and its line of the dump.
void cullView(ModeRun& mode, const osgvis_view_desc& desc, std::size_t v, const RawScene& scene, WalkFrames& frames)
{
    require(osgvis_cull(mode.context.get(), &desc));
    size_t written = 0, count = 0;
    require(osgvis_visible_ids(mode.context.get(), frames.ids.data(), frames.ids.size(), &written, &count));
    osgvis_statistics statistics{};
    require(osgvis_statistics_get(mode.context.get(), &statistics));
    mode.cullMs.push_back(statistics.cull_milliseconds);
    mode.visibleSum += double(written);
    std::fill(frames.drawn.begin(), frames.drawn.end(), false);
    frames.names.clear();
    for (std::size_t i = 0; i < written; ++i)
    {
        frames.drawn[frames.ids[i]] = true;
        frames.names.push_back(scene.objects[frames.ids[i]].identity);
    }
    if (mode.dump.is_open())
    {
        std::sort(frames.names.begin(), frames.names.end());
        mode.dump << v << " " << frames.names.size();
        for (const std::string& name : frames.names)
            mode.dump << " " << name;
        mode.dump << "\n";
    }
}

// Counts the pixels of the frame just drawn that differ from the unculled frame.
void compareWithUnculled(ModeRun& mode, RawRenderer& renderer, WalkFrames& frames)
{
    renderer.readPixels(frames.culled);
    std::size_t differing = 0;
    for (std::size_t p = 0; p + 3 < frames.culled.size(); p += 4)
        differing += std::memcmp(&frames.culled[p], &frames.unculled[p], 4) != 0;
    mode.differingPixels += differing;
    mode.viewsWithDifferences += differing != 0;
}

// Every view of the walk (until the window closes), culled and drawn in every mode.
void runWalk(const RawOptions& options, const RawScene& scene, const osgVis::core::Walk& walk,
             std::vector<ModeRun>& modes, RawRenderer& renderer, WalkFrames& frames)
{
    const glm::dmat4 projection = walk.projection.matrix(walk.aspect());
    for (std::size_t v = 0; v < walk.keys.size() && renderer.open(); ++v)
    {
        const osgVis::core::WalkKey& key = walk.keys[v];
        const glm::dmat4 view = key.viewMatrix();
        if (options.pixels)
            renderUnculled(renderer, view, projection, frames);
        const osgvis_view_desc desc = viewDesc(walk, key, view, projection);
        for (ModeRun& mode : modes)
        {
            cullView(mode, desc, v, scene, frames);
            renderer.render(view, projection, frames.drawn);
            if (options.pixels)
                compareWithUnculled(mode, renderer, frames);
        }
    }
}

void printModeRow(const ModeRun& mode, bool pixels)
{
    const std::size_t views = mode.cullMs.size();
    std::cout << std::left << std::setw(24) << mode.name << std::right << std::setw(7) << views << std::setw(12)
              << std::fixed << std::setprecision(1) << (views ? mode.visibleSum / double(views) : 0.0) << std::setw(10)
              << std::setprecision(3) << median(mode.cullMs);
    if (pixels)
        std::cout << std::setw(19) << mode.differingPixels << " (" << mode.viewsWithDifferences << ")";
    std::cout << "\n";
}

// Prints the table of the modes and closes their dumps; 1 where a conservative mode drew a pixel differently.
int report(const RawOptions& options, std::vector<ModeRun>& modes, const WalkFrames& frames)
{
    int status = 0;
    if (options.pixels)
        std::cout << "unculled frames: " << std::fixed << std::setprecision(1)
                  << (frames.framePixels ? 100.0 * double(frames.coveredPixels) / double(frames.framePixels) : 0.0)
                  << "% of the pixels show an object\n";
    std::cout << std::left << std::setw(24) << "mode" << std::right << std::setw(7) << "views" << std::setw(12)
              << "visible" << std::setw(10) << "cull ms" << (options.pixels ? "   pixels differing (views)" : "")
              << "\n";
    for (ModeRun& mode : modes)
    {
        printModeRow(mode, options.pixels);
        if (mode.dump.is_open())
        {
            mode.dump.close();
            if (!mode.dump)
                throw RunError("cannot write the visible sets of mode '" + mode.name + "'");
        }
        if (options.pixels && mode.conservative && mode.differingPixels != 0)
        {
            std::cerr << "osgvisrawgl: FAIL: conservative mode '" << mode.name << "' drew " << mode.differingPixels
                      << " pixels differently from the unculled frame in " << mode.viewsWithDifferences << " views"
                      << std::endl;
            status = 1;
        }
    }
    std::cout.flush();
    return status;
}

int run(const RawOptions& options)
{
    const RawScene scene = loadScene(options.model);
    const osgVis::core::Walk walk = loadWalk(options);
    std::unique_ptr<RawHierarchy> hierarchy = options.hierarchy ? std::make_unique<RawHierarchy>(scene) : nullptr;
    std::vector<ModeRun> modes = makeModes(options, scene, hierarchy.get());
    if (!options.dumpDir.empty())
        openDumps(options.dumpDir, scene, walk, modes);
    std::cerr << "scene: " << options.model << " (" << scene.objects.size() << " objects), walk: " << walk.keys.size()
              << " views at " << walk.width << "x" << walk.height << std::endl;

    RawRenderer renderer(scene, walk.width, walk.height, options.show);
    WalkFrames frames;
    frames.ids.resize(scene.objects.size());
    frames.drawn.resize(scene.objects.size());
    runWalk(options, scene, walk, modes, renderer, frames);
    return report(options, modes, frames);
}
} // namespace

int main(int argc, char** argv)
{
    RawOptions options;
    const std::string usage = rawUsage(); // after a bad command line, too
    if (const std::optional<int> status =
            osgVis::apps::readCommandLine(options, parseRawOptions, argc, argv, "osgvisrawgl", usage, usage))
        return *status;
    try
    {
        return run(options);
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvisrawgl: error: " << e.what() << std::endl;
        return 1;
    }
}
