// SPDX-License-Identifier: MIT
#include "ReportTable.h"

#include "Metrics.h"
#include "MisdrawnPixels.h"

#include <algorithm>
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

// Wide enough for the heading "mode" and every row's mode name.
template <typename Rows, typename NameOf> std::size_t nameColumnWidth(const Rows& rows, NameOf nameOf)
{
    std::size_t width = 4;
    for (const auto& row : rows)
        width = std::max(width, nameOf(row).size());
    return width;
}

void writeModeTable(std::ostream& out, const BenchReport& report)
{
    const std::size_t nameWidth =
        nameColumnWidth(report.modes, [](const ModeResult& result) { return result.mode.name; });
    out << leftCell("mode", nameWidth) << cell("false-invis", 12) << cell("efficacy", 10) << cell("occl.eff", 10)
        << cell("overest", 9) << cell("drawn%", 8) << cell("cull ms med/p99", 17) << cell("chain ms", 13)
        << cell("fps", 9)
        << cell("speedup", 9) << "\n";
    for (const ModeResult& result : report.modes)
    {
        const ModeMetrics& m = result.metrics;
        out << leftCell(result.mode.name, nameWidth) << cell(std::to_string(m.falseInvisible), 12)
            << cell(formatted(m.efficacy, "%.3f"), 10) << cell(formatted(m.occlusionEfficacy, "%.3f"), 10)
            << cell(formatted(m.overestimation, "%.2f"), 9) << cell(formatted(m.drawnFraction, "%.1f", 100.0), 8)
            << cell(formatted(m.cullMsMedian, "%.2f") + "/" + formatted(m.cullMsP99, "%.2f"), 17)
            << cell(formatted(m.chainMsMedian, "%.2f") + "/" + formatted(m.chainMsP99, "%.2f"), 13)
            << cell(formatted(m.fps, "%.1f"), 9) << cell(formatted(m.speedupVsOsg, "%.2fx"), 9) << "\n";
    }
}

void writeThreadingTable(std::ostream& out, const std::vector<ThreadingRow>& rows)
{
    out << "\nthreading (osgVis ms: the cull thread's time in osgVis per frame; fallback: async frames no region held;\n"
           "same: views drawing the main table's set, synchronous rows):\n";
    const std::size_t nameWidth = nameColumnWidth(rows, [](const ThreadingRow& row) { return row.mode; });
    out << leftCell("mode", nameWidth) << cell("threading", 41) << cell("async", 6) << cell("false-invis", 12)
        << cell("drawn%", 8) << cell("osgVis ms med/p99", 19) << cell("cull ms", 9) << cell("fallback", 9)
        << cell("fps", 8) << cell("vs single", 10) << cell("same", 10) << "\n";
    for (const ThreadingRow& row : rows)
    {
        std::string sameCell = "-";
        if (row.differingViews)
            sameCell = *row.differingViews == 0 ? "all" : std::to_string(*row.differingViews) + " differ";
        out << leftCell(row.mode, nameWidth) << cell(row.threading, 41) << cell(row.async ? "on" : "off", 6)
            << cell(std::to_string(row.falseInvisible), 12) << cell(formatted(row.drawnFraction, "%.1f", 100.0), 8)
            << cell(formatted(row.osgVisMsMedian, "%.3f") + "/" + formatted(row.osgVisMsP99, "%.3f"), 19)
            << cell(formatted(row.cullMsMedian, "%.2f"), 9)
            << cell(row.fallbackFrames ? std::to_string(*row.fallbackFrames) : "-", 9)
            << cell(formatted(row.fps, "%.1f"), 8) << cell(formatted(row.fpsVsSingleThreaded, "%.2fx"), 10)
            << cell(sameCell, 10) << "\n";
    }
}

void writeSweepTable(std::ostream& out, const SweepReport& sweeps)
{
    out << "\ncull-only sweeps (module chain on the extracted scene, no rendering; ms per query):\n";
    const std::size_t nameWidth = nameColumnWidth(sweeps.points, [](const SweepPoint& point) { return point.mode; });
    out << leftCell("mode", nameWidth) << cell("speed", 7) << cell("threads", 8) << cell("views", 7)
        << cell("cull ms med/p99", 17) << cell("visible", 10) << "\n";
    for (const SweepPoint& point : sweeps.points)
        out << leftCell(point.mode, nameWidth) << cell(std::to_string(point.speed) + "x", 7)
            << cell(std::to_string(point.threads), 8) << cell(std::to_string(point.views), 7)
            << cell(formatted(point.cullMsMedian, "%.3f") + "/" + formatted(point.cullMsP99, "%.3f"), 17)
            << cell(formatted(point.visibleMean, "%.1f"), 10) << "\n";
    for (const SweepDeterminism& determinism : sweeps.determinism)
    {
        out << determinism.mode << ": visible sets identical across thread counts: ";
        if (determinism.identicalAcrossThreads)
            out << "yes\n";
        else
            out << "NO (" << determinism.differingViews << " answers differ)\n";
    }
}
void writeMisdrawnTable(std::ostream& out, const BenchReport& report)
{
    out << "\nmis-drawn pixels per frame (pixels of the oracle's exact image at " << report.width << "x"
        << report.height << " showing an object the mode culled):\n";
    const std::size_t nameWidth =
        nameColumnWidth(report.modes, [](const ModeResult& result) { return result.mode.name; });
    out << leftCell("mode", nameWidth) << cell("frames>0", 9) << cell("%", 7) << cell("max", 8) << cell("mean", 9);
    for (std::size_t bin = 0; bin < MisdrawnPixels::Bins; ++bin)
        out << cell(misdrawnBinLabel(bin), 9);
    out << "\n";
    for (const ModeResult& result : report.modes)
    {
        if (!result.metrics.misdrawn)
            continue;
        const MisdrawnPixels& m = *result.metrics.misdrawn;
        const std::optional<double> percent =
            report.views ? std::optional<double>(double(m.framesWithAny) / double(report.views)) : std::nullopt;
        out << leftCell(result.mode.name, nameWidth) << cell(std::to_string(m.framesWithAny), 9)
            << cell(formatted(percent, "%.1f", 100.0), 7) << cell(std::to_string(m.maxPerFrame), 8)
            << cell(formatted(m.meanPerFrame, "%.2f"), 9);
        for (std::uint32_t frames : m.histogram)
            out << cell(std::to_string(frames), 9);
        out << "\n";
    }
}

