// SPDX-License-Identifier: MIT
#include "ReportJson.h"

#include "TextFile.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <stdexcept>

namespace osgVis::bench
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

namespace
{
std::string jsonNumber(const std::optional<double>& value)
{
    if (!value || !std::isfinite(*value))
        return "null";
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", *value);
    return text;
}

// Integers as JSON numbers, or null when the oracle counted no pixels.
template <typename Integer> std::string jsonCount(const std::optional<MisdrawnPixels>& misdrawn, Integer value)
{
    return misdrawn ? std::to_string(value) : "null";
}

void writeMisdrawn(std::ostream& out, const std::optional<MisdrawnPixels>& misdrawn, std::size_t views)
{
    const MisdrawnPixels m = misdrawn.value_or(MisdrawnPixels{});
    const std::optional<double> fraction =
        misdrawn && views ? std::optional<double>(double(m.framesWithAny) / double(views)) : std::nullopt;
    out << "      \"misdrawn_frames\": " << jsonCount(misdrawn, m.framesWithAny) << ",\n"
        << "      \"misdrawn_frames_fraction\": " << jsonNumber(fraction) << ",\n"
        << "      \"misdrawn_max\": " << jsonCount(misdrawn, m.maxPerFrame) << ",\n"
        << "      \"misdrawn_mean\": " << jsonNumber(m.meanPerFrame) << ",\n"
        << "      \"misdrawn_histogram\": ";
    // note: an array, not an object keyed by bin: mode objects stay flat (one level of braces)
    if (!misdrawn)
        out << "null,\n";
    else
    {
        out << "[";
        for (std::size_t bin = 0; bin < MisdrawnPixels::Bins; ++bin)
            out << (bin ? ", " : "") << m.histogram[bin];
        out << "],\n";
    }
}

void writeMode(std::ostream& out, const ModeResult& result, std::size_t views)
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
        << "      \"chain_ms_median\": " << jsonNumber(m.chainMsMedian) << ",\n"
        << "      \"chain_ms_p99\": " << jsonNumber(m.chainMsP99) << ",\n"
        << "      \"fps\": " << jsonNumber(m.fps) << ",\n";
    writeMisdrawn(out, m.misdrawn, views);
    out << "      \"speedup_vs_osg\": " << jsonNumber(m.speedupVsOsg) << ",\n"
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
    out << "},\n";
}
void writeMaskSweepRow(std::ostream& out, const MaskSweepRow& row)
{
    out << "    {\"mode\": " << jsonString(row.mode) << ", \"delta\": " << jsonNumber(row.delta)
        << ", \"views\": " << row.views << ", \"critical_frames\": " << row.criticalFrames
        << ", \"critical_fraction\": " << jsonNumber(row.criticalFraction) << ", \"slowdown\": " << row.slowdown
        << ", \"max_eye_speed\": " << jsonNumber(row.maxEyeSpeed);
    const std::pair<const char*, const StepTiming*> steps[] = {
        {"select", &row.select}, {"rasterize", &row.rasterize}, {"pyramid", &row.pyramid}, {"mark", &row.mark}};
    for (const auto& [name, step] : steps)
        out << ",\n     \"" << name << "_ms_median\": " << jsonNumber(step->median) << ", \"" << name
            << "_ms_p99\": " << jsonNumber(step->p99);
    out << ",\n     \"cull_ms_critical_median\": " << jsonNumber(row.cullMsCriticalMedian)
        << ", \"cull_ms_noncritical_median\": " << jsonNumber(row.cullMsNonCriticalMedian)
        << ", \"drawn_fraction\": " << jsonNumber(row.drawnFraction)
        << ", \"region_median\": " << jsonNumber(row.regionMedian) << ",\n     \"critical_reasons\": {";
    for (std::size_t i = 0; i < row.criticalReasons.size(); ++i)
        out << (i ? ", " : "") << jsonString(row.criticalReasons[i].first) << ": " << row.criticalReasons[i].second;
    out << "}}";
}

void writeMaskSweep(std::ostream& out, const std::vector<MaskSweepRow>& rows)
{
    out << "  \"mask_sweep\": [";
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        out << (i ? ",\n" : "\n");
        writeMaskSweepRow(out, rows[i]);
    }
    out << (rows.empty() ? "],\n" : "\n  ],\n");
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
std::string jsonCount(const std::optional<std::uint64_t>& value)
{
    return value ? std::to_string(*value) : "null";
}

