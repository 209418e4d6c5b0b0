// SPDX-License-Identifier: MIT
// The renderer that is not OSG against the OSG adapter (docs/visapi.md, "A renderer that is not
// OSG"). Both read the same glTF file through different loaders (osgvisrawgl: its own tinygltf code;
// osgvisbench: osgDB and osgVis's glTF plugin, then the adapter's extraction), name objects by the
// canonical identity (glTF node path and primitive) and cull the same walk; their objects (flags,
// triangle counts, bounds to the bit, triangle hashes) and visible sets per view must be identical,
// and osgvisrawgl's culled frames must equal its unculled ones pixel for pixel.
#include "AppProcess.h"

#include <osgVis/core/scene/Walk.h>

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

using namespace osgVis::test;

namespace
{
const std::vector<std::string> Modes = {"frustum", "octree", "mask", "cdt", "multifocal"};

std::string quoted(const std::filesystem::path& path)
{
    return "\"" + path.string() + "\"";
}

std::string joined(const std::vector<std::string>& items)
{
    std::string out;
    for (const std::string& item : items)
        out += (out.empty() ? "" : ",") + item;
    return out;
}

std::vector<std::string> lines(const std::filesystem::path& path)
{
    std::vector<std::string> out;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);)
        out.push_back(line);
    return out;
}

// `walk` with every `step`-th view (the first included), to keep the run short.
void saveThinnedWalk(const std::filesystem::path& from, const std::filesystem::path& to, std::size_t step)
{
    osgVis::core::Walk walk = osgVis::core::Walk::load(from.string());
    std::vector<osgVis::core::WalkKey> kept;
    for (std::size_t i = 0; i < walk.keys.size(); i += step)
        kept.push_back(walk.keys[i]);
    walk.keys = kept;
    walk.save(to.string());
}

// Compares DIR/objects.txt and DIR/<mode>.visible of both sides; prints the figures.
void expectSameDumps(const std::filesystem::path& osg, const std::filesystem::path& raw, const std::string& what)
{
    const std::vector<std::string> osgObjects = lines(osg / "objects.txt"), rawObjects = lines(raw / "objects.txt");
    ASSERT_GT(osgObjects.size(), 2u) << what << ": no objects from osgvisbench";
    ASSERT_EQ(osgObjects.size(), rawObjects.size()) << what << ": object counts differ";
    for (std::size_t i = 0; i < osgObjects.size(); ++i)
        EXPECT_EQ(osgObjects[i], rawObjects[i]) << what << ": object line " << i << " differs (OSG first)";
    for (const std::string& mode : Modes)
    {
        const std::vector<std::string> a = lines(osg / (mode + ".visible")), b = lines(raw / (mode + ".visible"));
        ASSERT_GT(a.size(), 2u) << what << ": no views in " << mode << ".visible";
        ASSERT_EQ(a.size(), b.size()) << what << ", " << mode << ": view counts differ";
        std::size_t identical = 0;
        for (std::size_t i = 2; i < a.size(); ++i)
        {
            identical += a[i] == b[i];
            EXPECT_EQ(a[i], b[i]) << what << ", " << mode << ": view line " << i << " differs (OSG first)";
        }
        EXPECT_EQ(a[1], b[1]) << what << ", " << mode << ": headers differ";
        std::cout << what << ", " << mode << ": " << a.size() - 2 << " views, " << identical << " identical"
                  << std::endl;
    }
}

void compareRenderers(const std::filesystem::path& model, const std::filesystem::path& walk,
                      const std::filesystem::path& dir, const std::string& what)
{
    const AppRun osg =
        runApp(OSGVIS_BENCH_EXE, "--clusters off --scene " + quoted(model) + " --walk " + quoted(walk) + " --dump-visible " +
                                     quoted(dir / "osg") + " --modes " + joined(Modes));
    ASSERT_EQ(osg.exitCode, 0) << osg.output;
    const AppRun raw = runApp(OSGVIS_RAWGL_EXE, quoted(model) + " --walk " + quoted(walk) + " --dump-visible " +
                                                    quoted(dir / "raw") + " --modes " + joined(Modes) + " --pixels");
    std::cout << raw.output;
    ASSERT_EQ(raw.exitCode, 0) << raw.output; // 1: a conservative mode's pixels differ
    for (const std::string& mode : Modes)
        EXPECT_TRUE(std::regex_search(raw.output, std::regex("\\n" + mode + " +[0-9]+ .* 0 \\(0\\)\\n")))
            << mode << " reports differing pixels:\n"
            << raw.output;
    std::smatch covered;
    ASSERT_TRUE(std::regex_search(raw.output, covered, std::regex(R"(unculled frames: ([0-9.]+)% of the pixels)")))
        << raw.output;
    EXPECT_GT(std::stod(covered[1]), 5.0) << "the frames show almost nothing: the pixel check would be empty";
    expectSameDumps(dir / "osg", dir / "raw", what);
}
} // namespace

TEST(RawGl, EngineSameObjectsAndVisibleSetsAsOsgAdapterAndSamePixels)
{
    const std::filesystem::path model = OSGVIS_GLTF_SAMPLE;
    if (!std::filesystem::exists(model))
        GTEST_SKIP() << model << " is missing (Debian package assimp-testmodels)";
    if (!haveDisplay())
        GTEST_SKIP() << "no X display (scripts/with-display.sh provides one)";
    const std::filesystem::path dir = scratchDirectory("rawgl", "engine");
    // The automatic walk through the model (as osgvisbench makes it), every fourth view.
    const AppRun walk =
        runApp(OSGVIS_BENCH_EXE, "--clusters off --scene " + quoted(model) + " --walk auto --save-walk " + quoted(dir / "auto.walk") +
                                     " --dump-visible " + quoted(dir / "probe") + " --modes frustum");
    ASSERT_EQ(walk.exitCode, 0) << walk.output;
    saveThinnedWalk(dir / "auto.walk", dir / "engine.walk", 4);
    compareRenderers(model, dir / "engine.walk", dir, "2CylinderEngine");

    // The renderer's own hierarchy (glTF node boxes, overlapping) handed over by callback: cdt walks
    // it by depth only, octree and mask judge its nodes by their recorded boxes, and their frames
    // still equal the unculled ones.
    const AppRun walked = runApp(OSGVIS_RAWGL_EXE, quoted(model) + " --walk " + quoted(dir / "engine.walk") +
                                                       " --modes cdt,cdt-depthfree,octree,mask --hierarchy --pixels");
    std::cout << walked.output;
    ASSERT_EQ(walked.exitCode, 0) << walked.output;
    for (const char* mode : {"cdt", "cdt-depthfree", "octree", "mask"})
        EXPECT_TRUE(std::regex_search(walked.output, std::regex(std::string("\\n") + mode + " +[0-9]+ .* 0 \\(0\\)\\n")))
            << mode << " on the renderer's hierarchy:\n"
            << walked.output;
}

TEST(RawGl, GeneratedCityExportedToGltfSameVisibleSetsAndSamePixels)
{
    if (!haveDisplay())
        GTEST_SKIP() << "no X display (scripts/with-display.sh provides one)";
    const std::filesystem::path dir = scratchDirectory("rawgl", "city");
    const AppRun generated =
        runApp(OSGVIS_GEN_EXE, "--kind city --triangles 20000 --seed 3 -o " + quoted(dir / "city.glb"));
    ASSERT_EQ(generated.exitCode, 0) << generated.output;
    saveThinnedWalk(dir / "city.walk", dir / "short.walk", 16);
    compareRenderers(dir / "city.glb", dir / "short.walk", dir, "generated city");
}
