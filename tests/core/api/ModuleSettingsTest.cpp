// SPDX-License-Identifier: MIT
// Typed module settings (issue 46): mode strings carry settings ("octree:occluders=64"), names are
// shorthands for settings, the text round-trips, a setting that makes a module approximate is a
// name, and bad settings are refused with the module's keys.
#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/api/ModuleSettings.h>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace osgVis::core;

namespace
{
std::string errorOf(const std::string& modes)
{
    try
    {
        createChain(modes);
    }
    catch (const UnknownModeError& error)
    {
        return error.what();
    }
    return "(no error)";
}
} // namespace

TEST(ModuleSettings, NamesAreShorthandsForSettings)
{
    const ChainSettings chain = parseChainSettings("frustum+octree-paper+mask-approx,cdt-depthfree");
    ASSERT_EQ(chain.size(), 4u);
    EXPECT_TRUE(std::holds_alternative<std::monostate>(chain[0].options));
    const OctreeOptions& octree = std::get<OctreeOptions>(chain[1].options);
    EXPECT_FALSE(octree.fuseDisjoint);
    EXPECT_TRUE(octree.fuseConnected);
    const MaskOptions& mask = std::get<MaskOptions>(chain[2].options);
    EXPECT_EQ(mask.shrink, MaskShrink::FusedUnion);
    EXPECT_EQ(mask.shrinkPixels, 4.0);
    EXPECT_EQ(std::get<CdtOptions>(chain[3].options).rule, CdtOptions::Rule::DepthFree);
    // A name with settings that equal another shorthand's is written as that shorthand.
    EXPECT_EQ(formatChainSettings(parseChainSettings("octree:fuseDisjoint=false")), "octree-paper");
    EXPECT_EQ(formatChainSettings(parseChainSettings("mask:measure=distance")), "mask-distance");
    EXPECT_EQ(formatChainSettings(parseChainSettings("cdt-depth:rule=combined")), "cdt");
}

TEST(ModuleSettings, SettingsReachTheModulesAndRoundTrip)
{
    const std::string text = "frustum+octree:occluders=64:areaAngleThreshold=0.01+mask-approx:shrinkPixels=2.5+"
                             "cdt:constraintBudget=512:tolerancePixels=0.125+multifocal:cachedCells=8+cellportal-pvs";
    const ChainSettings chain = parseChainSettings(text);
    EXPECT_EQ(std::get<OctreeOptions>(chain[1].options).occluders, 64u);
    EXPECT_EQ(std::get<OctreeOptions>(chain[1].options).areaAngleThreshold, 0.01);
    EXPECT_EQ(std::get<MaskOptions>(chain[2].options).shrinkPixels, 2.5);
    EXPECT_EQ(std::get<CdtOptions>(chain[3].options).constraintBudget, 512u);
    EXPECT_EQ(std::get<MultifocalModuleOptions>(chain[4].options).cachedCells, 8u);
    EXPECT_EQ(std::get<CellPortalStage>(chain[5].options), CellPortalStage::CellToObject);
    EXPECT_EQ(formatChainSettings(chain), text);
    EXPECT_EQ(formatChainSettings(parseChainSettings(formatChainSettings(chain))), text);

    // Every key of every built-in name reads back what it writes.
    for (const StageSettings& stage : builtInStages())
        for (const auto& [key, value] : stageKeys(stage))
        {
            const std::string one = stage.name + ":" + key + "=" + value;
            EXPECT_EQ(formatStageSettings(parseStageSettings(one)), stage.name) << one;
        }

    // The chain made from settings: the modules' own names and approximation follow the settings.
    ModuleChain modules = createChain(text);
    EXPECT_EQ(modules.name(), "frustum,octree,mask-approx,cdt,multifocal,cellportal-pvs");
    EXPECT_TRUE(modules.approximate());
    EXPECT_FALSE(createChain("frustum+mask:shrinkPixels=0.5").approximate());
    EXPECT_EQ(std::string(createChain("octree:fuseConnected=false:fuseDisjoint=false").module(0).name()),
              "octree-single");
}

TEST(ModuleSettings, BadSettingsNameTheKeys)
{
    EXPECT_EQ(errorOf("octree:occluder=3"),
              "mode 'octree:occluder=3': no setting 'occluder' (settings: occluders, areaAngleThreshold, "
              "fuseConnected, fuseDisjoint, temporalCoherence, coplanarUnions, sweepAreaAngleThreshold, "
              "occlusionTreeMaxNodes, maxLeafObjects, parallelMinObjects, sceneHierarchy, workBudget)");
    EXPECT_EQ(errorOf("octree:occluders=-3"), "mode 'octree:occluders=-3': bad value in 'occluders=-3' (e.g. occluders=32)");
    EXPECT_EQ(errorOf("mask:shrinkPixels=inf"), "mode 'mask:shrinkPixels=inf': bad value in 'shrinkPixels=inf' (e.g. shrinkPixels=2)");
    EXPECT_EQ(errorOf("octree:fuseDisjoint"), "mode 'octree:fuseDisjoint': bad value in 'fuseDisjoint' (e.g. fuseDisjoint=true)");
    EXPECT_EQ(errorOf("frustum:x=1"), "mode 'frustum:x=1': this module takes no settings");
    EXPECT_EQ(errorOf("cellportal:stage=pvs"), "mode 'cellportal:stage=pvs': this module takes no settings");
    // Approximation is a name: no key turns the mask's conservative shrinkage off.
    EXPECT_NE(errorOf("mask:shrink=fused").find("no setting 'shrink'"), std::string::npos);
    EXPECT_NE(errorOf("nosuch:x=1").find("only osgVis's own modules take settings"), std::string::npos);
}

// docs/modes.md lists every key of every module, so the page cannot fall behind the code.
TEST(ModuleSettings, TheDocsListEveryKey)
{
    std::ifstream in(std::string(OSGVIS_SOURCE_DIR) + "/docs/modes.md");
    ASSERT_TRUE(in) << "docs/modes.md";
    std::stringstream text;
    text << in.rdbuf();
    for (const StageSettings& stage : builtInStages())
    {
        EXPECT_NE(text.str().find("`" + stage.name + "`"), std::string::npos) << stage.name;
        for (const auto& [key, value] : stageKeys(stage))
            EXPECT_NE(text.str().find("`" + key + "`"), std::string::npos) << stage.name << ":" << key;
    }
}
