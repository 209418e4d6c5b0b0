// SPDX-License-Identifier: MIT
#include "OracleReference.h"

#include "Progress.h"

#include <osgVis/oracle/IdBufferOracle.h>
#include <osgVis/oracle/TriangleIdOracle.h>

#include <algorithm>
#include <iostream>
#include <iterator>
#include <memory>
#include <utility>

namespace osgVis::bench
{
namespace
{
// oracle index → scene id (core::InvalidObject where the extraction has no such object)
std::vector<core::ObjectId> mapOracleObjects(const std::vector<oracle::OracleObject>& oracleObjects,
                                             const ExtractedScene& scene)
{
    std::vector<core::ObjectId> ids;
    ids.reserve(oracleObjects.size());
    std::size_t unknown = 0;
    for (const oracle::OracleObject& object : oracleObjects)
    {
        ids.push_back(scene.find(object.drawable.get(), object.path));
        if (ids.back() == core::InvalidObject)
            ++unknown;
    }
    if (unknown != 0)
        std::cerr << "osgvisbench: warning: " << unknown << " of " << oracleObjects.size()
                  << " oracle objects are unknown to the scene extraction; each one the oracle sees counts "
                     "as false-invisible for every mode"
                  << std::endl;
    return ids;
}

core::VisibleSet objectsInFrustum(const core::Scene& scene, const core::Frustum& frustum)
{
    core::VisibleSet inside(scene.objects.size());
    for (const core::SceneObject& object : scene.objects)
        if (object.bounds.empty() || !object.bounds.finite() ||
            frustum.classify(object.bounds) != core::Containment::Outside)
            inside.set(object.id);
    return inside;
}
// Clusters (docs/clusters.md) are finer than the ID buffer's objects: a clustered drawable the ID
// buffer sees is narrowed to the clusters that own a triangle in a triangle-ID render at the display
// size or at the supersampled size, the two sizes the ID buffer renders at (their sample points
// differ: a sliver one of them catches the other may miss). One the ID buffer sees whose triangles
// both renders missed keeps every cluster.
class ClusterReference
{
public:
    ClusterReference(const std::vector<oracle::OracleObject>& objects, const std::vector<core::ObjectId>& sceneIdOf,
                     const ExtractedScene& scene, unsigned width, unsigned height, unsigned supersample)
        : _sceneIdOf(sceneIdOf), _scene(scene), _triangles(objects, width, height)
    {
        if (supersample > 1)
            _supersampled = std::make_unique<oracle::TriangleIdOracle>(objects, width * supersample, height * supersample);
    }

    void narrow(const BenchView& view, const std::vector<std::uint32_t>& visibleObjects, core::VisibleSet& exact)
    {
        std::vector<std::uint32_t> triangles = _triangles.visible(view.view, view.projection);
        if (_supersampled)
        {
            const std::vector<std::uint32_t> more = _supersampled->visible(view.view, view.projection);
            std::vector<std::uint32_t> both;
            both.reserve(triangles.size() + more.size());
            std::set_union(triangles.begin(), triangles.end(), more.begin(), more.end(), std::back_inserter(both));
            triangles.swap(both);
        }
        for (std::uint32_t o : visibleObjects)
        {
            const core::ObjectId first = _sceneIdOf.at(o);
            if (first == core::InvalidObject || !_scene.refs[first].clusters)
                continue;
            const ClusterLayout& layout = *_scene.refs[first].clusters;
            const std::uint32_t begin = _triangles.firstTriangle(o);
            const std::uint32_t end = begin + std::uint32_t(layout.triangleCount());
            auto t = std::lower_bound(triangles.begin(), triangles.end(), begin);
            if (t == triangles.end() || *t >= end)
            {
                for (std::size_t c = 0; c < layout.size(); ++c)
                    exact.set(first + core::ObjectId(c));
                continue;
            }
            exact.clear(first);
            for (; t != triangles.end() && *t < end; ++t)
                exact.set(first + layout.clusterOfTriangle()[*t - begin]);
        }
    }

private:
    const std::vector<core::ObjectId>& _sceneIdOf;
    const ExtractedScene& _scene;
    oracle::TriangleIdOracle _triangles;
    std::unique_ptr<oracle::TriangleIdOracle> _supersampled;
};

void addPixelCounts(const oracle::IdBufferOracle::Result& result, const std::vector<core::ObjectId>& sceneIdOf,
                    const ExtractedScene& scene, ViewReference& view)
{
    for (std::size_t i = 0; i < result.visible.size(); ++i)
        if (result.pixels[i] != 0)
        {
            const core::ObjectId id = sceneIdOf.at(result.visible[i]);
            const ClusterLayout* clusters = id == core::InvalidObject ? nullptr : scene.refs[id].clusters.get();
            view.pixels.push_back(
                {id, std::uint32_t(result.pixels[i]), clusters ? std::uint32_t(clusters->size()) : 1u});
        }
}
} // namespace

OracleReference computeOracleReference(osg::Node& root, const ExtractedScene& scene,
                                       const std::vector<BenchView>& views, unsigned width, unsigned height,
                                       unsigned supersample)
{
    oracle::OracleSettings settings;
    settings.width = width;
    settings.height = height;
    settings.supersample = supersample;
    oracle::IdBufferOracle idBuffer(&root, settings);
    const std::vector<core::ObjectId> sceneIdOf = mapOracleObjects(idBuffer.objects(), scene);
    std::unique_ptr<ClusterReference> clusters;
    if (scene.clusteredDrawables != 0)
        clusters = std::make_unique<ClusterReference>(idBuffer.objects(), sceneIdOf, scene, width, height, supersample);

    OracleReference reference;
    reference.supersample = supersample;
    reference.pixelCounts = true;
    reference.views.reserve(views.size());
    Progress progress("oracle", views.size());
    for (std::size_t v = 0; v < views.size(); ++v)
    {
        const oracle::IdBufferOracle::Result result = idBuffer.visible(views[v].view, views[v].projection);
        ViewReference viewReference;
        viewReference.exact.reset(scene.scene.objects.size());
        for (std::uint32_t oracleIndex : result.visible)
        {
            const core::ObjectId id = sceneIdOf.at(oracleIndex);
            if (id == core::InvalidObject)
                ++viewReference.unknownVisible;
            else
                viewReference.exact.set(id);
        }
        if (clusters)
            clusters->narrow(views[v], result.visible, viewReference.exact);
        addPixelCounts(result, sceneIdOf, scene, viewReference);
        if (result.onlyInSupersampled != 0)
        {
            reference.viewsWithSupersampleExtras.push_back(std::uint32_t(v));
            reference.supersampleExtras += result.onlyInSupersampled;
        }
        reference.views.push_back(std::move(viewReference));
        progress.advance(v + 1);
    }
    addFrustumSets(reference, scene.scene, views);
    return reference;
}

void addFrustumSets(OracleReference& reference, const core::Scene& scene, const std::vector<BenchView>& views)
{
    for (std::size_t v = 0; v < reference.views.size() && v < views.size(); ++v)
        reference.views[v].inFrustum = objectsInFrustum(scene, views[v].frustum);
}
} // namespace osgVis::bench
