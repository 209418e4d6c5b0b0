// SPDX-License-Identifier: MIT
#include "PvsTrust.h"

#include <osgVis/SceneExtractor>

#include <cstdio>

namespace osgVis::pvsplugin
{
const char* const TrustedDescription = "osgVis:pvs-trusted";
const char* const UntrustedPrefix = "osgVis:pvs-untrusted: ";

namespace
{
std::string hex(std::uint64_t value)
{
    char text[19];
    std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(value));
    return text;
}
} // namespace

std::string mismatchWithModel(const core::PvsFile& pvs, osg::Node& model)
{
    // A bake of a whole paged database: the model is its root with whatever is loaded, each tile
    // checked as it arrives (CellPortalModule); here the root's own objects must be the bake's.
    if (pvs.data.tiles)
    {
        ExtractionOptions options;
        options.keepTriangles = false;
        const osg::ref_ptr<ExtractedScene> extracted = extractScene(model, options);
        std::vector<core::ObjectId> bakedOf;
        std::string why = "the model pages nothing";
        if (extracted->scene.tiles && core::mapToBakedObjects(*pvs.data.tiles, *extracted->scene.tiles, bakedOf, why))
            return "";
        return "baked for another paged database (" + why + ")";
    }
    // note: only the geometry fingerprint hashes triangles; without it the check skips collecting them.
    const bool geometry = pvs.geometryFingerprint != 0;
    ExtractionOptions options;
    options.keepTriangles = geometry;
    const osg::ref_ptr<ExtractedScene> extracted = extractScene(model, options);
    const std::uint64_t baked = geometry ? pvs.geometryFingerprint : pvs.data.fingerprint;
    const std::uint64_t fingerprint =
        geometry ? core::sceneGeometryFingerprint(extracted->scene) : core::sceneFingerprint(extracted->scene);
    const std::size_t objects = extracted->scene.objects.size();
    if (fingerprint == baked && objects == pvs.data.objectCount)
        return "";
    // Clusters (docs/clusters.md) change the objects: say so when the model without them is the one baked.
    if (extracted->clusteredDrawables != 0)
    {
        ExtractionOptions whole = options;
        whole.clusterThreshold = 0;
        const osg::ref_ptr<ExtractedScene> unsplit = extractScene(model, whole);
        const std::uint64_t unsplitFingerprint =
            geometry ? core::sceneGeometryFingerprint(unsplit->scene) : core::sceneFingerprint(unsplit->scene);
        if (unsplitFingerprint == baked && unsplit->scene.objects.size() == pvs.data.objectCount)
            return "baked without clusters (" + std::to_string(pvs.data.objectCount) + " objects; with " +
                   std::to_string(extracted->clusteredDrawables) + " drawables split into clusters this model has " +
                   std::to_string(objects) + "): bake it again, or set OSGVIS_CLUSTER_THRESHOLD=0 to read it";
    }
    const char* kind = geometry ? "geometry fingerprint " : "fingerprint ";
    return std::string("baked for another model (") + kind + hex(baked) + ", " + std::to_string(pvs.data.objectCount) +
           " objects; this model has " + hex(fingerprint) + ", " + std::to_string(objects) + " objects)";
}

osg::ref_ptr<VisibilityGroup> makeTrustedGroup(osg::Node& model, const std::string& name,
                                               std::shared_ptr<const core::BakedData> baked, const std::string& modes)
{
    osg::ref_ptr<VisibilityGroup> group = new VisibilityGroup(modes);
    group->setBakedData(std::move(baked));
    group->setName(name);
    group->addDescription(TrustedDescription);
    group->addChild(&model);
    return group;
}

osg::ref_ptr<VisibilityGroup> makeUntrustedGroup(osg::Node& model, const std::string& name, const std::string& reason)
{
    osg::ref_ptr<VisibilityGroup> group = new VisibilityGroup("frustum");
    group->setName(name);
    group->addDescription(UntrustedPrefix + reason);
    group->addChild(&model);
    return group;
}

bool isPvsGroup(const osg::Node& node)
{
    const auto* group = dynamic_cast<const VisibilityGroup*>(&node);
    if (!group || group->getNumChildren() != 1)
        return false;
    for (const std::string& description : group->getDescriptions())
        if (description == TrustedDescription || description.rfind(UntrustedPrefix, 0) == 0)
            return true;
    return false;
}
} // namespace osgVis::pvsplugin
