// SPDX-License-Identifier: MIT
#include "BadModelFiles.h"

#include <fstream>

namespace osgVis::test
{
namespace
{
std::filesystem::path writeFile(const std::filesystem::path& path, const char* text)
{
    std::ofstream(path, std::ios::binary) << text;
    return path;
}
} // namespace

std::filesystem::path writeEmptyModel(const std::filesystem::path& dir)
{
    return writeFile(dir / "empty.osg", "Group {\n}\n");
}

std::filesystem::path writeGarbageModel(const std::filesystem::path& dir)
{
    return writeFile(dir / "garbage.osgb", "this is not a scene graph\n");
}

std::filesystem::path writeNanModel(const std::filesystem::path& dir)
{
    return writeFile(dir / "nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv 2 2 2\n"
                                      "f 1 2 3\nf 4 2 3\nf 5 5 1\n");
}
} // namespace osgVis::test
