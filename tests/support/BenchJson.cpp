// SPDX-License-Identifier: MIT
#include "BenchJson.h"

#include <cstdlib>

namespace osgVis::test
{
std::string modeObject(const std::string& json, const std::string& mode)
{
    const std::size_t modes = json.find("\"modes\":");
    if (modes == std::string::npos)
        return {};
    const std::size_t begin = json.find("\"" + mode + "\": {", modes);
    if (begin == std::string::npos)
        return {};
    const std::size_t end = json.find('}', begin);
    return json.substr(begin, end == std::string::npos ? std::string::npos : end - begin + 1);
}

bool hasKey(const std::string& json, const std::string& key)
{
    return json.find("\"" + key + "\":") != std::string::npos;
}

std::optional<double> numberField(const std::string& json, const std::string& key)
{
    const std::string tag = "\"" + key + "\":";
    const std::size_t at = json.find(tag);
    if (at == std::string::npos)
        return std::nullopt;
    const char* text = json.c_str() + at + tag.size();
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text)
        return std::nullopt; // null
    return value;
}
} // namespace osgVis::test
