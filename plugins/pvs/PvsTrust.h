// SPDX-License-Identifier: MIT
#pragma once
// Whether a .pvs file's data were baked for a model, and the VisibilityGroup that shows the model
// either way: "cellportal" (or "multifocal" for view cells) when the data are trusted, "frustum"
// when not. The group carries a
// description an application can test:
//   "osgVis:pvs-trusted"                   the .pvs matches the model; its data are registered
//   "osgVis:pvs-untrusted: <reason>"       corrupt .pvs, or baked for another model
#include <osgVis/VisibilityGroup>
#include <osgVis/core/pvs/PvsFormat.h>

#include <osg/Node>

#include <string>

namespace osgVis::pvsplugin
{
extern const char* const TrustedDescription;
extern const char* const UntrustedPrefix; // followed by the reason

// "" when `pvs` was baked for `model`, else why not: the same geometry fingerprint and object count
// where the file has a geometry fingerprint (version 2), else the same fingerprint and object count.
std::string mismatchWithModel(const core::PvsFile& pvs, osg::Node& model);

// The group holds the .pvs's data (VisibilityGroup::setBakedData), not the process-wide store.
osg::ref_ptr<VisibilityGroup> makeTrustedGroup(osg::Node& model, const std::string& name,
                                              std::shared_ptr<const core::BakedData> baked,
                                              const std::string& modes = "cellportal");
osg::ref_ptr<VisibilityGroup> makeUntrustedGroup(osg::Node& model, const std::string& name, const std::string& reason);
// True for a group this plugin made (its child is the model a .pvs was read with).
bool isPvsGroup(const osg::Node& node);
} // namespace osgVis::pvsplugin
