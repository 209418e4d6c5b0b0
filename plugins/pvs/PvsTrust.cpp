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

std::string mismatchWithModel(const core::CellPortalData& data, osg::Node& model)
{
    // note: the fingerprint hashes no triangles, so the check skips collecting them.
    ExtractionOptions options;
    options.keepTriangles = false;
    const osg::ref_ptr<ExtractedScene> extracted = extractScene(model, options);
    const std::uint64_t fingerprint = core::sceneFingerprint(extracted->scene);
    const std::size_t objects = extracted->scene.objects.size();
    if (fingerprint == data.fingerprint && objects == data.objectCount)
        return "";
    return "baked for another model (fingerprint " + hex(data.fingerprint) + ", " + std::to_string(data.objectCount) +
           " objects; this model has " + hex(fingerprint) + ", " + std::to_string(objects) + " objects)";
}

osg::ref_ptr<VisibilityGroup> makeTrustedGroup(osg::Node& model, const std::string& name)
{
    osg::ref_ptr<VisibilityGroup> group = new VisibilityGroup("cellportal");
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
