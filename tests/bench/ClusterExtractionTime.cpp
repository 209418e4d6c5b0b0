// SPDX-License-Identifier: MIT
// Extraction time with clusters on and off (docs/clusters.md): reads a model, extracts it a few
// times each way on this thread, prints the median wall time and what clusters cost in memory.
// Run by hand for figures (tests/bench/results/clusters/run.sh); never a timed assert.
#include <osgVis/SceneExtractor>

#include <osg/Geometry>
#include <osgDB/ReadFile>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <set>
#include <vector>

int main(int argc, char** argv)
{
    if (argc < 2)
    {
        std::fprintf(stderr, "usage: osgvis_cluster_extraction_time MODEL [REPEATS]\n");
        return 2;
    }
    const osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(argv[1]);
    if (!model)
    {
        std::fprintf(stderr, "cannot read '%s'\n", argv[1]);
        return 1;
    }
    const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
    for (const std::uint32_t threshold : {0u, osgVis::defaultClusterThreshold()})
    {
        osgVis::ExtractionOptions options;
        options.clusterThreshold = threshold;
        std::vector<double> ms;
        osg::ref_ptr<osgVis::ExtractedScene> scene;
        for (int i = 0; i < repeats; ++i)
        {
            const auto start = std::chrono::steady_clock::now();
            scene = osgVis::extractScene(*model, options);
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        std::sort(ms.begin(), ms.end());
        std::set<const osgVis::ClusterLayout*> layouts;
        std::size_t clusterBytes = 0, geometryBytes = 0;
        for (const osgVis::ObjectRef& ref : scene->refs)
            if (ref.clusters && layouts.insert(ref.clusters.get()).second)
            {
                clusterBytes += ref.clusters->memoryBytes();
                // The clustered drawable's own arrays and primitive sets (arrays shared between
                // drawables count once per drawable: an upper bound).
                const osg::Geometry* geometry = ref.drawable->asGeometry();
                osg::Geometry::ArrayList arrays;
                geometry->getArrayList(arrays);
                for (const auto& array : arrays)
                    geometryBytes += array->getTotalDataSize();
                for (unsigned i = 0; i < geometry->getNumPrimitiveSets(); ++i)
                    geometryBytes += geometry->getPrimitiveSet(i)->getTotalDataSize();
            }
        std::printf("clusters %s (threshold %u): %zu objects, %llu triangles, %zu drawables clustered, "
                    "extraction median %.1f ms (of %d), cluster tables + private indices %.1f MiB = %.2f of the "
                    "clustered drawables' geometry (%.1f MiB)\n",
                    threshold ? "on" : "off", threshold, scene->scene.objects.size(),
                    static_cast<unsigned long long>(scene->scene.totalTriangles()), scene->clusteredDrawables,
                    ms[ms.size() / 2], repeats, clusterBytes / 1048576.0,
                    geometryBytes ? double(clusterBytes) / double(geometryBytes) : 0.0, geometryBytes / 1048576.0);
    }
    return 0;
}
