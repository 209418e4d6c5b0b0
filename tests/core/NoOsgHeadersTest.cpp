// SPDX-License-Identifier: MIT
// The core must stay renderer-independent: no file under osgvis/core may include an OSG, OpenThreads
// or GL header. Scans the sources, not the build, so it also covers headers no target compiles.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// `#include <dir/...>` or `#include "dir/..."` where dir is an OSG library (osg, osgDB, osgUtil, ...;
// any osg* except osgVis), OpenThreads, or a GL loader/API directory.
const std::regex& forbiddenInclude()
{
    static const std::regex pattern(
        R"(^\s*#\s*include\s*[<"]\s*()"
        R"(osg(?!Vis/)[A-Za-z]*/|OpenThreads/|GL/|GLES[0-9]*/|GLFW/|EGL/|KHR/|epoxy/|glad/))");
    return pattern;
}

// "line: text" for each offending include in `text`.
std::vector<std::string> forbiddenIncludes(const std::string& text)
{
    std::vector<std::string> found;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number)
    {
        if (std::regex_search(line, forbiddenInclude()))
            found.push_back(std::to_string(number) + ": " + line);
    }
    return found;
}
} // namespace

TEST(NoOsgHeaders, ScannerCatchesOffendingLines)
{
    for (const char* bad : {"#include <osg/Node>", "  #  include \"osgDB/ReadFile\"", "#include <osgUtil/CullVisitor>",
                            "#include <osgViewer/Viewer>", "#include <osgGA/GUIEventHandler>",
                            "#include <osgText/Text>", "#include <osgShadow/ShadowMap>",
                            "#include <OpenThreads/Mutex>", "#include <GL/gl.h>", "#include <GLES3/gl3.h>",
                            "#include <GLFW/glfw3.h>", "#include <epoxy/gl.h>", "#include <glad/glad.h>"})
        EXPECT_EQ(forbiddenIncludes(std::string("int a;\n") + bad + "\n").size(), 1u) << bad;
    EXPECT_EQ(forbiddenIncludes("#include <osg/Node>\n#include <GL/gl.h>\n").front(), "1: #include <osg/Node>");
}

TEST(NoOsgHeaders, ScannerAcceptsCoreIncludes)
{
    for (const char* good : {"#include <osgVis/core/geometry/Aabb.h>", "#include <glm/glm.hpp>", "#include <tbb/parallel_for.h>",
                             "#include <vector>", "// #include <osg/Node> (why the core does not)",
                             "#include \"OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh\""})
        EXPECT_TRUE(forbiddenIncludes(good).empty()) << good;
}

TEST(NoOsgHeaders, CoreIncludesNoOsgOrGlHeader)
{
    namespace fs = std::filesystem;
    const fs::path core = fs::path(OSGVIS_SOURCE_DIR) / "osgvis" / "core";
    ASSERT_TRUE(fs::is_directory(core)) << core;
    std::size_t scanned = 0;
    std::vector<std::string> offences;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(core))
    {
        if (!entry.is_regular_file())
            continue;
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        ++scanned;
        for (const std::string& hit : forbiddenIncludes(text.str()))
            offences.push_back(entry.path().string() + ":" + hit);
    }
    EXPECT_GT(scanned, 10u);
    std::string report;
    for (const std::string& o : offences)
        report += o + "\n";
    EXPECT_TRUE(offences.empty()) << report;
}
