// SPDX-License-Identifier: MIT
#include "ProgressiveJson.h"

#include <regex>

namespace osgVis::test
{
std::vector<ProgressiveStageRow> progressiveRows(const std::string& json)
{
    std::vector<ProgressiveStageRow> rows;
    const std::size_t begin = json.find("\"progressive\": [");
    if (begin == std::string::npos)
        return rows;
    const std::size_t end = json.find(']', begin);
    const std::string array = json.substr(begin, end - begin);
    static const std::regex row(R"re(\{"stage": "([^"]*)", "drawn_fraction": ([^,]+), "objects_fraction": ([^}]+)\})re");
    for (auto it = std::sregex_iterator(array.begin(), array.end(), row); it != std::sregex_iterator(); ++it)
        rows.push_back({(*it)[1].str(), std::stod((*it)[2].str()), std::stod((*it)[3].str())});
    return rows;
}
} // namespace osgVis::test
