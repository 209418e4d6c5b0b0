// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Data the core does not know, by name, for modules that do (Luka §3.3, "generic attributes"):
/// bytes attached to an object or to the whole scene.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace osgVis::core
{
class NamedAttributes
{
public:
    /// `object` may be ~0u (InvalidObject): the scene. Empty bytes remove the attribute.
    void set(std::uint32_t object, const std::string& name, std::vector<std::uint8_t> bytes)
    {
        if (bytes.empty())
            _values.erase({object, name});
        else
            _values[{object, name}] = std::move(bytes);
    }
    /// nullptr when the attribute is not set.
    const std::vector<std::uint8_t>* find(std::uint32_t object, const std::string& name) const
    {
        const auto it = _values.find({object, name});
        return it == _values.end() ? nullptr : &it->second;
    }
    std::size_t size() const { return _values.size(); }

private:
    std::map<std::pair<std::uint32_t, std::string>, std::vector<std::uint8_t>> _values;
};
} // namespace osgVis::core
