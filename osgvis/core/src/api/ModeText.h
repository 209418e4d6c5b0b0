// SPDX-License-Identifier: MIT
#pragma once
// The text of mode strings, read the same way by the registry (createChain) and the typed settings
// (parseChainSettings): parts split at any of `separators` and trimmed, and names listed in messages.
#include <string>
#include <vector>

namespace osgVis::core::modetext
{
inline std::string trimmed(const std::string& s)
{
    const char* space = " \t\r\n";
    const std::size_t first = s.find_first_not_of(space);
    return first == std::string::npos ? std::string() : s.substr(first, s.find_last_not_of(space) - first + 1);
}

// "a + b,c" at ",+" → {"a", "b", "c"}; empty parts are kept, so a caller can refuse them.
inline std::vector<std::string> split(const std::string& text, const char* separators)
{
    std::vector<std::string> parts;
    for (std::size_t start = 0;;)
    {
        const std::size_t at = text.find_first_of(separators, start);
        parts.push_back(trimmed(text.substr(start, at == std::string::npos ? std::string::npos : at - start)));
        if (at == std::string::npos)
            return parts;
        start = at + 1;
    }
}

inline std::string joined(const std::vector<std::string>& names)
{
    std::string out;
    for (const std::string& name : names)
        out += (out.empty() ? "" : ", ") + name;
    return out;
}
} // namespace osgVis::core::modetext
