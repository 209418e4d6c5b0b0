// SPDX-License-Identifier: MIT
#pragma once
// Model files an application must refuse or survive, written fresh for each test.
#include <filesystem>

namespace osgVis::test
{
// A valid .osg file holding one empty Group: readable, but nothing to draw.
std::filesystem::path writeEmptyModel(const std::filesystem::path& dir);
// Bytes no OSG plugin understands, under a .osgb name.
std::filesystem::path writeGarbageModel(const std::filesystem::path& dir);
// An OBJ with one good triangle, one with a NaN vertex and one of zero area.
std::filesystem::path writeNanModel(const std::filesystem::path& dir);
} // namespace osgVis::test
