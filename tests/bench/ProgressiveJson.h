// SPDX-License-Identifier: MIT
#pragma once
// Reads the bench JSON's "progressive" array (the cell-portal stages' drawn fractions) for the tests.
#include <string>
#include <vector>

namespace osgVis::test
{
struct ProgressiveStageRow
{
    std::string stage;
    double drawnFraction = -1.0;
    double objectsFraction = -1.0;
};

// The rows in file order; empty when the array is empty or missing.
std::vector<ProgressiveStageRow> progressiveRows(const std::string& json);
} // namespace osgVis::test
