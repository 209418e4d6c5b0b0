// SPDX-License-Identifier: MIT
// The one contract, checked for every mode the registry knows: over the generated scenes (every
// view of their walks) and the adversarial set, a conservative mode leaves 0 visible objects
// undrawn. The judge is the oracle inside osgvisbench, which renders the real graph; modes run
// through the same OSG adapter an application uses. A mode registered later is picked up here
// without touching this file.
#include "AppProcess.h"
#include "BenchJson.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/gen/Generator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

using namespace osgVis::test;

namespace
{
struct ContractScene
{
    std::string name;      // test name part
    std::string generate;  // osgvisgen arguments less -o
    std::string benchArgs; // view sampling and size
    std::string pk3 = {}, map = {}; // or a real Quake 3 level: the map's path inside a Debian-installed .pk3
    // With a level: read as OSG's own tools draw it (osgconv through the bsp plugin, its wireframe
    // PolygonMode set to FILL, no osgVis repair) rather than by osgVis's loader.
    bool asPlugin = false;
    std::string walkText = {}; // the views to walk (a walk file's text), or none: benchArgs say
};

// Views in which each mode once culled an object the GPU draws on the plugin's triangles of
// OpenArena levels (issue 47): a T-junction seam under an octree coplanar union (oa_dm4, view 4),
// objects standing on a floor or ceiling seen from the other side, tied in depth (cdt, views 1-3),
// and a sliver fan triangle drawn through a wall (oa_dm1, mask).
const char* const WalkHeader = "osgvis-walk 1\nsize 1280 1024\nprojection perspective 70\nclip 0.05 120\n";
const std::string Oa4Views = std::string(WalkHeader) +
                             "view 6.00 11.1998 21.4009 -1.9812 10.3207 21.3986 -1.5046 0 0 1\n"
                             "view 6.30 9.6797 24.4253 1.4732 10.3740 23.7677 1.7656 0 0 1\n"
                             "view 7.20 11.3307 24.5509 -1.9812 10.4488 24.2095 -1.6561 0 0 1\n"
                             "view 13.10 11.0409 21.1987 -1.9812 10.8880 20.2304 -1.7835 0 0 1\n";
const std::string Oa1Views = std::string(WalkHeader) +
                             "view 13.10 22.5485 -30.6229 1.4224 21.5641 -30.5237 1.2770 0 0 1\n";

// Modes the bench runs: OSG's own culling, every non-approximate module alone, and each after
// frustum (the chain an application would use).
std::vector<std::string> conservativeModes()
{
    std::vector<std::string> modes{"osg"};
    for (const std::string& name : osgVis::core::moduleNames())
    {
        if (osgVis::core::createModule(name)->approximate())
            continue;
        modes.push_back(name);
        if (name != "frustum")
            modes.push_back("frustum+" + name);
    }
    return modes;
}

std::string joined(const std::vector<std::string>& items)
{
    std::string text;
    for (const std::string& item : items)
        text += (text.empty() ? "" : ",") + item;
    return text;
}

std::vector<ContractScene> contractScenes()
{
    std::vector<ContractScene> scenes;
    for (const std::string& kind : osgVis::gen::sceneKindNames())
    {
        // Every view of the walk at a small size, then a sample of it at the walk's own size.
        // Small scenes, but never below a kind's smallest budget (the floor has a fixed layout);
        // such a kind is larger, so it gets a sample of its views.
        const std::uint64_t least = osgVis::gen::minTrianglesFor(osgVis::gen::parseSceneKind(kind));
        const std::string sample = least > 6000 ? " --views 100" : "";
        scenes.push_back({kind + "_every_view",
                          "--kind " + kind + " --triangles " + std::to_string(std::max<std::uint64_t>(6000, least)) +
                              " --seed 1",
                          "--size 320x256" + sample});
        scenes.push_back({kind + "_full_size",
                          "--kind " + kind + " --triangles " + std::to_string(std::max<std::uint64_t>(12000, least)) +
                              " --seed 2",
                          "--views 24"});
    }
    // Real levels nobody here made (OpenArena, GPL data, read from Debian's openarena-081-maps where
    // installed, never shipped), walked from inside by the automatic walk; skipped without the package.
    for (const char* map : {"oa_dm4", "ce1m7"})
        scenes.push_back({std::string("openarena_") + map, "", "--views 40 --size 320x256",
                          "/usr/share/games/openarena/baseoa/pak1-maps.pk3", std::string("maps/") + map + ".bsp"});
    const std::string pk3 = "/usr/share/games/openarena/baseoa/pak1-maps.pk3";
    for (const auto& [map, walk] : {std::pair{"oa_dm4", Oa4Views}, std::pair{"oa_dm1", Oa1Views}})
        scenes.push_back({std::string("openarena_plugin_") + map, "", "", pk3, std::string("maps/") + map + ".bsp",
                          true, walk});
    // Views nobody tuned: random gazes from the free space of three levels, read both ways.
    for (const char* map : {"oa_dm1", "oa_dm4", "ce1m7"})
        for (const bool asPlugin : {false, true})
            scenes.push_back({std::string("openarena_random_") + (asPlugin ? "plugin_" : "") + map, "",
                              "--walk random --seed 47 --views 40 --size 480x384", pk3,
                              std::string("maps/") + map + ".bsp", asPlugin});
    for (std::string name : osgVis::gen::adversarialSceneNames())
    {
        const std::string arguments = "--adversarial " + name;
        for (char& c : name)
            if (c == '-')
                c = '_';
        scenes.push_back({name, arguments, ""});
    }
    return scenes;
}

void PrintTo(const ContractScene& scene, std::ostream* out)
{
    *out << scene.name;
}

class ConservativeModes : public ::testing::TestWithParam<ContractScene>
{
};

TEST_P(ConservativeModes, MissNoVisibleObject)
{
    ASSERT_TRUE(haveDisplay()) << "needs an X display: run the tests through scripts/test.sh";
    const ContractScene& scene = GetParam();
    const auto dir = scratchDirectory("modes", scene.name);
    std::string model = (dir / "scene.osgb").string();
    std::string benchArgs = scene.benchArgs;
    if (scene.pk3.empty())
    {
        const AppRun generated = runApp(OSGVISGEN_EXE, scene.generate + " -o \"" + model + "\"");
        ASSERT_EQ(generated.exitCode, 0) << generated.output;
    }
    else
    {
        if (!std::filesystem::exists(scene.pk3))
            GTEST_SKIP() << scene.pk3 << " is not installed (Debian package openarena-081-maps)";
        const AppRun unzip = runApp("unzip", "-o -q '" + scene.pk3 + "' '" + scene.map + "' -d '" + dir.string() + "'");
        ASSERT_EQ(unzip.exitCode, 0) << "cannot extract " << scene.map << ": " << unzip.output;
        model = (dir / scene.map).string();
        if (scene.asPlugin)
        {
            const std::string drawn = (dir / "plugin.osgt").string();
            const AppRun converted = runApp("bash", "-c \"osgconv '" + model + "' '" + drawn + ".raw.osgt' && sed -e " +
                                                        "'s/Front LINE/Front FILL/; s/Back LINE/Back FILL/' '" + drawn +
                                                        ".raw.osgt' > '" + drawn + "' && rm '" + drawn + ".raw.osgt'\"");
            ASSERT_EQ(converted.exitCode, 0) << converted.output;
            model = drawn;
        }
        if (!scene.walkText.empty())
        {
            const std::string walk = (dir / "views.walk").string();
            std::ofstream(walk) << scene.walkText;
            benchArgs = "--walk \"" + walk + "\"";
        }
    }

    const std::vector<std::string> modes = conservativeModes();
    ASSERT_GE(modes.size(), 2u) << "the registry lost the frustum module";
    const std::string json = (dir / "bench.json").string();
    const AppRun bench = runApp(OSGVIS_BENCH_EXE, "--scene \"" + model + "\" --modes " + joined(modes) + " " +
                                                      benchArgs + " --json \"" + json + "\"");
    const std::string report = readText(json);
    ASSERT_FALSE(report.empty()) << bench.output;
    for (const std::string& mode : modes)
    {
        const std::string result = modeObject(report, mode);
        ASSERT_FALSE(result.empty()) << mode << " missing from " << report;
        EXPECT_EQ(numberField(result, "false_invisible"), 0.0) << mode << " on " << scene.name << ": " << result;
        EXPECT_GE(numberField(result, "overestimation").value_or(0.0), 1.0) << mode << ": " << result;
    }
    EXPECT_EQ(bench.exitCode, 0) << bench.output;
}

INSTANTIATE_TEST_SUITE_P(EveryScene, ConservativeModes, ::testing::ValuesIn(contractScenes()),
                         [](const ::testing::TestParamInfo<ContractScene>& info) { return info.param.name; });
} // namespace
