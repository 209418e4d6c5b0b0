// SPDX-License-Identifier: MIT
#pragma once
// The human-readable result: a heading line about the run and one row per mode.
#include "BenchReport.h"

#include <iosfwd>

namespace osgVis::bench
{
void writeReportTable(std::ostream& out, const BenchReport& report);
} // namespace osgVis::bench
