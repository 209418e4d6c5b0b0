// SPDX-License-Identifier: MIT
#pragma once
// The machine-readable result (schema in docs/benchmark.md). Every number is finite or null.
#include "BenchReport.h"

#include <iosfwd>
#include <string>

namespace osgVis::bench
{
// `text` as a JSON string literal, quotes included.
std::string jsonString(const std::string& text);
void writeReportJson(std::ostream& out, const BenchReport& report);
// Throws std::runtime_error when the file cannot be written.
void saveReportJson(const std::string& path, const BenchReport& report);
} // namespace osgVis::bench
