// SPDX-License-Identifier: MIT
// Visible clusters drawn from the layout's private index buffer (docs/clusters.md): one drawable
// per cull, so what a draw reads was decided for its own frame and view.
#include <osgVis/ClusterDraw>

#include <osg/BufferObject>
#include <osg/GL>
#include <osg/State>
#include <osg/VertexArrayState>

#include <cmath>

namespace osgVis
{
ClusterDraw::ClusterDraw() = default;

ClusterDraw::ClusterDraw(const osg::Drawable& original, const ClusterLayout& layout, Runs runs)
    : _original(&original), _layout(&layout), _runs(std::move(runs))
{
    // note: nothing here may compile into a display list (the ranges are this frame's), and no
    // vertex array object either (a fresh drawable each frame would make one each frame).
    setSupportsDisplayList(false);
    setUseDisplayList(false);
    setUseVertexArrayObject(false);
    setUseVertexBufferObjects(true);
    setInitialBound(original.getBoundingBox());
    setName(original.getName());
}

ClusterDraw::ClusterDraw(const ClusterDraw& other, const osg::CopyOp& copyop)
    : osg::Drawable(other, copyop), _original(other._original), _layout(other._layout), _runs(other._runs)
{
}

ClusterDraw::~ClusterDraw() = default;

void ClusterDraw::drawImplementation(osg::RenderInfo& renderInfo) const
{
    if (!_layout || _runs.empty())
        return;
    osg::State& state = *renderInfo.getState();
    const osg::Geometry& geometry = _layout->geometry();
    const bool useVbo = state.useVertexBufferObject(geometry.getUseVertexBufferObjects());
    osg::VertexArrayState* vas = state.getCurrentVertexArrayState();
    vas->setVertexBufferObjectSupported(useVbo);
    geometry.drawVertexArraysImplementation(renderInfo);

    const osg::DrawElementsUInt& indices = _layout->indices();
    const char* base = nullptr;
    osg::GLBufferObject* ebo = useVbo ? indices.getOrCreateGLBufferObject(state.getContextID()) : nullptr;
    if (ebo)
    {
        vas->bindElementBufferObject(ebo);
        base = reinterpret_cast<const char*>(ebo->getOffset(indices.getBufferIndex()));
    }
    else
    {
        vas->unbindElementBufferObject();
        base = reinterpret_cast<const char*>(&indices.front());
    }
    for (const auto& [first, count] : _runs)
        glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, base + std::size_t(first) * sizeof(GLuint));
    if (useVbo)
    {
        vas->unbindVertexBufferObject();
        vas->unbindElementBufferObject();
    }
}

std::vector<std::uint32_t> ClusterDraw::drawnClusters() const
{
    std::vector<std::uint32_t> out;
    if (!_layout)
        return out;
    const std::vector<ClusterLayout::Cluster>& clusters = _layout->clusters();
    std::size_t run = 0;
    for (std::uint32_t c = 0; c < clusters.size() && run < _runs.size(); ++c)
    {
        while (run < _runs.size() && GLint(clusters[c].firstIndex) >= _runs[run].first + _runs[run].second)
            ++run;
        if (run < _runs.size() && GLint(clusters[c].firstIndex) >= _runs[run].first)
            out.push_back(c);
    }
    return out;
}
} // namespace osgVis