void writeThreading(std::ostream& out, const std::vector<ThreadingRow>& rows)
{
    out << "  \"threading\": [";
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const ThreadingRow& row = rows[i];
        out << (i ? ",\n" : "\n") << "    {\"mode\": " << jsonString(row.mode)
            << ", \"threading\": " << jsonString(row.threading) << ", \"async\": " << (row.async ? "true" : "false")
            << ", \"false_invisible\": " << row.falseInvisible
            << ", \"drawn_fraction\": " << jsonNumber(row.drawnFraction)
            << ",\n     \"osgvis_ms_median\": " << jsonNumber(row.osgVisMsMedian)
            << ", \"osgvis_ms_p99\": " << jsonNumber(row.osgVisMsP99)
            << ", \"cull_ms_median\": " << jsonNumber(row.cullMsMedian)
            << ", \"fallback_frames\": "
            << jsonCount(row.fallbackFrames ? std::optional<std::uint64_t>(*row.fallbackFrames) : std::nullopt)
            << ",\n     \"fps\": " << jsonNumber(row.fps)
            << ", \"fps_vs_single_threaded\": " << jsonNumber(row.fpsVsSingleThreaded)
            << ", \"views_differing_from_main_pass\": "
            << jsonCount(row.differingViews ? std::optional<std::uint64_t>(*row.differingViews) : std::nullopt) << "}";
    }
    out << (rows.empty() ? "],\n" : "\n  ],\n");
}
template <typename Field> void writeViewColumn(std::ostream& out, const char* key, const std::vector<ViewRecord>& views,
                                               Field field, bool last = false)
{
    out << "\"" << key << "\": [";
    for (std::size_t v = 0; v < views.size(); ++v)
        out << (v ? ", " : "") << field(views[v]);
    out << (last ? "]" : "], ");
}

// One record per view, as columns: every array has one entry per view of the pass.
void writeViewColumns(std::ostream& out, const std::vector<ViewRecord>& views)
{
    writeViewColumn(out, "view_objects", views, [](const ViewRecord& r) { return std::to_string(r.objects); });
    writeViewColumn(out, "view_triangles", views, [](const ViewRecord& r) { return std::to_string(r.triangles); });
    writeViewColumn(out, "view_false_invisible", views,
                    [](const ViewRecord& r) { return std::to_string(r.falseInvisible); });
    writeViewColumn(out, "view_cull_ms", views, [](const ViewRecord& r) { return jsonNumber(r.cullMs); });
    writeViewColumn(
        out, "view_digest", views,
        [](const ViewRecord& r)
        {
            char hex[24];
            std::snprintf(hex, sizeof hex, "\"%016llx\"", static_cast<unsigned long long>(r.digest));
            return std::string(hex);
        },
        true);
}

void writePerView(std::ostream& out, const BenchReport& report)
{
    out << "  \"per_view\": {";
    for (std::size_t i = 0; i < report.modes.size(); ++i)
    {
        out << (i ? ",\n" : "\n") << "    " << jsonString(report.modes[i].mode.name) << ": {";
        writeViewColumns(out, report.modes[i].perView);
        out << "}";
    }
    out << (report.modes.empty() ? "},\n" : "\n  },\n") << "  \"threading_per_view\": [";
    for (std::size_t i = 0; i < report.threading.size(); ++i)
    {
        const ThreadingRow& row = report.threading[i];
        out << (i ? ",\n" : "\n") << "    {\"mode\": " << jsonString(row.mode)
            << ", \"threading\": " << jsonString(row.threading) << ", \"async\": " << (row.async ? "true" : "false")
            << ", ";
        writeViewColumns(out, row.perView);
        out << "}";
    }
    out << (report.threading.empty() ? "]\n" : "\n  ]\n");
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
        writeMode(out, report.modes[i], report.views);
        out << (i + 1 < report.modes.size() ? ",\n" : "\n");
    }
    out << "  },\n";
    writeProgressive(out, report.progressive);
    writeMaskSweep(out, report.maskSweep);
    writeThreading(out, report.threading);
    writeSweeps(out, report.sweeps);
    writePerView(out, report);
    out << "}\n";
}

void saveReportJson(const std::string& path, const BenchReport& report)
{
    writeTextFile(path, "JSON report", [&](std::ostream& out) { writeReportJson(out, report); });
}
} // namespace osgVis::bench
