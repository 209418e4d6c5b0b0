// SPDX-License-Identifier: MIT
#include "SweepJson.h"

#include "BenchJson.h"

namespace osgVis::test
{
namespace
{
std::string stringField(const std::string& object, const std::string& key)
{
    const std::string tag = "\"" + key + "\": \"";
    const std::size_t at = object.find(tag);
    if (at == std::string::npos)
        return {};
    const std::size_t begin = at + tag.size();
    return object.substr(begin, object.find('"', begin) - begin);
}
} // namespace

std::vector<SweepEntry> sweepEntries(const std::string& json)
{
    std::vector<SweepEntry> entries;
    const std::size_t sweeps = json.find("\"sweeps\": [");
    if (sweeps == std::string::npos)
        return entries;
    const std::size_t end = json.find(']', sweeps);
    for (std::size_t begin = json.find('{', sweeps); begin < end; begin = json.find('{', begin + 1))
    {
        const std::string object = json.substr(begin, json.find('}', begin) - begin + 1);
        SweepEntry entry;
        entry.mode = stringField(object, "mode");
        entry.speed = numberField(object, "speed").value_or(-1);
        entry.threads = numberField(object, "threads").value_or(-1);
        entry.views = numberField(object, "views").value_or(-1);
        entry.cullMsMedian = numberField(object, "cull_ms_median");
        entry.cullMsP99 = numberField(object, "cull_ms_p99");
        entry.visibleMean = numberField(object, "visible_mean");
        entries.push_back(entry);
    }
    return entries;
}

std::optional<bool> identicalAcrossThreads(const std::string& json, const std::string& mode)
{
    const std::size_t map = json.find("\"identical_across_threads\": {");
    if (map == std::string::npos)
        return std::nullopt;
    const std::string tag = "\"" + mode + "\": ";
    const std::size_t at = json.find(tag, map);
    if (at == std::string::npos || at > json.find('}', map))
        return std::nullopt;
    return json.compare(at + tag.size(), 4, "true") == 0;
}
} // namespace osgVis::test
