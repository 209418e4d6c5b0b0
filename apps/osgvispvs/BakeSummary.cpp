// SPDX-License-Identifier: MIT
#include "BakeSummary.h"

#include <cstdio>
#include <iomanip>

namespace osgVis::pvstool
{
namespace
{
std::string jsonString(const std::string& text)
{
    std::string quoted = "\"";
    for (char c : text)
    {
        if (c == '"' || c == '\\')
            quoted += std::string("\\") + c;
        else if (static_cast<unsigned char>(c) < 0x20)
        {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(c));
            quoted += escaped;
        }
        else
            quoted += c;
    }
    return quoted + "\"";
}

std::string bytesText(std::uint64_t bytes)
{
    char text[64];
    if (bytes >= 1024 * 1024)
        std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
    else if (bytes >= 1024)
        std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / 1024.0);
    else
        std::snprintf(text, sizeof text, "%llu bytes", (unsigned long long)bytes);
    return text;
}
} // namespace

BakeSummary summarizeBake(const core::CellPortalData& data, std::uint64_t triangles)
{
    BakeSummary s;
    s.objects = data.objectCount;
    s.triangles = triangles;
    s.cells = std::uint32_t(data.graph.cells.size());
    s.portals = std::uint32_t(data.graph.portals.size());
    std::uint64_t visibleCells = 0, pvsObjects = 0;
    for (const core::SourceCellVisibility& source : data.sources)
    {
        s.stabNodes += source.stabTree.size();
        visibleCells += source.cellToCell.count();
        pvsObjects += source.cellToObject.count();
        s.budgetExceededCells += source.budgetExceeded ? 1 : 0;
    }
    if (!data.sources.empty())
    {
        s.averageVisibleCells = double(visibleCells) / double(data.sources.size());
        s.averagePvsObjects = double(pvsObjects) / double(data.sources.size());
    }
    return s;
}

void printBakeSummary(std::ostream& out, const BakeSummary& s)
{
    char line[256];
    out << "model:                 " << s.modelFile << " (" << s.objects << " objects, " << s.triangles
        << " triangles)\n";
    out << "written:               " << s.pvsFile << " (" << bytesText(s.fileBytes) << ", names the model as '"
        << s.modelPathInPvs << "')\n";
    out << "cells:                 " << s.cells << '\n';
    out << "portals:               " << s.portals << '\n';
    out << "stab-tree nodes:       " << s.stabNodes << '\n';
    std::snprintf(line, sizeof line, "average visible cells: %.1f\n", s.averageVisibleCells);
    out << line;
    std::snprintf(line, sizeof line, "average PVS:           %.1f objects (%.1f %% of the model)\n", s.averagePvsObjects,
                  100.0 * s.averagePvsFraction());
    out << line;
    std::snprintf(line, sizeof line, "search budget hit:     %u cells (%.1f %%)\n", s.budgetExceededCells,
                  100.0 * s.budgetExceededFraction());
    out << line;
    std::snprintf(line, sizeof line, "bake time:             %.2f s\n", s.bakeSeconds);
    out << line;
}

void writeBakeSummaryJson(std::ostream& out, const BakeSummary& s)
{
    const auto flags = out.flags();
    out << std::setprecision(17);
    out << "{\n";
    out << "  \"model\": " << jsonString(s.modelFile) << ",\n";
    out << "  \"pvs\": " << jsonString(s.pvsFile) << ",\n";
    out << "  \"model_path_in_pvs\": " << jsonString(s.modelPathInPvs) << ",\n";
    out << "  \"objects\": " << s.objects << ",\n";
    out << "  \"triangles\": " << s.triangles << ",\n";
    out << "  \"cells\": " << s.cells << ",\n";
    out << "  \"portals\": " << s.portals << ",\n";
    out << "  \"stab_nodes\": " << s.stabNodes << ",\n";
    out << "  \"average_visible_cells\": " << s.averageVisibleCells << ",\n";
    out << "  \"average_pvs_objects\": " << s.averagePvsObjects << ",\n";
    out << "  \"average_pvs_fraction\": " << s.averagePvsFraction() << ",\n";
    out << "  \"budget_exceeded_cells\": " << s.budgetExceededCells << ",\n";
    out << "  \"budget_exceeded_fraction\": " << s.budgetExceededFraction() << ",\n";
    out << "  \"bake_seconds\": " << s.bakeSeconds << ",\n";
    out << "  \"file_bytes\": " << s.fileBytes << ",\n";
    out << "  \"options\": {\"min_coverage\": " << s.options.subdivision.minCoverage
        << ", \"min_face_area\": " << s.options.subdivision.minFaceArea
        << ", \"min_cell_size\": " << s.options.subdivision.minCellSize
        << ", \"max_cells\": " << s.options.subdivision.maxCells << ", \"stab_budget\": " << s.options.stabBudget
        << ", \"threads\": " << s.options.threads << "}\n";
    out << "}\n";
    out.flags(flags);
}
} // namespace osgVis::pvstool
