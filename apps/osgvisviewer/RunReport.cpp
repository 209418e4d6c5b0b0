// SPDX-License-Identifier: MIT
#include "RunReport.h"

#include <osgVis/Statistics>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace osgVis::viewer
{
namespace
{
double attribute(const osg::Stats& stats, unsigned frameNumber, const std::string& name)
{
    double value = 0.0;
    return stats.getAttribute(frameNumber, name, value) ? value : 0.0;
}

// The frames' mean figures (a FrameFigures holds them); hasOsgVis only where every frame has it.
FrameFigures meansOf(const std::vector<FrameFigures>& frames)
{
    FrameFigures means;
    if (frames.empty())
        return means;
    means.hasOsgVis = std::all_of(frames.begin(), frames.end(), [](const FrameFigures& f) { return f.hasOsgVis; });
    for (double FrameFigures::*figure :
         {&FrameFigures::visibleObjects, &FrameFigures::drawnTriangles, &FrameFigures::cullMilliseconds,
          &FrameFigures::osgDrawables, &FrameFigures::osgTriangles, &FrameFigures::osgCullMilliseconds})
    {
        for (const FrameFigures& f : frames)
            means.*figure += f.*figure;
        means.*figure /= double(frames.size());
    }
    return means;
}

std::string jsonString(const std::string& text)
{
    std::ostringstream out;
    out << '"';
    for (unsigned char c : text)
    {
        if (c == '"' || c == '\\')
            out << '\\' << c;
        else if (c < 0x20)
            out << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
        else
            out << c;
    }
    out << '"';
    return out.str();
}

void writeFile(const std::filesystem::path& path, const std::string& text)
{
    std::ofstream out(path);
    out << text;
    out.close();
    if (!out)
        throw std::runtime_error("cannot write '" + path.string() + "'");
}
} // namespace

FrameFigures readFrameFigures(const osg::Stats& stats, unsigned frameNumber)
{
    FrameFigures figures;
    double value = 0.0;
    figures.hasOsgVis = stats.getAttribute(frameNumber, STATS_VISIBLE, value);
    figures.visibleObjects = attribute(stats, frameNumber, STATS_VISIBLE);
    figures.drawnTriangles = attribute(stats, frameNumber, STATS_TRIANGLES);
    figures.cullMilliseconds = attribute(stats, frameNumber, STATS_CULL_MS);
    figures.osgDrawables = attribute(stats, frameNumber, "Visible number of drawables");
    // osgUtil::Statistics counts primitives per GL mode: strips and fans as triangles, quads as two.
    figures.osgTriangles = attribute(stats, frameNumber, "Visible number of GL_TRIANGLES") +
                           attribute(stats, frameNumber, "Visible number of GL_TRIANGLE_STRIP") +
                           attribute(stats, frameNumber, "Visible number of GL_TRIANGLE_FAN") +
                           2.0 * attribute(stats, frameNumber, "Visible number of GL_QUADS") +
                           2.0 * attribute(stats, frameNumber, "Visible number of GL_QUAD_STRIP") +
                           attribute(stats, frameNumber, "Visible number of GL_POLYGON");
    figures.osgCullMilliseconds = 1000.0 * attribute(stats, frameNumber, "Cull traversal time taken");
    return figures;
}

void RunReport::write(const std::string& directory) const
{
    const FrameFigures means = meansOf(frames);
    // Mode "osg" has no adapter figures: OSG's own counts of what it drew stand in for them.
    const double visible = means.hasOsgVis ? means.visibleObjects : means.osgDrawables;
    const double triangles = means.hasOsgVis ? means.drawnTriangles : means.osgTriangles;
    const char* source = means.hasOsgVis ? "osgVis" : "osg scene statistics";

    std::ostringstream json;
    json << std::setprecision(10);
    json << "{\n"
         << "  \"scene\": " << jsonString(scene) << ",\n"
         << "  \"walk\": " << jsonString(walk) << ",\n"
         << "  \"mode\": " << jsonString(mode) << ",\n"
         << "  \"width\": " << width << ",\n"
         << "  \"height\": " << height << ",\n"
         << "  \"views\": " << frames.size() << ",\n"
         << "  \"objects\": " << objects << ",\n"
         << "  \"scene_triangles\": " << sceneTriangles << ",\n"
         << "  \"figures_from\": " << jsonString(source) << ",\n"
         << "  \"mean_visible_objects\": " << visible << ",\n"
         << "  \"mean_drawn_triangles\": " << triangles << ",\n"
         << "  \"mean_cull_ms\": " << (means.hasOsgVis ? means.cullMilliseconds : 0.0) << ",\n"
         << "  \"mean_osg_drawables\": " << means.osgDrawables << ",\n"
         << "  \"mean_osg_triangles\": " << means.osgTriangles << ",\n"
         << "  \"mean_osg_cull_traversal_ms\": " << means.osgCullMilliseconds << ",\n"
         << "  \"total_seconds\": " << totalSeconds << ",\n"
         << "  \"frames\": [";
    for (std::size_t i = 0; i < frames.size(); ++i)
    {
        const FrameFigures& f = frames[i];
        json << (i ? "," : "") << "\n    {\"view\": " << i << ", \"visible_objects\": "
             << (f.hasOsgVis ? f.visibleObjects : f.osgDrawables) << ", \"drawn_triangles\": "
             << (f.hasOsgVis ? f.drawnTriangles : f.osgTriangles) << ", \"cull_ms\": " << f.cullMilliseconds
             << ", \"osg_drawables\": " << f.osgDrawables << ", \"osg_cull_traversal_ms\": " << f.osgCullMilliseconds
             << "}";
    }
    json << "\n  ]\n}\n";

    std::ostringstream text;
    text << std::fixed << std::setprecision(2);
    text << "scene                " << scene << "\n"
         << "walk                 " << walk << "\n"
         << "mode                 " << mode << "\n"
         << "size                 " << width << "x" << height << "\n"
         << "views                " << frames.size() << "\n"
         << "objects              " << objects << " (" << sceneTriangles << " triangles)\n"
         << "mean visible objects " << visible << " (" << source << ")\n"
         << "mean drawn triangles " << triangles << " (" << source << ")\n";
    if (means.hasOsgVis)
        text << "mean cull ms         " << std::setprecision(3) << means.cullMilliseconds << " (osgVis query)\n";
    else
        text << "mean cull ms         - (mode osg has no visibility query)\n";
    text << "mean OSG cull ms     " << std::setprecision(3) << means.osgCullMilliseconds << " (whole cull traversal)\n"
         << "total time           " << std::setprecision(2) << totalSeconds << " s\n";

    writeFile(std::filesystem::path(directory) / "report.json", json.str());
    writeFile(std::filesystem::path(directory) / "report.txt", text.str());
}
} // namespace osgVis::viewer
