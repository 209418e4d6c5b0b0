// SPDX-License-Identifier: MIT
#include "ReportHtml.h"

#include "Metrics.h"
#include "TextFile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <stdexcept>

namespace osgVis::bench
{
namespace
{
std::string escaped(const std::string& text)
{
    std::string out;
    for (const char c : text)
        switch (c)
        {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    return out;
}

std::string number(const std::optional<double>& value, const char* format, double scale = 1.0)
{
    if (!value || !std::isfinite(*value))
        return "&ndash;";
    char text[32];
    std::snprintf(text, sizeof text, format, *value * scale);
    return text;
}

// Line colours by mode name; exact is black and drawn thicker, as the line the others approach.
std::string colourOf(const BenchMode& mode, std::size_t index)
{
    if (mode.kind == BenchMode::Kind::Exact)
        return "#000000";
    if (mode.kind == BenchMode::Kind::OsgDefault)
        return "#8c8c8c";
    static const char* const palette[] = {"#1f77b4", "#2ca02c", "#ff7f0e", "#9467bd", "#d62728", "#17becf", "#bcbd22", "#e377c2"};
    return palette[index % (sizeof palette / sizeof *palette)];
}

// The smallest 1, 2 or 5 × 10^k at or above `value`: a plot's top that ticks read well at.
double niceCeiling(double value)
{
    const double magnitude = std::pow(10.0, std::floor(std::log10(value)));
    for (const double step : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (step * magnitude >= value)
            return step * magnitude;
    return 10.0 * magnitude;
}

// 120000 as "120k", 2500000 as "2.5M", small values as they are.
std::string tickText(double value)
{
    char text[32];
    if (value >= 1e6)
        std::snprintf(text, sizeof text, "%gM", value / 1e6);
    else if (value >= 1e4)
        std::snprintf(text, sizeof text, "%gk", value / 1e3);
    else
        std::snprintf(text, sizeof text, "%g", value);
    return text;
}

struct Series
{
    std::string name, colour;
    std::vector<double> values;
    double width = 1.5;
    std::vector<std::size_t> marked; // views with a false-invisible object
};

// A line plot of per-view values, views along x; marked views get a red cross on their series.
void writePlot(std::ostream& out, const std::string& title, const std::string& yLabel, const std::vector<Series>& series)
{
    const double width = 960, height = 300, left = 70, right = 160, top = 30, bottom = 40;
    std::size_t views = 0;
    double maxValue = 0.0;
    for (const Series& s : series)
    {
        views = std::max(views, s.values.size());
        for (const double v : s.values)
            if (std::isfinite(v))
                maxValue = std::max(maxValue, v);
    }
    if (views == 0)
        return;
    maxValue = maxValue > 0.0 ? niceCeiling(maxValue) : 1.0;
    const double plotW = width - left - right, plotH = height - top - bottom;
    const auto x = [&](std::size_t v) { return left + (views > 1 ? plotW * double(v) / double(views - 1) : 0.0); };
    const auto y = [&](double value) { return top + plotH * (1.0 - value / maxValue); };
    char buffer[256];
    out << "<svg class=\"plot\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << " " << height << "\" role=\"img\" aria-label=\"" << escaped(title) << "\">\n"
        << "<rect x=\"0\" y=\"0\" width=\"" << width << "\" height=\"" << height << "\" fill=\"#ffffff\"/>\n"
        << "<text x=\"" << left << "\" y=\"18\" class=\"title\">" << escaped(title) << "</text>\n";
    for (int tick = 0; tick <= 4; ++tick)
    {
        const double value = maxValue * tick / 4.0;
        std::snprintf(buffer, sizeof buffer,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#e4e4e4\"/>"
                      "<text x=\"%.1f\" y=\"%.1f\" class=\"tick\" text-anchor=\"end\">%s</text>\n",
                      left, y(value), left + plotW, y(value), left - 6, y(value) + 4, tickText(value).c_str());
        out << buffer;
    }
    std::snprintf(buffer, sizeof buffer,
                  "<text x=\"%.1f\" y=\"%.1f\" class=\"tick\" text-anchor=\"middle\">view (0 to %zu)</text>\n"
                  "<text x=\"14\" y=\"%.1f\" class=\"tick\" transform=\"rotate(-90 14 %.1f)\" text-anchor=\"middle\">%s</text>\n",
                  left + plotW / 2, height - 10, views - 1, top + plotH / 2, top + plotH / 2, escaped(yLabel).c_str());
    out << buffer;
    for (std::size_t i = 0; i < series.size(); ++i)
    {
        const Series& s = series[i];
        out << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"" << s.width << "\" points=\"";
        for (std::size_t v = 0; v < s.values.size(); ++v)
            if (std::isfinite(s.values[v]))
            {
                std::snprintf(buffer, sizeof buffer, "%.1f,%.1f ", x(v), y(s.values[v]));
                out << buffer;
            }
        out << "\"/>\n";
        for (const std::size_t v : s.marked)
        {
            const double cx = x(v), cy = y(v < s.values.size() && std::isfinite(s.values[v]) ? s.values[v] : 0.0);
            std::snprintf(buffer, sizeof buffer,
                          "<path d=\"M%.1f %.1fl8 8m0 -8l-8 8\" stroke=\"#e00000\" stroke-width=\"2.5\"/>\n", cx - 4,
                          cy - 4);
            out << buffer;
        }
        const double ly = top + 16.0 * double(i);
        std::snprintf(buffer, sizeof buffer,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"%.1f\"/>"
                      "<text x=\"%.1f\" y=\"%.1f\" class=\"legend\">%s%s</text>\n",
                      width - right + 12, ly, width - right + 36, ly, s.colour.c_str(), std::max(2.0, s.width),
                      width - right + 42, ly + 4, escaped(s.name).c_str(), s.marked.empty() ? "" : " (\xE2\x9C\x95 missed)");
        out << buffer;
    }
    out << "</svg>\n";
}

std::vector<Series> perViewSeries(const BenchReport& report, const std::function<double(const ViewRecord&)>& value)
{
    std::vector<Series> series;
    for (std::size_t i = 0; i < report.modes.size(); ++i)
    {
        const ModeResult& result = report.modes[i];
        Series s;
        s.name = result.mode.name;
        s.colour = colourOf(result.mode, i);
        s.width = result.mode.kind == BenchMode::Kind::Exact ? 3.0 : 1.5;
        for (std::size_t v = 0; v < result.perView.size(); ++v)
        {
            s.values.push_back(value(result.perView[v]));
            if (result.perView[v].falseInvisible != 0)
                s.marked.push_back(v);
        }
        series.push_back(std::move(s));
    }
    return series;
}

void writeModeTable(std::ostream& out, const BenchReport& report)
{
    out << "<table><tr><th>mode</th><th>false-invisible</th><th>efficacy</th><th>occlusion efficacy</th>"
           "<th>overestimation</th><th>drawn %</th><th>cull ms median / p99</th><th>fps</th><th>vs osg</th></tr>\n";
    for (const ModeResult& r : report.modes)
    {
        const ModeMetrics& m = r.metrics;
        const bool bad = r.mode.conservative && m.falseInvisible != 0;
        out << "<tr><td>" << escaped(r.mode.name) << (r.mode.conservative ? "" : " <small>(not conservative)</small>")
            << "</td><td class=\"" << (bad ? "bad" : "num") << "\">" << m.falseInvisible << "</td><td class=\"num\">"
            << number(m.efficacy, "%.3f") << "</td><td class=\"num\">" << number(m.occlusionEfficacy, "%.3f")
            << "</td><td class=\"num\">" << number(m.overestimation, "%.2f") << "</td><td class=\"num\">"
            << number(m.drawnFraction, "%.1f", 100.0) << "</td><td class=\"num\">" << number(m.cullMsMedian, "%.2f")
            << " / " << number(m.cullMsP99, "%.2f") << "</td><td class=\"num\">" << number(m.fps, "%.1f")
            << "</td><td class=\"num\">" << number(m.speedupVsOsg, "%.2f&times;") << "</td></tr>\n";
    }
    out << "</table>\n";
}

void writeProgressive(std::ostream& out, const std::vector<ProgressiveRow>& rows)
{
    if (rows.empty())
        return;
    out << "<h2>Cell-portal, stage by stage</h2>\n<p>Mean over the views of the fraction of the scene each stage "
           "keeps (Teller &amp; S&eacute;quin's progressive table).</p>\n<table><tr><th>stage</th><th>drawn "
           "triangles %</th><th>objects %</th></tr>\n";
    for (const ProgressiveRow& row : rows)
        out << "<tr><td>" << escaped(row.stage) << "</td><td class=\"num\">" << number(row.drawnFraction, "%.1f", 100.0)
            << "</td><td class=\"num\">" << number(row.objectsFraction, "%.1f", 100.0) << "</td></tr>\n";
    out << "</table>\n";
}

void writeThreading(std::ostream& out, const std::vector<ThreadingRow>& rows)
{
    if (rows.empty())
        return;
    out << "<h2>Threading models</h2>\n<table><tr><th>mode</th><th>threading</th><th>async</th><th>false-invisible</th>"
           "<th>drawn %</th><th>osgVis ms median</th><th>fps</th></tr>\n";
    for (const ThreadingRow& row : rows)
        out << "<tr><td>" << escaped(row.mode) << "</td><td>" << escaped(row.threading) << "</td><td>"
            << (row.async ? "on" : "off") << "</td><td class=\"" << (row.conservative && row.falseInvisible ? "bad" : "num")
            << "\">" << row.falseInvisible << "</td><td class=\"num\">" << number(row.drawnFraction, "%.1f", 100.0)
            << "</td><td class=\"num\">" << number(row.osgVisMsMedian, "%.3f") << "</td><td class=\"num\">"
            << number(row.fps, "%.1f") << "</td></tr>\n";
    out << "</table>\n";
}
} // namespace

void writeReportHtml(std::ostream& out, const BenchReport& report)
{
    std::uint64_t missed = 0;
    for (const ModeResult& r : report.modes)
        if (r.mode.conservative)
            missed += r.metrics.falseInvisible;
    out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>osgVis bench: "
        << escaped(report.scene) << "</title>\n<style>\n"
        << "body{font-family:sans-serif;margin:24px;color:#222;max-width:1000px}"
           "h1{font-size:22px}h2{font-size:17px;margin-top:28px}"
           "table{border-collapse:collapse;font-size:13px}td,th{border:1px solid #ccc;padding:3px 8px}"
           "th{background:#f0f0f0}td.num{text-align:right}td.bad{text-align:right;background:#f8c0c0}"
           ".summary{font-size:15px;background:#eef6ee;padding:8px;border-left:4px solid #2ca02c}"
           ".alarm{font-size:15px;background:#fbe3e3;padding:8px;border-left:4px solid #e00000}"
           ".plot text.title{font-size:14px;font-weight:bold}.plot text.tick{font-size:11px;fill:#555}"
           ".plot text.legend{font-size:12px}figure{margin:12px 0}img{max-width:100%}"
           "figcaption{font-size:13px;color:#444}code{font-size:12px}\n"
        << "</style></head><body>\n<h1>osgVis bench: " << escaped(report.scene) << "</h1>\n<p>" << report.objects
        << " objects, " << report.triangles << " triangles; " << report.views << " views at " << report.width << "&times;"
        << report.height << (report.cube ? " (six cube faces per walk key)" : "") << "; oracle supersample "
        << report.supersample << ".<br><code>" << escaped(report.command) << "</code></p>\n";
    if (const std::string best = bestModeSummary(report); !best.empty())
        out << "<p class=\"summary\">" << escaped(best) << ".</p>\n";
    out << "<p class=\"" << (missed ? "alarm" : "summary") << "\">" << missed
        << " false-invisible objects in conservative modes over all views: "
        << (missed ? "a visible object was culled." : "no visible object was culled (exact-visibility oracle).")
        << "</p>\n<h2>All modes</h2>\n";
    writeModeTable(out, report);
    out << "<h2>Per view</h2>\n<p>Triangles each mode drew in each view; <b>exact</b> (black) is what is really "
           "visible. A red &#x2715; marks a view where a mode culled a visible object.</p>\n";
    writePlot(out, "drawn triangles per view", "triangles",
              perViewSeries(report, [](const ViewRecord& r) { return double(r.triangles); }));
    writePlot(out, "cull time per view", "ms", perViewSeries(report, [](const ViewRecord& r) { return r.cullMs; }));
    writeProgressive(out, report.progressive);
    writeThreading(out, report.threading);
    if (!report.pictures.empty())
    {
        out << "<h2>Pictures</h2>\n<p>Left: " << escaped(report.pictureBaseline) << ". Middle: "
            << escaped(report.pictureMode)
            << " (the same pixels, fewer triangles). Right: top-down map of what " << escaped(report.pictureMode)
            << " drew (green), culled inside the view frustum (red) and left outside it (grey); the frustum in "
               "yellow, the eye in white.</p>\n";
        for (std::size_t i = 0; i < report.pictures.size(); ++i)
            out << "<figure><img src=\"" << escaped(report.pictures[i]) << "\" alt=\"view " << report.pictureViews[i]
                << "\"><figcaption>view " << report.pictureViews[i] << "</figcaption></figure>\n";
    }
    out << "</body></html>\n";
}

std::string saveReportHtml(const std::string& directory, const BenchReport& report)
{
    const std::string path = (std::filesystem::path(directory) / "index.html").string();
    writeTextFile(path, "report", [&](std::ostream& out) { writeReportHtml(out, report); });
    return path;
}
} // namespace osgVis::bench
