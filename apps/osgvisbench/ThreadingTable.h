// SPDX-License-Identifier: MIT
#pragma once
// The threading table (--threading, --async): every osg and module-chain mode rendered again
// under each OSG threading model with asynchronous visibility on and/or off, against the same
// oracle reference as the main table.
#include "BenchOptions.h"
#include "BenchReport.h"
#include "BenchView.h"
#include "OracleReference.h"

#include <SceneSource.h>

#include <osgVis/core/scene/VisibleSet.h>

#include <map>
#include <string>
#include <vector>

namespace osgVis::bench
{
// `mainPasses` holds the main table's drawn sets per mode name (SingleThreaded, sync), which the
// synchronous rows must reproduce view for view.
std::vector<ThreadingRow> runThreadingTable(const BenchOptions& options, const std::vector<BenchMode>& modes,
                                            const apps::LoadedScene& scene, const core::Walk& walk,
                                            const std::vector<BenchView>& views, const OracleReference& reference,
                                            const std::map<std::string, std::vector<core::VisibleSet>>& mainPasses);
} // namespace osgVis::bench
