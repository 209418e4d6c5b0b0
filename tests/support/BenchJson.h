// SPDX-License-Identifier: MIT
#pragma once
// Just enough reading of osgvisbench's JSON for the tests: fields of the top level and of one mode
// object. Not a general JSON parser; the bench writes one key per line with flat mode objects.
#include <optional>
#include <string>

namespace osgVis::test
{
// The text of the object `"modes": { "<mode>": { ... } }`, or empty when the mode is missing.
std::string modeObject(const std::string& json, const std::string& mode);
// True when `"key":` occurs in `json`.
bool hasKey(const std::string& json, const std::string& key);
// The number after `"key":`; nullopt for null or a missing key.
std::optional<double> numberField(const std::string& json, const std::string& key);
} // namespace osgVis::test
