// SPDX-License-Identifier: MIT
#pragma once
// Enum values by their command-line names (scene kinds, forest layouts): one table gives the parse,
// the name and the list, and the error message names every known value.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace osgVis::gen
{
template <typename Value> struct Named
{
    Value value;
    const char* name;
};

// Throws std::invalid_argument "unknown <what> '<name>' (known: a, b, c)".
template <typename Value, std::size_t N>
Value parseNamed(const Named<Value> (&table)[N], const std::string& name, const char* what)
{
    std::string known;
    for (const Named<Value>& entry : table)
    {
        if (name == entry.name)
            return entry.value;
        known += (known.empty() ? "" : ", ") + std::string(entry.name);
    }
    throw std::invalid_argument("unknown " + std::string(what) + " '" + name + "' (known: " + known + ")");
}

template <typename Value, std::size_t N> const char* nameOf(const Named<Value> (&table)[N], Value value)
{
    for (const Named<Value>& entry : table)
        if (value == entry.value)
            return entry.name;
    return "unknown";
}

template <typename Value, std::size_t N> std::vector<std::string> namesIn(const Named<Value> (&table)[N])
{
    std::vector<std::string> names;
    for (const Named<Value>& entry : table)
        names.emplace_back(entry.name);
    return names;
}
} // namespace osgVis::gen
