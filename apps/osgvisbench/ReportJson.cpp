#include "ReportJson.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <stdexcept>

namespace osgVis::bench
{
namespace
{
std::string jsonString(const std::string& text)
{
    std::string quoted = "\"";
    for (unsigned char c : text)
    {
        if (c == '"' || c == '\\')
            quoted += {'\\', char(c)};
        else if (c < 0x20)
        {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", c);
            quoted += escape;
        }
        else
            quoted += char(c);
    }
    return quoted + "\"";
}

std::string jsonNumber(const std::optional<double>& value)
{
    if (!value || !std::isfinite(*value))
        return "null";
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", *value);
    return text;
}

void writeMode(std::ostream& out, const ModeResult& result)
{
    const ModeMetrics& m = result.metrics;
    out << "    " << jsonString(result.mode.name) << ": {\n"
        << "      \"false_invisible\": " << m.falseInvisible << ",\n"
        << "      \"efficacy\": " << jsonNumber(m.efficacy) << ",\n"
        << "      \"efficacy_objects\": " << jsonNumber(m.efficacyObjects) << ",\n"
        << "      \"occlusion_efficacy\": " << jsonNumber(m.occlusionEfficacy) << ",\n"
        << "      \"overestimation\": " << jsonNumber(m.overestimation) << ",\n"
        << "      \"drawn_fraction\": " << jsonNumber(m.drawnFraction) << ",\n"
        << "      \"cull_ms_median\": " << jsonNumber(m.cullMsMedian) << ",\n"
        << "      \"cull_ms_p99\": " << jsonNumber(m.cullMsP99) << ",\n"
        << "      \"fps\": " << jsonNumber(m.fps) << ",\n"
        << "      \"speedup_vs_osg\": " << jsonNumber(m.speedupVsOsg) << ",\n"
        << "      \"fps_vs_exact\": " << jsonNumber(m.fpsVsExact) << "\n"
        << "    }";
}

void writeSweepPoint(std::ostream& out, const SweepPoint& point)
{
    out << "    {\"mode\": " << jsonString(point.mode) << ", \"speed\": " << point.speed
        << ", \"threads\": " << point.threads << ", \"views\": " << point.views
        << ", \"cull_ms_median\": " << jsonNumber(point.cullMsMedian)
        << ", \"cull_ms_p99\": " << jsonNumber(point.cullMsP99)
        << ", \"visible_mean\": " << jsonNumber(point.visibleMean) << "}";
}

void writeSweeps(std::ostream& out, const SweepReport& sweeps)
{
    out << "  \"sweeps\": [";
    for (std::size_t i = 0; i < sweeps.points.size(); ++i)
    {
        out << (i ? ",\n" : "\n");
        writeSweepPoint(out, sweeps.points[i]);
    }
    out << (sweeps.points.empty() ? "],\n" : "\n  ],\n") << "  \"identical_across_threads\": {";
    for (std::size_t i = 0; i < sweeps.determinism.size(); ++i)
        out << (i ? ", " : "") << jsonString(sweeps.determinism[i].mode) << ": "
            << (sweeps.determinism[i].identicalAcrossThreads ? "true" : "false");
    out << "}\n";
}
void writeProgressive(std::ostream& out, const std::vector<ProgressiveRow>& rows)
{
    out << "  \"progressive\": [";
    for (std::size_t i = 0; i < rows.size(); ++i)
        out << (i ? ",\n" : "\n") << "    {\"stage\": " << jsonString(rows[i].stage)
            << ", \"drawn_fraction\": " << jsonNumber(rows[i].drawnFraction)
            << ", \"objects_fraction\": " << jsonNumber(rows[i].objectsFraction) << "}";
    out << (rows.empty() ? "],\n" : "\n  ],\n");
}
} // namespace

void writeReportJson(std::ostream& out, const BenchReport& report)
{
    out << "{\n"
        << "  \"scene\": " << jsonString(report.scene) << ",\n"
        << "  \"triangles\": " << report.triangles << ",\n"
        << "  \"objects\": " << report.objects << ",\n"
        << "  \"views\": " << report.views << ",\n"
        << "  \"size\": [" << report.width << ", " << report.height << "],\n"
        << "  \"cube\": " << (report.cube ? "true" : "false") << ",\n"
        << "  \"command\": " << jsonString(report.command) << ",\n"
        << "  \"oracle\": {\n"
        << "    \"supersample\": " << report.supersample << ",\n"
        << "    \"supersample_extra_objects\": " << report.supersampleExtras << ",\n"
        << "    \"views_with_supersample_extras\": [";
    for (std::size_t i = 0; i < report.viewsWithSupersampleExtras.size(); ++i)
        out << (i ? ", " : "") << report.viewsWithSupersampleExtras[i];
    out << "]\n"
        << "  },\n"
        << "  \"modes\": {\n";
    for (std::size_t i = 0; i < report.modes.size(); ++i)
    {
        writeMode(out, report.modes[i]);
        out << (i + 1 < report.modes.size() ? ",\n" : "\n");
    }
    out << "  },\n";
    writeProgressive(out, report.progressive);
    writeSweeps(out, report.sweeps);
    out << "}\n";
}

void saveReportJson(const std::string& path, const BenchReport& report)
{
    std::ofstream file(path);
    if (!file)
        throw std::runtime_error("cannot write JSON report '" + path + "'");
    writeReportJson(file, report);
    file.close();
    if (!file)
        throw std::runtime_error("failed writing JSON report '" + path + "'");
}
} // namespace osgVis::bench
