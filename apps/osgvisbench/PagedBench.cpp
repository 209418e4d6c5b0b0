// SPDX-License-Identifier: MIT
#include "PagedBench.h"

#include "BenchRun.h"
#include "BenchView.h"
#include "BenchViewer.h"
#include "DerivedWalks.h"
#include "EmittedObjects.h"
#include "ModeGraph.h"
#include "Progress.h"
#include "SampleStatistics.h"

#include <osgVis/ClusterDraw>
#include <osgVis/VisibilityGroup>
#include <osgVis/oracle/IdBufferOracle.h>
#include <osgVis/core/cellportal/CellPortalModule.h>
#include <osgVis/core/pvs/PvsFormat.h>

#include <osg/NodeVisitor>
#include <osg/PagedLOD>
#include <osgDB/DatabasePager>
#include <osgDB/ReadFile>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <malloc.h>
#include <mutex>
#include <set>
#include <stdexcept>
#include <unordered_map>

namespace osgVis::bench
{
namespace
{
// The paged nodes under `root` in depth-first order: the tile numbering of one read of the root file.
std::vector<osg::PagedLOD*> pagedNodesOf(osg::Node& root)
{
    struct Collector : osg::NodeVisitor
    {
        Collector() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        std::vector<osg::PagedLOD*> found;
        void apply(osg::PagedLOD& node) override
        {
            found.push_back(&node);
            traverse(node);
        }
    } collector;
    root.accept(collector);
    return collector.found;
}

// A tile's drawables in depth-first order, the order the oracle numbers them in.
std::vector<const osg::Drawable*> drawablesOf(osg::Node& tile)
{
    struct Collector : osg::NodeVisitor
    {
        Collector() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        std::vector<const osg::Drawable*> found;
        void apply(osg::Drawable& drawable) override { found.push_back(&drawable); }
    } collector;
    tile.accept(collector);
    return collector.found;
}

std::string tilePath(const osg::PagedLOD& node)
{
    return node.getDatabasePath() + node.getFileName(0);
}

// OSG's pager, counting the files it is asked for (from cull threads).
class CountingPager : public osgDB::DatabasePager
{
public:
    void requestNodeFile(const std::string& fileName, osg::NodePath& nodePath, float priority,
                         const osg::FrameStamp* framestamp, osg::ref_ptr<osg::Referenced>& databaseRequest,
                         const osg::Referenced* options) override
    {
        {
            std::lock_guard<std::mutex> lock(_mutex);
            _files.insert(fileName);
        }
        osgDB::DatabasePager::requestNodeFile(fileName, nodePath, priority, framestamp, databaseRequest, options);
    }
    std::size_t filesRequested() const
    {
        std::lock_guard<std::mutex> lock(_mutex);
        return _files.size();
    }

protected:
    ~CountingPager() override = default;

private:
    mutable std::mutex _mutex;
    std::set<std::string> _files;
};

// Bytes the heap holds now (glibc): what the loaded tiles, their GL copies in llvmpipe and
// osgVis's extractions take, unlike the resident set, which freed memory does not shrink.
double heapBytes()
{
    const struct mallinfo2 info = mallinfo2();
    return double(info.uordblks) + double(info.hblkhd);
}

// The fully loaded database as the oracle sees it: every tile read and added to its node.
struct FullDatabase
{
    osg::ref_ptr<osg::Node> root;
    std::vector<std::uint32_t> firstObject, objectCount; // per tile, in the oracle's numbering
    std::vector<std::uint32_t> tileOfObject;             // per oracle object; ~0u: in no tile
    std::vector<osg::Matrixd> world;                     // per oracle object: local to root
    std::vector<std::uint64_t> tileBytes;
};

FullDatabase loadFullDatabase(const std::string& rootFile)
{
    FullDatabase full;
    full.root = osgDB::readRefNodeFile(rootFile);
    if (!full.root)
        throw std::runtime_error("cannot read the paged database '" + rootFile + "'");
    const std::vector<osg::PagedLOD*> tiles = pagedNodesOf(*full.root);
    if (tiles.empty())
        throw std::runtime_error("'" + rootFile + "' holds no osg::PagedLOD: no paged database (osgvisgen --paged)");
    for (osg::PagedLOD* node : tiles)
    {
        if (node->getNumChildren() != 0 || node->getNumFileNames() != 1)
            throw std::runtime_error("tile '" + node->getName() +
                                     "': the paged bench reads PagedLODs with one paged child each");
        osg::ref_ptr<osg::Node> tile = osgDB::readRefNodeFile(tilePath(*node));
        if (!tile)
            throw std::runtime_error("cannot read tile '" + tilePath(*node) + "'");
        node->addChild(tile.get());
        std::error_code error;
        full.tileBytes.push_back(std::filesystem::file_size(tilePath(*node), error));
    }
    return full;
}

struct PagedRow
{
    std::string mode;
    bool conservative = true;
    std::size_t filesRequested = 0, loads = 0, expiries = 0, peakResident = 0;
    double bytesRead = 0, peakHeapBytes = 0;
    std::size_t popInFrames = 0, popInObjects = 0, falseInvisible = 0, framesWithFalseInvisible = 0;
    std::uint64_t popInPixels = 0;
    double medianFrameSeconds = 0;
};

// What a mode's run knows of the tiles from frame to frame.
struct TileResidency
{
    explicit TileResidency(std::size_t tiles) : resident(tiles, false), drawables(tiles) {}

