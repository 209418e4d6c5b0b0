#include "ReportTable.h"

#include <cstdio>
#include <ostream>
#include <string>

namespace osgVis::bench
{
namespace
{
std::string formatted(const std::optional<double>& value, const char* format, double scale = 1.0)
{
    if (!value)
        return "-";
    char text[32];
    std::snprintf(text, sizeof text, format, *value * scale);
    return text;
}

std::string leftCell(const std::string& text, std::size_t width)
{
    return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

std::string cell(const std::string& text, int width)
{
    return text.size() >= std::size_t(width) ? text + " " : std::string(std::size_t(width) - text.size(), ' ') + text;
}
} // namespace

void writeReportTable(std::ostream& out, const BenchReport& report)
{
    out << "scene: " << report.scene << "\n"
        << "objects: " << report.objects << "  triangles: " << report.triangles << "  views: " << report.views
        << "  size: " << report.width << "x" << report.height << "  oracle supersample: " << report.supersample
        << " (extra objects in " << report.viewsWithSupersampleExtras.size() << " views)\n\n";

    std::size_t nameWidth = 4;
    for (const ModeResult& result : report.modes)
        nameWidth = std::max(nameWidth, result.mode.name.size());
    out << leftCell("mode", nameWidth) << cell("false-invis", 12) << cell("efficacy", 10) << cell("occl.eff", 10)
        << cell("overest", 9) << cell("drawn%", 8) << cell("cull ms med/p99", 17) << cell("fps", 9)
        << cell("speedup", 9) << "\n";
    for (const ModeResult& result : report.modes)
    {
        const ModeMetrics& m = result.metrics;
        out << leftCell(result.mode.name, nameWidth) << cell(std::to_string(m.falseInvisible), 12)
            << cell(formatted(m.efficacy, "%.3f"), 10) << cell(formatted(m.occlusionEfficacy, "%.3f"), 10)
            << cell(formatted(m.overestimation, "%.2f"), 9) << cell(formatted(m.drawnFraction, "%.1f", 100.0), 8)
            << cell(formatted(m.cullMsMedian, "%.2f") + "/" + formatted(m.cullMsP99, "%.2f"), 17)
            << cell(formatted(m.fps, "%.1f"), 9) << cell(formatted(m.speedupVsOsg, "%.2fx"), 9) << "\n";
    }
    out.flush();
}
} // namespace osgVis::bench
