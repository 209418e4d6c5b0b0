// SPDX-License-Identifier: MIT
#include "VolumeBench.h"

#include "BenchRun.h"
#include "ReportJson.h"
#include "TextFile.h"


#include <osgVis/core/multifocal/VolumeVisibility.h>
#include <osgVis/gen/Forest.h>
#include <osgVis/oracle/VolumeOracle.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

namespace osgVis::bench
{
namespace
{
using Clock = std::chrono::steady_clock;

struct VolumeRow
{
    std::size_t objects = 0, pvsObjects = 0, exactObjects = 0, missingObjects = 0;
    std::size_t triangles = 0, culledTriangles = 0, backFacing = 0, exactTriangles = 0, missingTriangles = 0;
    std::size_t restTriangles = 0, restCulled = 0, restHidden = 0; // the triangles not facing away
    double occluderSeconds = 0.0, pvsSeconds = 0.0;                // pvs: median of the repeats
    std::uint32_t planes = 0;
    std::uint64_t occludersInserted = 0;
    std::size_t eyes = 0;
    double zNear = 0.0;
};

// The box --volume names (parseBenchOptions has checked it).
core::Aabb volumeBox(const BenchOptions& options)
{
    if (options.volume == "paper")
    {
        const osg::BoundingBoxd box = gen::forestViewVolume(
            gen::parseForestLayout(options.forestLayout.empty() ? "dense" : options.forestLayout), options.seed);
        return core::Aabb(core::Vec3(box.xMin(), box.yMin(), box.zMin()), core::Vec3(box.xMax(), box.yMax(), box.zMax()));
    }
    double v[6];
    std::sscanf(options.volume.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", v, v + 1, v + 2, v + 3, v + 4, v + 5);
    return core::Aabb(core::Vec3(v[0], v[1], v[2]), core::Vec3(v[3], v[4], v[5]));
}

double percent(std::size_t part, std::size_t whole)
{
    return whole ? 100.0 * double(part) / double(whole) : 0.0;
}

void writeJson(std::ostream& out, const BenchOptions& options, const core::Aabb& box, const VolumeRow& r)
{
    out.precision(17);
    out << "{\n  \"command\": " << jsonString(options.commandLine) << ",\n  \"volume\": [" << box.min.x << ", "
        << box.min.y << ", " << box.min.z << ", " << box.max.x << ", " << box.max.y << ", " << box.max.z << "],\n"
        << "  \"plane_resolution\": " << options.planeResolution << ",\n  \"planes_per_direction\": "
        << options.planesPerDirection << ",\n  \"oracle_eyes\": " << r.eyes << ",\n  \"oracle_face_size\": "
        << options.volumeFaceSize << ",\n  \"near\": " << r.zNear << ",\n  \"objects\": " << r.objects
        << ",\n  \"pvs_objects\": " << r.pvsObjects << ",\n  \"exact_objects\": " << r.exactObjects
        << ",\n  \"missing_objects\": " << r.missingObjects << ",\n  \"triangles\": " << r.triangles
        << ",\n  \"culled_triangles\": " << r.culledTriangles << ",\n  \"back_facing_triangles\": " << r.backFacing
        << ",\n  \"exact_triangles\": " << r.exactTriangles << ",\n  \"missing_triangles\": " << r.missingTriangles
        << ",\n  \"rest_triangles\": " << r.restTriangles << ",\n  \"rest_culled\": " << r.restCulled
        << ",\n  \"rest_hidden\": " << r.restHidden << ",\n  \"rest_efficacy\": "
        << (r.restHidden ? double(r.restCulled) / double(r.restHidden) : 0.0) << ",\n  \"planes\": " << r.planes
        << ",\n  \"occluders_inserted\": " << r.occludersInserted << ",\n  \"occluder_seconds\": " << r.occluderSeconds
        << ",\n  \"pvs_seconds\": " << r.pvsSeconds << "\n}\n";
}

oracle::VolumeOracleSettings oracleSettings(const BenchOptions& options)
{
    oracle::VolumeOracleSettings settings;
    settings.faceSize = options.volumeFaceSize;
    settings.interiorEyes = options.volumeEyes;
    settings.supersample = 1;
    return settings;
}

// The volume PVS of the box, timed: the occluders once, the PVS --volume-repeat times (median kept).
core::VolumePvs timedVolumePvs(const core::Scene& scene, const core::Aabb& box, const BenchOptions& options,
                               double oracleNear, VolumeRow& row)
{
    core::MultifocalOptions multifocal;
    multifocal.planeResolution = int(options.planeResolution);
    multifocal.planesPerDirection = int(options.planesPerDirection);
    multifocal.nearDistance = oracleNear * std::sqrt(3.0);
    const Clock::time_point built = Clock::now();
    const std::vector<core::OccluderPolygon> occluders = core::volumeOccluders(scene);
    row.occluderSeconds = std::chrono::duration<double>(Clock::now() - built).count();
    std::vector<double> seconds;
    core::VolumePvs pvs;
    for (unsigned k = 0; k < std::max(1u, options.volumeRepeat); ++k)
    {
        const Clock::time_point start = Clock::now();
        pvs = core::computeVolumePvs(scene, occluders, box, multifocal);
        seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    std::sort(seconds.begin(), seconds.end());
    row.pvsSeconds = seconds[seconds.size() / 2];
    return pvs;
}

// Of the triangles not facing away from the box, those the PVS culls and those the oracle finds hidden.
void countRestTriangles(const core::Scene& scene, const core::Aabb& box, const core::VolumePvs& pvs,
                        const std::vector<std::uint8_t>& visible, VolumeRow& row)
{
    // Triangles facing away from every point of the box, counted as computeVolumePvs does.
    const core::Vec3 corners[8] = {{box.min.x, box.min.y, box.min.z}, {box.max.x, box.min.y, box.min.z},
                                   {box.min.x, box.max.y, box.min.z}, {box.max.x, box.max.y, box.min.z},
                                   {box.min.x, box.min.y, box.max.z}, {box.max.x, box.min.y, box.max.z},
                                   {box.min.x, box.max.y, box.max.z}, {box.max.x, box.max.y, box.max.z}};
    for (std::size_t t = 0; t < scene.triangles.size(); ++t)
    {
        const core::Triangle& tri = scene.triangles[t];
        const core::Vec3 a(tri.a), n = glm::cross(core::Vec3(tri.b) - a, core::Vec3(tri.c) - a);
        bool away = true;
        for (const core::Vec3& c : corners)
            away = away && glm::dot(c - a, n) < 0.0;
        if (away)
            continue;
        ++row.restTriangles;
        const bool culled = !pvs.hiddenTriangles.empty() && pvs.hiddenTriangles[t];
        row.restCulled += culled ? 1 : 0;
        row.restHidden += visible[t] ? 0 : 1;
    }
}

// The PVS against what the oracle saw: objects and triangles kept, seen and missing.
void compareWithOracle(const core::Scene& scene, const core::Aabb& box, const core::VolumePvs& pvs,
                       const oracle::VolumeVisibility& seen, VolumeRow& row)
{
    row.objects = scene.objects.size();
    row.pvsObjects = pvs.objects.count();
    row.exactObjects = seen.objects.size();
    for (std::uint32_t id : seen.objects)
        row.missingObjects += pvs.objects.test(id) ? 0 : 1;
    row.triangles = scene.triangles.size();
    row.culledTriangles = pvs.statistics.trianglesCulled;
    row.backFacing = pvs.statistics.trianglesBackFacing;
    row.exactTriangles = seen.triangles.size();
    std::vector<std::uint8_t> visible(scene.triangles.size(), 0);
    for (std::uint32_t t : seen.triangles)
    {
        visible[t] = 1;
        row.missingTriangles += pvs.hiddenTriangles.empty() || !pvs.hiddenTriangles[t] ? 0 : 1;
    }
    countRestTriangles(scene, box, pvs, visible, row);
    row.planes = pvs.statistics.planes;
    row.occludersInserted = pvs.statistics.occludersInserted;
    row.eyes = seen.eyes.size();
    row.zNear = seen.zNear;
}

void printReport(std::ostream& out, const std::string& sceneName, const core::Aabb& box, const BenchOptions& options,
                 const VolumeRow& row)
{
    char line[512];
    out << "volume PVS (multifocal) of " << sceneName << ", box (" << box.min.x << ", " << box.min.y << ", "
        << box.min.z << ") - (" << box.max.x << ", " << box.max.y << ", " << box.max.z << "), "
        << options.planeResolution << "-pixel planes, " << options.planesPerDirection << " per face\n";
    std::snprintf(line, sizeof line, "  objects    %8zu  kept %8zu  exact %8zu  missing %zu\n", row.objects,
                  row.pvsObjects, row.exactObjects, row.missingObjects);
    out << line;
    std::snprintf(line, sizeof line,
                  "  triangles  %8zu  culled %8zu (%.1f %%)  facing away %8zu (%.1f %%)  exact %8zu  missing %zu\n",
                  row.triangles, row.culledTriangles, percent(row.culledTriangles, row.triangles), row.backFacing,
                  percent(row.backFacing, row.triangles), row.exactTriangles, row.missingTriangles);
    out << line;
    std::snprintf(line, sizeof line, "  not facing away %zu: culled %zu, hidden by the oracle %zu, efficacy %.3f\n",
                  row.restTriangles, row.restCulled, row.restHidden,
                  row.restHidden ? double(row.restCulled) / double(row.restHidden) : 0.0);
    out << line;
    std::snprintf(line, sizeof line,
                  "  time per volume %.3f s (median of %u; occluders %.3f s once), %u planes, %llu occluders inserted; "
                  "oracle: %zu eyes, %u-pixel faces, near %.4g\n",
                  row.pvsSeconds, std::max(1u, options.volumeRepeat), row.occluderSeconds, row.planes,
                  (unsigned long long)row.occludersInserted, row.eyes, options.volumeFaceSize, row.zNear);
    out << line;
}
} // namespace

int runVolumeBench(const BenchOptions& options, std::ostream& out)
{
    const core::Aabb box = volumeBox(options);
    // The walk is loaded as for a walk run and not used.
    const apps::LoadedScene loaded = loadBenchScene(options);
    // The apps extract without triangles; the volume PVS tests triangles and counts them.
    ExtractionOptions extraction;
    extraction.keepTriangles = true;
    const osg::ref_ptr<ExtractedScene> extracted = extractScene(*loaded.model, extraction);
    const core::Scene& scene = extracted->scene;

    // The oracle first: its near plane is the near distance the PVS must assume (a 90° cube face
    // reaches √3 times as far as its near plane).
    oracle::VolumeOracle volumeOracle(loaded.model.get(), oracleSettings(options));
    const oracle::VolumeVisibility seen = volumeOracle.visibleFrom(
        osg::BoundingBoxd(box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z));
    if (volumeOracle.triangleCount() != scene.triangles.size())
        throw std::runtime_error("the oracle numbers " + std::to_string(volumeOracle.triangleCount()) +
                                 " triangles, the extraction " + std::to_string(scene.triangles.size()));

    VolumeRow row;
    const core::VolumePvs pvs = timedVolumePvs(scene, box, options, seen.zNear, row);
    compareWithOracle(scene, box, pvs, seen, row);
    printReport(out, loaded.name, box, options, row);
    if (!options.jsonFile.empty())
        writeTextFile(options.jsonFile, "JSON report", [&](std::ostream& json) { writeJson(json, options, box, row); });
    const bool missing = row.missingObjects != 0 || row.missingTriangles != 0;
    if (missing)
        out << "osgvisbench: FAIL: the volume PVS lacks " << row.missingObjects << " objects and "
            << row.missingTriangles << " triangles the oracle saw\n";
    return missing ? 1 : 0;
}
} // namespace osgVis::bench
