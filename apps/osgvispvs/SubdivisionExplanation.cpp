// SPDX-License-Identifier: MIT
#include "SubdivisionExplanation.h"

namespace osgVis::pvstool
{
namespace
{
void explainFaces(const core::Scene& scene, const core::SubdivisionOptions& options, std::ostream& out)
{
    const std::size_t faces = core::findOpaqueAxialFaces(scene).size();
    const std::size_t cells = core::subdivideCells(scene, options).cells.size();
    out << "subdivision from faces: " << faces << " opaque axis-aligned faces, " << cells << " cells\n";
    if (cells <= 1)
        out << "  one cell: no plane of opaque, two-sided, axis-aligned faces covers " << options.minCoverage
            << " of the model's\n"
               "  cross-section. Walls that are not axis-aligned rectangles, or that are culled on one side,\n"
               "  split nothing here; a Quake 3 level states its solids: try --cells-from solids\n";
}

void explainSolids(const core::Scene& scene, const core::SubdivisionOptions& options, std::ostream& out)
{
    core::SolidSubdivisionReport r;
    const core::CellGraph graph = core::subdivideSolidCells(scene, options, &r);
    out << "subdivision from solids: " << r.solidBoxes << " solid boxes, " << r.unproven << " unproven solids, "
        << r.eyePoints << " eye points\n"
        << "  kd leaves " << r.leaves << ": solid " << r.solidLeaves << ", partly solid (open) " << r.mixedLeaves
        << ", open in eye space " << r.eyeSpaceLeaves << ", open elsewhere " << r.outsideLeaves << "\n"
        << "  faces closed by an opaque solid face " << r.closedFaces << "; solid leaves sightlines may enter "
        << r.reachedSolidLeaves << "; open leaves no sightline from eye space reaches " << r.unreachedOpenLeaves
        << " (no cell there; an eye there keeps everything)\n"
        << "  cells " << graph.cells.size() << ", portals " << graph.portals.size() << "\n";
    if (r.solidBoxes == 0)
        out << "  the model states no solid space: today only a Quake 3 level's box brushes do (a .bsp file);\n"
               "  without solids the open space is one cell, culled by the view frustum alone\n";
    else if (r.eyePoints == 0)
        out << "  no eye points (a level's spawn points): no face of a solid is trusted, since a level compiler\n"
               "  drops the faces that face space no eye reaches, so sightlines may enter every solid\n";
    else if (r.eyeSpaceLeaves == 0)
        out << "  no eye point lies in enclosed open space: the solids leave a gap to the model's outside (a\n"
               "  leak through space no box brush fills), so no face of a solid is trusted\n";
}
} // namespace

void explainSubdivision(const core::Scene& scene, const core::SubdivisionOptions& options, std::ostream& out)
{
    if (!scene.cells.empty())
        out << "cells stated by osgVis::Cell markers: " << scene.cells.size() << " cells, "
            << scene.portals.size() << " portals\n";
    else if (options.fromSolids)
        explainSolids(scene, options, out);
    else
        explainFaces(scene, options, out);
}
} // namespace osgVis::pvstool
