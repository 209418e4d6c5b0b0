// SPDX-License-Identifier: MIT
#include "OracleCache.h"

#include "Fnv1a.h"

#include <osgVis/core/scene/SceneFingerprint.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace osgVis::bench
{
namespace
{
constexpr char Magic[8] = {'O', 'S', 'G', 'V', 'O', 'R', 'C', '1'};

template <typename T> std::uint64_t mixValue(std::uint64_t hash, const T& value)
{
    return fnv1a(hash, &value, sizeof value);
}

std::uint64_t mixMatrix(std::uint64_t hash, const osg::Matrixd& matrix)
{
    return fnv1a(hash, matrix.ptr(), 16 * sizeof(double));
}

class Writer
{
public:
    explicit Writer(std::ofstream& out) : _out(out) {}
    template <typename T> void value(const T& v) { _out.write(reinterpret_cast<const char*>(&v), sizeof v); }

private:
    std::ofstream& _out;
};

// Reads what Writer wrote; any read past the end or count out of range makes ok() false.
class Reader
{
public:
    explicit Reader(std::ifstream& in) : _in(in) {}
    template <typename T> T value()
    {
        T v{};
        _in.read(reinterpret_cast<char*>(&v), sizeof v);
        _ok = _ok && bool(_in);
        return v;
    }
    // A count no larger than `limit` (counts bound what the file may make us allocate).
    std::uint32_t count(std::uint64_t limit)
    {
        const std::uint32_t n = value<std::uint32_t>();
        if (n > limit)
            _ok = false;
        return _ok ? n : 0;
    }
    bool ok() const { return _ok; }

private:
    std::ifstream& _in;
    bool _ok = true;
};

void writeView(Writer& out, const ViewReference& view)
{
    out.value(view.unknownVisible);
    const std::vector<core::ObjectId> exact = view.exact.ids();
    out.value(std::uint32_t(exact.size()));
    for (core::ObjectId id : exact)
        out.value(id);
    out.value(std::uint32_t(view.pixels.size()));
    for (const ObjectPixels& p : view.pixels)
    {
        out.value(p.id);
        out.value(p.pixels);
        out.value(p.clusters);
    }
}

bool readView(Reader& in, std::size_t objectCount, ViewReference& view)
{
    view.unknownVisible = in.value<std::uint32_t>();
    view.exact.reset(objectCount);
    const std::uint32_t exact = in.count(objectCount);
    for (std::uint32_t i = 0; i < exact && in.ok(); ++i)
    {
        const auto id = in.value<core::ObjectId>();
        if (id >= objectCount)
            return false;
        view.exact.set(id);
    }
    const std::uint32_t pixels = in.count(objectCount + (std::uint64_t(1) << 20));
    view.pixels.resize(pixels);
    for (ObjectPixels& p : view.pixels)
    {
        p.id = in.value<core::ObjectId>();
        p.pixels = in.value<std::uint32_t>();
        p.clusters = in.value<std::uint32_t>();
        if (p.id != core::InvalidObject && p.id >= objectCount)
            return false;
    }
    return in.ok();
}
} // namespace

std::uint64_t oracleCacheKey(const ExtractedScene& withTriangles, const std::vector<BenchView>& views,
                             unsigned width, unsigned height, unsigned supersample)
{
    std::uint64_t hash = Fnv1aSeed;
    hash = mixValue(hash, core::sceneGeometryFingerprint(withTriangles.scene));
    hash = mixValue(hash, std::uint64_t(withTriangles.scene.objects.size()));
    hash = mixValue(hash, std::uint64_t(views.size()));
    for (const BenchView& view : views)
        hash = mixMatrix(mixMatrix(hash, view.view), view.projection);
    hash = mixValue(hash, std::uint64_t(width));
    hash = mixValue(hash, std::uint64_t(height));
    return mixValue(hash, std::uint64_t(supersample));
}

std::string oracleCacheFile(const std::string& dir, std::uint64_t key)
{
    char name[40];
    std::snprintf(name, sizeof name, "oracle-%016llx.bin", static_cast<unsigned long long>(key));
    return (std::filesystem::path(dir) / name).string();
}

std::optional<OracleReference> loadOracleReference(const std::string& file, std::uint64_t key,
                                                   std::size_t objectCount)
{
    std::ifstream stream(file, std::ios::binary);
    if (!stream)
        return std::nullopt;
    Reader in(stream);
    char magic[sizeof Magic];
    stream.read(magic, sizeof magic);
    OracleReference reference;
    bool ok = bool(stream) && std::memcmp(magic, Magic, sizeof Magic) == 0 && in.value<std::uint64_t>() == key &&
              in.value<std::uint64_t>() == objectCount;
    if (ok)
    {
        reference.supersample = in.value<std::uint32_t>();
        reference.pixelCounts = in.value<std::uint8_t>() != 0;
        reference.supersampleExtras = in.value<std::uint64_t>();
        const std::uint32_t views = in.count(1u << 24);
        reference.views.resize(views);
        for (std::uint32_t v = 0; v < views && ok; ++v)
            ok = readView(in, objectCount, reference.views[v]);
        const std::uint32_t extras = in.count(views);
        for (std::uint32_t i = 0; i < extras && ok; ++i)
            reference.viewsWithSupersampleExtras.push_back(in.value<std::uint32_t>());
        ok = ok && in.ok() && in.value<std::uint32_t>() == 0x454e4421u; // "END!": the file is whole
    }
    if (!ok)
    {
        std::cerr << "osgvisbench: ignoring the cached oracle " << file
                  << ": not a cache file of this scene and walk, or damaged; rendering the oracle again" << std::endl;
        return std::nullopt;
    }
    return reference;
}

void saveOracleReference(const std::string& file, std::uint64_t key, const OracleReference& reference)
{
    const std::filesystem::path path(file);
    if (path.has_parent_path())
        std::filesystem::create_directories(path.parent_path());
    const std::string temporary = file + ".part";
    {
        std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
        if (!stream)
            throw std::runtime_error("cannot write the oracle cache file " + temporary);
        stream.write(Magic, sizeof Magic);
        Writer out(stream);
        out.value(key);
        out.value(std::uint64_t(reference.views.empty() ? 0 : reference.views.front().exact.capacity()));
        out.value(std::uint32_t(reference.supersample));
        out.value(std::uint8_t(reference.pixelCounts ? 1 : 0));
        out.value(reference.supersampleExtras);
        out.value(std::uint32_t(reference.views.size()));
        for (const ViewReference& view : reference.views)
            writeView(out, view);
        out.value(std::uint32_t(reference.viewsWithSupersampleExtras.size()));
        for (std::uint32_t v : reference.viewsWithSupersampleExtras)
            out.value(v);
        out.value(std::uint32_t(0x454e4421u));
        if (!stream.flush())
            throw std::runtime_error("cannot write the oracle cache file " + temporary);
    }
    std::filesystem::rename(temporary, file);
}

OracleReference cachedOracleReference(const std::string& dir, osg::Node& root, const ExtractedScene& scene,
                                      const std::vector<BenchView>& views, unsigned width, unsigned height,
                                      unsigned supersample)
{
    const osg::ref_ptr<ExtractedScene> withTriangles = extractScene(root, ExtractionOptions{true});
    const std::uint64_t key = oracleCacheKey(*withTriangles, views, width, height, supersample);
    const std::string file = oracleCacheFile(dir, key);
    if (std::optional<OracleReference> cached = loadOracleReference(file, key, scene.scene.objects.size()))
    {
        std::cerr << "osgvisbench: oracle: " << views.size() << " views from the cache " << file << std::endl;
        addFrustumSets(*cached, scene.scene, views);
        return std::move(*cached);
    }
    OracleReference reference = computeOracleReference(root, scene, views, width, height, supersample);
    saveOracleReference(file, key, reference);
    return reference;
}
} // namespace osgVis::bench
