// SPDX-License-Identifier: MIT
#pragma once
// The report for people (--report DIR): DIR/index.html, one self-contained page (inline SVG and
// CSS, nothing fetched from anywhere) with the run's table, per-view plots of drawn triangles (every
// mode against exact) and of cull time, false-invisible markers, the progressive and threading
// tables, and the side-by-side pictures written beside it.
#include "BenchReport.h"

#include <iosfwd>
#include <string>

namespace osgVis::bench
{
void writeReportHtml(std::ostream& out, const BenchReport& report);
// Writes DIR/index.html; throws std::runtime_error when it cannot. Returns the file's path.
std::string saveReportHtml(const std::string& directory, const BenchReport& report);
} // namespace osgVis::bench
