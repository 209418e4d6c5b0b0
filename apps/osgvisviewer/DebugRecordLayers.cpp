// SPDX-License-Identifier: MIT
#include "DebugRecordLayers.h"

#include "MapGeometry.h"

#include <osg/LineWidth>

#include <sstream>

namespace osgVis::viewer
{
namespace
{
const osg::Vec4 OccludedNodeColour(0.95f, 0.15f, 0.15f, 1.0f);
const osg::Vec4 VisibleNodeColour(0.2f, 0.9f, 0.25f, 1.0f);
const osg::Vec4 OutsideNodeColour(0.6f, 0.6f, 0.6f, 1.0f);
const osg::Vec4 OccluderColour(0.2f, 0.45f, 1.0f, 1.0f);
const osg::Vec4 EyeCellColour(1.0f, 1.0f, 0.0f, 1.0f);
const float NodeFillAlpha = 0.25f;

osg::Vec4 nodeColour(core::NodeState state)
{
    switch (state)
    {
    case core::NodeState::Invisible:
        return OccludedNodeColour;
    case core::NodeState::OutsideFrustum:
        return OutsideNodeColour;
    case core::NodeState::Visible:
        break;
    }
    return VisibleNodeColour;
}

void setLineWidth(osg::Geometry& layer, float width)
{
    layer.getOrCreateStateSet()->setAttribute(new osg::LineWidth(width));
}
} // namespace

DebugRecordLayers::DebugRecordLayers()
{
    _nodeFills = makeMapLayer(GL_QUADS, 0, NodeFillBin, VisibleNodeColour, true);
    _nodeOutlines = makeMapLayer(GL_LINES, 0, NodeOutlineBin, VisibleNodeColour, true);
    _occluders = makeMapLayer(GL_LINES, 0, OccluderBin, OccluderColour, false);
    setLineWidth(*_occluders, 4.0f);
    _eyeCell = makeMapLayer(GL_LINES, 0, EyeCellBin, EyeCellColour, false);
    setLineWidth(*_eyeCell, 2.0f);
}

std::vector<osg::Drawable*> DebugRecordLayers::drawables() const
{
    return {_nodeFills.get(), _nodeOutlines.get(), _occluders.get(), _eyeCell.get()};
}

void DebugRecordLayers::update(const core::DebugRecord& record)
{
    const unsigned nodes = unsigned(record.nodes.size());
    resizeMapLayer(*_nodeFills, 4 * nodes);
    resizeMapLayer(*_nodeOutlines, 8 * nodes);
    auto& fills = static_cast<osg::Vec3Array&>(*_nodeFills->getVertexArray());
    auto& fillColours = static_cast<osg::Vec4Array&>(*_nodeFills->getColorArray());
    auto& outlines = static_cast<osg::Vec3Array&>(*_nodeOutlines->getVertexArray());
    auto& outlineColours = static_cast<osg::Vec4Array&>(*_nodeOutlines->getColorArray());
    std::size_t counts[3] = {0, 0, 0}; // by NodeState
    for (unsigned i = 0; i < nodes; ++i)
    {
        const core::DebugRecord::Node& node = record.nodes[i];
        ++counts[std::size_t(node.state)];
        setFootprint(fills, outlines, i, node.bounds);
        osg::Vec4 colour = nodeColour(node.state);
        std::fill(outlineColours.begin() + 8 * i, outlineColours.begin() + 8 * (i + 1), colour);
        colour.a() = NodeFillAlpha;
        std::fill(fillColours.begin() + 4 * i, fillColours.begin() + 4 * (i + 1), colour);
    }

    unsigned edges = 0;
    for (const std::vector<core::Vec3>& polygon : record.activeOccluders)
        edges += polygon.size() >= 2 ? unsigned(polygon.size()) : 0u;
    resizeMapLayer(*_occluders, 2 * edges);
    auto& occluderLines = static_cast<osg::Vec3Array&>(*_occluders->getVertexArray());
    unsigned vertex = 0;
    for (const std::vector<core::Vec3>& polygon : record.activeOccluders)
    {
        if (polygon.size() < 2)
            continue;
        for (std::size_t corner = 0; corner < polygon.size(); ++corner)
        {
            const core::Vec3& from = polygon[corner];
            const core::Vec3& to = polygon[(corner + 1) % polygon.size()];
            setPlanarVertex(occluderLines, vertex++, from.x, from.y);
            setPlanarVertex(occluderLines, vertex++, to.x, to.y);
        }
    }

    const bool hasEyeCell = !record.eyeCell.empty();
    resizeMapLayer(*_eyeCell, hasEyeCell ? 8 : 0);
    if (hasEyeCell)
        setFootprintOutline(static_cast<osg::Vec3Array&>(*_eyeCell->getVertexArray()), 0, record.eyeCell);

    _legend.clear();
    if (nodes == 0 && record.activeOccluders.empty() && !hasEyeCell)
        return;
    std::ostringstream legend;
    legend << "nodes: " << counts[std::size_t(core::NodeState::Invisible)] << " red occluded, "
           << counts[std::size_t(core::NodeState::Visible)] << " green visible\n"
           << counts[std::size_t(core::NodeState::OutsideFrustum)] << " grey outside; " << record.activeOccluders.size()
           << " blue occluders" << (hasEyeCell ? "; yellow eye cell" : "");
    _legend = legend.str();
}
} // namespace osgVis::viewer
