// SPDX-License-Identifier: MIT
#include "OracleReference.h"

#include "Progress.h"

#include <osgVis/oracle/IdBufferOracle.h>

#include <iostream>
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
void addPixelCounts(const oracle::IdBufferOracle::Result& result, const std::vector<core::ObjectId>& sceneIdOf,
                    ViewReference& view)
{
    for (std::size_t i = 0; i < result.visible.size(); ++i)
        if (result.pixels[i] != 0)
            view.pixels.push_back({sceneIdOf.at(result.visible[i]), std::uint32_t(result.pixels[i])});
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
        addPixelCounts(result, sceneIdOf, viewReference);
        viewReference.inFrustum = objectsInFrustum(scene.scene, views[v].frustum);
        if (result.onlyInSupersampled != 0)
        {
            reference.viewsWithSupersampleExtras.push_back(std::uint32_t(v));
            reference.supersampleExtras += result.onlyInSupersampled;
        }
        reference.views.push_back(std::move(viewReference));
        progress.advance(v + 1);
    }
    return reference;
}
} // namespace osgVis::bench
