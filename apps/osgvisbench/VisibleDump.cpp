// SPDX-License-Identifier: MIT
#include "VisibleDump.h"

#include "BenchRun.h"
#include "BenchView.h"
#include "TextFile.h"

#include <GltfIdentity.h>
#include <SceneSource.h>

#include <osgVis/core/api/ModuleRegistry.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace osgVis::bench
{
namespace
{
// The glTF identity of every object; "o<id>" for an object that has none (a model from another loader).
std::vector<std::string> identities(const ExtractedScene& scene)
{
    std::vector<std::string> names;
    names.reserve(scene.refs.size());
    for (std::size_t id = 0; id < scene.refs.size(); ++id)
    {
        std::string name = apps::gltfIdentity(scene.refs[id]);
        names.push_back(name.empty() ? "o" + std::to_string(id) : name);
    }
    return names;
}
// FNV-1a over the bits of an object's world triangles (osgvisrawgl hashes its own the same way).
std::uint64_t triangleHash(const core::Scene& scene, const core::SceneObject& object)
{
    std::uint64_t hash = 1469598103934665603ull;
    for (std::uint32_t t = 0; t < object.triangleCount; ++t)
    {
        const core::Triangle& triangle = scene.triangles[object.firstTriangle + t];
        for (const core::Vec3f* corner : {&triangle.a, &triangle.b, &triangle.c})
            for (int i = 0; i < 3; ++i)
            {
                std::uint32_t bits;
                const float value = (*corner)[i];
                std::memcpy(&bits, &value, sizeof bits);
                for (int b = 0; b < 4; ++b)
                {
                    hash ^= (bits >> (8 * b)) & 0xffu;
                    hash *= 1099511628211ull;
                }
            }
    }
    return hash;
}

// DIR/objects.txt: what culling got of every object, to tell why two visible sets differ.
void writeObjects(const std::filesystem::path& path, const core::Scene& scene, const std::vector<std::string>& names)
{
    std::ofstream out(path);
    out << "# osgvis-objects 1\n# objects " << scene.objects.size() << "\n";
    char line[512];
    for (const core::SceneObject& o : scene.objects)
    {
        std::snprintf(
            line, sizeof line, " flags %u triangles %u bounds %.17g %.17g %.17g %.17g %.17g %.17g hash %016llx",
            unsigned(o.flags), unsigned(o.triangleCount), o.bounds.min.x, o.bounds.min.y, o.bounds.min.z,
            o.bounds.max.x, o.bounds.max.y, o.bounds.max.z, static_cast<unsigned long long>(triangleHash(scene, o)));
        out << names[o.id] << line << "\n";
    }
    if (!out)
        throw std::runtime_error("cannot write '" + path.string() + "'");
}
} // namespace

void writeVisibleDumps(const BenchOptions& options, const std::vector<BenchMode>& modes, std::ostream& out)
{
    for (const BenchMode& mode : modes)
        if (mode.kind != BenchMode::Kind::ModuleChain)
            throw UsageError("--dump-visible writes what a module chain answers; '" + mode.name + "' is none");
    createFolder(options.dumpVisibleDir, "folder");

    const apps::LoadedScene loaded = loadBenchScene(options);
    if (!options.saveWalkFile.empty())
        loaded.walk.save(options.saveWalkFile);
    const core::Walk walk = benchWalk(loaded.walk, options);
    const std::vector<core::View> views = makeCoreViews(walk);
    // note: the extraction a VisibilityGroup's ViewCuller makes (default options keep the triangles);
    // the bench's shared extraction keeps none, which object-space occluders need.
    const osg::ref_ptr<ExtractedScene> scene = extractScene(*loaded.model);
    const std::vector<std::string> names = identities(*scene);
    writeObjects(std::filesystem::path(options.dumpVisibleDir) / "objects.txt", scene->scene, names);

    for (const BenchMode& mode : modes)
    {
        core::ModuleChain chain = core::createChain(mode.chain);
        chain.setScene(scene->scene);
        const std::filesystem::path path = std::filesystem::path(options.dumpVisibleDir) / (mode.name + ".visible");
        std::ofstream file(path);
        file << "# osgvis-visible 1\n# mode " << mode.name << " views " << views.size() << " objects " << names.size()
             << "\n";
        core::VisibleSet visible;
        std::vector<std::string> line;
        for (std::size_t v = 0; v < views.size(); ++v)
        {
            chain.cull(views[v], visible);
            line.clear();
            for (std::size_t id = 0; id < names.size(); ++id)
                if (visible.test(core::ObjectId(id)))
                    line.push_back(names[id]);
            std::sort(line.begin(), line.end());
            file << v << " " << line.size();
            for (const std::string& name : line)
                file << " " << name;
            file << "\n";
        }
        file.close();
        if (!file)
            throw std::runtime_error("cannot write '" + path.string() + "'");
        out << "visible sets: " << path.string() << " (" << views.size() << " views, " << names.size() << " objects)"
            << std::endl;
    }
}
} // namespace osgVis::bench