std::string stepCell(const StepTiming& step)
{
    return formatted(step.median, "%.2f") + "/" + formatted(step.p99, "%.2f");
}

// The reasons with at least one frame: "first:1 stamp-expired:4".
std::string reasonsCell(const MaskSweepRow& row)
{
    std::string text;
    for (const auto& [reason, frames] : row.criticalReasons)
        if (frames != 0)
            text += (text.empty() ? "" : " ") + reason + ":" + std::to_string(frames);
    return text.empty() ? "-" : text;
}

void writeMaskSweepTable(std::ostream& out, const std::vector<MaskSweepRow>& rows)
{
    // Every row has the same observer: the sweep's one slowed walk.
    out << "\nmask sweep over the image-space shrinkage Delta (cull only; observer " << rows.front().slowdown
        << "x slower, V " << formatted(rows.front().maxEyeSpeed, "%.4g") << " units/s; step ms med/p99 over critical "
        << "frames):\n";
    const std::size_t nameWidth = nameColumnWidth(rows, [](const MaskSweepRow& row) { return row.mode; });
    out << leftCell("mode", nameWidth) << cell("Delta", 7) << cell("views", 7) << cell("crit%", 7) << cell("select", 13)
        << cell("rasterize", 13) << cell("pyramid", 13) << cell("mark", 13) << cell("cull crit", 10)
        << cell("cull other", 11) << cell("drawn%", 8) << cell("delta", 9) << "  critical reasons\n";
    for (const MaskSweepRow& row : rows)
        out << leftCell(row.mode, nameWidth) << cell(formatted(row.delta, "%g"), 7)
            << cell(std::to_string(row.views), 7) << cell(formatted(row.criticalFraction, "%.1f", 100.0), 7)
            << cell(stepCell(row.select), 13) << cell(stepCell(row.rasterize), 13) << cell(stepCell(row.pyramid), 13)
            << cell(stepCell(row.mark), 13) << cell(formatted(row.cullMsCriticalMedian, "%.2f"), 10)
            << cell(formatted(row.cullMsNonCriticalMedian, "%.3f"), 11)
            << cell(formatted(row.drawnFraction, "%.1f", 100.0), 8) << cell(formatted(row.regionMedian, "%.3g"), 9)
            << "  " << reasonsCell(row) << "\n";
}

void writeProgressiveTable(std::ostream& out, const std::vector<ProgressiveRow>& rows)
{
    out << "\nprogressive cell-portal table (cull only, mean over the views):\n";
    std::size_t nameWidth = 5;
    for (const ProgressiveRow& row : rows)
        nameWidth = std::max(nameWidth, row.stage.size());
    out << leftCell("stage", nameWidth) << cell("drawn%", 9) << cell("objects%", 10) << "\n";
    for (const ProgressiveRow& row : rows)
        out << leftCell(row.stage, nameWidth) << cell(formatted(row.drawnFraction, "%.2f", 100.0), 9)
            << cell(formatted(row.objectsFraction, "%.2f", 100.0), 10) << "\n";
}
} // namespace

void writeReportTable(std::ostream& out, const BenchReport& report)
{
    out << "scene: " << report.scene << "\n"
        << "objects: " << report.objects << "  triangles: " << report.triangles << "  views: " << report.views
        << (report.cube ? " (cube faces)" : "") << "  size: " << report.width << "x" << report.height
        << "  oracle supersample: " << report.supersample << " (extra objects in "
        << report.viewsWithSupersampleExtras.size() << " views)\n\n";
    if (!report.modes.empty())
        writeModeTable(out, report);
    if (const std::string best = bestModeSummary(report); !best.empty())
        out << "\n" << best << "\n";
    if (std::any_of(report.modes.begin(), report.modes.end(),
                    [](const ModeResult& result) { return result.metrics.misdrawn.has_value(); }))
        writeMisdrawnTable(out, report);
    if (!report.progressive.empty())
        writeProgressiveTable(out, report.progressive);
    if (!report.sweeps.points.empty())
        writeSweepTable(out, report.sweeps);
    if (!report.maskSweep.empty())
        writeMaskSweepTable(out, report.maskSweep);
    if (!report.threading.empty())
        writeThreadingTable(out, report.threading);
    if (report.explanation)
        writeExplanation(out, *report.explanation);
    out.flush();
}
} // namespace osgVis::bench