    std::vector<bool> resident;
    std::vector<std::vector<const osg::Drawable*>> drawables;
    // A drawable may be drawn more than once in a tile: its instances, told apart by matrix.
    std::unordered_map<const osg::Drawable*, std::vector<std::uint32_t>> objectsOf;
};

// Counts the tiles loaded and expired since the last frame and maps the drawables of those loaded to
// their oracle objects; returns how many tiles are resident.
std::size_t updateResidency(const std::vector<osg::PagedLOD*>& tiles, const FullDatabase& full,
                            TileResidency& residency, PagedRow& row)
{
    std::size_t residentNow = 0;
    for (std::size_t t = 0; t < tiles.size(); ++t)
    {
        const bool now = tiles[t]->getNumChildren() > 0;
        residentNow += now;
        std::vector<const osg::Drawable*>& drawables = residency.drawables[t];
        if (now && !residency.resident[t])
        {
            ++row.loads;
            row.bytesRead += double(full.tileBytes[t]);
            drawables = drawablesOf(*tiles[t]->getChild(0));
            if (drawables.size() != full.objectCount[t])
                throw std::runtime_error("tile '" + tilePath(*tiles[t]) + "' loaded with other drawables than before");
            for (std::size_t d = 0; d < drawables.size(); ++d)
                residency.objectsOf[drawables[d]].push_back(full.firstObject[t] + std::uint32_t(d));
        }
        else if (!now && residency.resident[t])
        {
            ++row.expiries;
            for (const osg::Drawable* d : drawables)
                residency.objectsOf.erase(d);
            drawables.clear();
        }
        residency.resident[t] = now;
    }
    return residentNow;
}

// Marks the oracle objects the last frame drew: a drawable's instance is the one whose world matrix
// is nearest the leaf's.
void markEmitted(const osgUtil::RenderStage& stage, const osg::Matrixd& viewMatrix, const TileResidency& residency,
                 const FullDatabase& full, std::vector<bool>& emitted)
{
    std::fill(emitted.begin(), emitted.end(), false);
    const osg::Matrixd inverseView = osg::Matrixd::inverse(viewMatrix);
    forEachRenderLeaf(stage, [&](const osgUtil::RenderLeaf& leaf) {
        const osg::Drawable* drawable = leaf.getDrawable();
        if (const auto* part = dynamic_cast<const ClusterDraw*>(drawable))
            drawable = part->original();
        const auto found = residency.objectsOf.find(drawable);
        if (found == residency.objectsOf.end() || !leaf._modelview.valid())
            return;
        const osg::Matrixd model = *leaf._modelview * inverseView;
        std::uint32_t nearest = found->second.front();
        double nearestDifference = std::numeric_limits<double>::max();
        for (std::uint32_t object : found->second)
        {
            double difference = 0.0;
            for (int i = 0; i < 16; ++i)
                difference = std::max(difference, std::abs(model.ptr()[i] - full.world[object].ptr()[i]));
            if (difference < nearestDifference)
                nearest = object, nearestDifference = difference;
        }
        emitted[nearest] = true;
    });
}

// The objects the oracle sees in a view that the mode missed: in a tile not loaded (pop-in), or in
// a loaded tile but not drawn (false invisible).
void countMisses(const oracle::IdBufferOracle::Result& seen, const FullDatabase& full,
                 const std::vector<bool>& resident, const std::vector<bool>& emitted, PagedRow& row)
{
    bool popIn = false, missed = false;
    for (std::size_t i = 0; i < seen.visible.size(); ++i)
    {
        const std::uint32_t object = seen.visible[i];
        const std::uint32_t tile = full.tileOfObject[object];
        if (tile == ~0u)
            continue;
        if (!resident[tile])
        {
            popIn = true;
            ++row.popInObjects;
            row.popInPixels += seen.pixels[i];
        }
        else if (!emitted[object])
        {
            missed = true;
            ++row.falseInvisible;
        }
    }
    row.popInFrames += popIn;
    row.framesWithFalseInvisible += missed;
}

PagedRow runMode(const BenchMode& mode, const BenchOptions& options, const std::string& rootFile,
                 const FullDatabase& full, const std::vector<BenchView>& views, const core::Walk& walk,
                 const std::vector<oracle::IdBufferOracle::Result>& seen)
{
    PagedRow row;
    row.mode = mode.name;
    row.conservative = mode.conservative;
    const double heapBefore = heapBytes();
    osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(rootFile);
    if (!model)
        throw std::runtime_error("cannot read the paged database '" + rootFile + "'");
    const std::vector<osg::PagedLOD*> tiles = pagedNodesOf(*model);
    if (tiles.size() != full.firstObject.size())
        throw std::runtime_error("'" + rootFile + "' changed while the bench ran");
    osg::ref_ptr<ExtractedScene> none = new ExtractedScene; // module chains need no extraction here
    osg::ref_ptr<osg::Node> graph = buildModeGraph(mode, *model, *none, false, {}, options.backOff);
    if (auto* group = dynamic_cast<VisibilityGroup*>(graph.get()))
        group->setPagingOptions(options.paging);

    BenchViewer viewer(walk.width, walk.height, walk.projection, *model);
    osg::ref_ptr<CountingPager> pager = new CountingPager;
    viewer.setDatabasePager(pager.get());
    viewer.setSceneData(graph.get());

    TileResidency residency(tiles.size());
    std::vector<double> frameSeconds;
    std::vector<bool> emitted(full.tileOfObject.size());
    Progress progress(mode.name + " (paged)", views.size());
    for (std::size_t v = 0; v < views.size(); ++v)
    {
        frameSeconds.push_back(viewer.renderFrame(views[v]).seconds);
        // The update traversal of this frame merged and expired before its cull: what is resident now
        // is what the frame could draw.
        const std::size_t residentNow = updateResidency(tiles, full, residency, row);
        row.peakResident = std::max(row.peakResident, residentNow);
        row.peakHeapBytes = std::max(row.peakHeapBytes, heapBytes() - heapBefore);
        markEmitted(viewer.lastRenderStage(), views[v].view, residency, full, emitted);
        countMisses(seen[v], full, residency.resident, emitted, row);
        progress.advance(v + 1);
    }
    row.filesRequested = pager->filesRequested();
    std::sort(frameSeconds.begin(), frameSeconds.end());
    row.medianFrameSeconds = median(frameSeconds).value_or(0.0);
    return row;
}

void writeJson(const std::string& path, const BenchOptions& options, const std::string& scene, std::size_t tiles,
               std::size_t tilesSeen, std::size_t views, const core::Walk& walk, const std::vector<PagedRow>& rows)
{
    std::ofstream out(path);
    if (!out)
        throw std::runtime_error("cannot write '" + path + "'");
    const auto quoted = [](const std::string& text) {
        std::string q = "\"";
        for (char c : text)
            q += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
        return q + "\"";
    };
    out << "{\n  \"kind\": \"paged\",\n  \"command\": " << quoted(options.commandLine) << ",\n  \"scene\": "
        << quoted(scene) << ",\n  \"tiles\": " << tiles << ",\n  \"tiles_seen_by_oracle\": " << tilesSeen
        << ",\n  \"osg_max_pagedlod\": " << quoted(std::getenv("OSG_MAX_PAGEDLOD") ? std::getenv("OSG_MAX_PAGEDLOD") : "")
        << ",\n  \"views\": " << views << ",\n  \"width\": "
        << walk.width << ",\n  \"height\": " << walk.height << ",\n  \"modes\": [\n";
    for (std::size_t r = 0; r < rows.size(); ++r)
    {
        const PagedRow& row = rows[r];
        out << "    {\"mode\": " << quoted(row.mode) << ", \"files_requested\": " << row.filesRequested
            << ", \"tiles_loaded\": " << row.loads << ", \"tiles_expired\": " << row.expiries
            << ", \"bytes_read\": " << std::uint64_t(row.bytesRead) << ", \"peak_resident_tiles\": " << row.peakResident
            << ", \"peak_heap_bytes\": " << std::uint64_t(row.peakHeapBytes) << ", \"pop_in_frames\": " << row.popInFrames
            << ", \"pop_in_objects\": " << row.popInObjects << ", \"pop_in_pixels\": " << row.popInPixels
            << ", \"false_invisible\": " << row.falseInvisible
            << ", \"views_with_false_invisible\": " << row.framesWithFalseInvisible
            << ", \"median_frame_ms\": " << row.medianFrameSeconds * 1000.0 << "}" << (r + 1 < rows.size() ? "," : "")
            << "\n";
    }
    out << "  ]\n}\n";
}

// `--scene DIR/x.pvs`: a cell-portal bake of the whole database (osgvispvs on its root file). Its
// data are registered, where cellportal modes find them for every load state, and the root file it
// names is what the bench pages; the plugin is not used, as it would put a culling group above it.
BenchOptions withBakedDatabase(const BenchOptions& options)
{
    const std::string& file = options.sceneFile;
    if (file.size() < 4 || file.compare(file.size() - 4, 4, ".pvs") != 0)
        return options;
    core::PvsFile pvs = core::readPvsFile(file);
    if (!pvs.hasCellPortal || !pvs.data.tiles || pvs.sourceRange)
        throw std::runtime_error("'" + file + "' holds no cell-portal bake of a whole paged database (osgvispvs " +
                                 "DIR/root.osgb -o " + file + ")");
    BenchOptions rooted = options;
    const std::filesystem::path model(pvs.modelPath);
    rooted.sceneFile =
        (model.is_absolute() ? model : std::filesystem::path(file).parent_path() / model).lexically_normal().string();
    core::registerBakedCellPortalData(std::make_shared<const core::CellPortalData>(std::move(pvs.data)));
    return rooted;
}
} // namespace

int runPagedBench(const BenchOptions& givenOptions, const std::vector<BenchMode>& modes, std::ostream& out)
{
    for (const BenchMode& mode : modes)
        if (mode.kind != BenchMode::Kind::OsgDefault && mode.kind != BenchMode::Kind::ModuleChain)
            throw UsageError("--paged runs osg and module-chain modes; '" + mode.name + "' is neither");
    const BenchOptions options = withBakedDatabase(givenOptions);
    const apps::LoadedScene scene = loadBenchScene(options);
    const core::Walk walk = subsampledWalk(scene.walk, options.views);
    const std::vector<BenchView> views = makeBenchViews(walk);

    FullDatabase full = loadFullDatabase(options.sceneFile);
    oracle::OracleSettings settings;
    settings.width = walk.width;
    settings.height = walk.height;
    settings.supersample = options.supersample;
    std::vector<oracle::IdBufferOracle::Result> seen;
    {
        oracle::IdBufferOracle oracle(full.root.get(), settings);
        // Tile of each oracle object: the paged node on its path.
        const std::vector<osg::PagedLOD*> tiles = pagedNodesOf(*full.root);
        std::unordered_map<const osg::Node*, std::uint32_t> tileOf;
        for (std::size_t t = 0; t < tiles.size(); ++t)
            tileOf[tiles[t]] = std::uint32_t(t);
        full.firstObject.assign(tiles.size(), 0);
        full.objectCount.assign(tiles.size(), 0);
        full.tileOfObject.assign(oracle.objects().size(), ~0u);
        for (const oracle::OracleObject& object : oracle.objects())
            full.world.push_back(osg::computeLocalToWorld(object.path));
        for (std::size_t o = 0; o < oracle.objects().size(); ++o)
            for (const osg::Node* node : oracle.objects()[o].path)
                if (const auto found = tileOf.find(node); found != tileOf.end())
                {
                    const std::uint32_t t = found->second;
                    if (full.objectCount[t]++ == 0)
                        full.firstObject[t] = std::uint32_t(o);
                    full.tileOfObject[o] = t;
                }
        std::cerr << "scene: " << scene.name << " (" << tiles.size() << " tiles, " << oracle.objects().size()
                  << " objects), walk: " << scene.walkSource << ", " << views.size() << " views at " << walk.width
                  << "x" << walk.height << std::endl;
        Progress progress("oracle (fully loaded)", views.size());
        for (std::size_t v = 0; v < views.size(); ++v)
        {
            seen.push_back(oracle.visible(views[v].view, views[v].projection));
            progress.advance(v + 1);
        }
    }
    const std::size_t tileCount = full.firstObject.size();
    full.root = nullptr; // the modes' memory is measured without it
    // Tiles the oracle sees at least once: what a mode with no pop-in must load at least.
    std::vector<bool> everSeen(tileCount, false);
    for (const oracle::IdBufferOracle::Result& result : seen)
        for (std::uint32_t object : result.visible)
            if (full.tileOfObject[object] != ~0u)
                everSeen[full.tileOfObject[object]] = true;
    const std::size_t tilesSeen = std::size_t(std::count(everSeen.begin(), everSeen.end(), true));

    std::vector<PagedRow> rows;
    for (const BenchMode& mode : modes)
        rows.push_back(runMode(mode, options, options.sceneFile, full, views, walk, seen));

    const PagedRow* osgRow = nullptr;
    for (const PagedRow& row : rows)
        if (row.mode == "osg")
            osgRow = &row;
    char line[512];
    std::snprintf(line, sizeof line, "%-18s %9s %7s %7s %8s %9s %9s %8s %8s %10s %6s %7s %6s\n", "mode", "requested",
                  "loaded", "expired", "MB read", "peak res", "heap MB", "pop-in f", "pop-in o", "pop-in px", "fi",
                  "fps", "vs osg");
    out << "paged database " << scene.name << ": " << tileCount << " tiles (" << tilesSeen
        << " seen by the oracle along the walk), " << views.size() << " views at " << walk.width << "x" << walk.height
        << " (frames back to back, OSG's DatabasePager)\n"
        << line;
    int failures = 0;
    for (const PagedRow& row : rows)
    {
        const double fps = row.medianFrameSeconds > 0 ? 1.0 / row.medianFrameSeconds : 0.0;
        const double osgFps = osgRow && osgRow->medianFrameSeconds > 0 ? 1.0 / osgRow->medianFrameSeconds : 0.0;
        std::snprintf(line, sizeof line, "%-18s %9zu %7zu %7zu %8.1f %9zu %9.1f %8zu %8zu %10llu %6zu %7.1f %5.2fx\n",
                      row.mode.c_str(), row.filesRequested, row.loads, row.expiries, row.bytesRead / 1e6,
                      row.peakResident, row.peakHeapBytes / 1e6, row.popInFrames, row.popInObjects,
                      (unsigned long long)row.popInPixels, row.falseInvisible, fps, osgFps > 0 ? fps / osgFps : 0.0);
        out << line;
        if (row.conservative && row.falseInvisible != 0)
        {
            std::cerr << "osgvisbench: FAIL: conservative mode '" << row.mode << "' did not draw "
                      << row.falseInvisible << " visible objects of loaded tiles in " << row.framesWithFalseInvisible
                      << " views" << std::endl;
            ++failures;
        }
    }
    if (!options.jsonFile.empty())
        writeJson(options.jsonFile, options, scene.name, tileCount, tilesSeen, views.size(), walk, rows);
    return failures == 0 ? 0 : 1;
}
} // namespace osgVis::bench
