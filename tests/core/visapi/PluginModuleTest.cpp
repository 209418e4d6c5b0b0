// SPDX-License-Identifier: MIT
// Modules as plugins: the worked example `cfrustum` (C, through osgVis/visapi.h only) answers what
// the built-in frustum module answers, alone and in chains; every way a plugin can be broken gives
// a message naming the file and the reason, and a module failing at query time culls nothing.
#include "RandomBoxScene.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/plugin/CallbackModule.h>
#include <osgVis/core/plugin/PluginModules.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>

using namespace osgVis::core;

namespace
{
const std::string brokenDir = OSGVIS_BROKEN_MODULE_DIR;

std::string brokenPath(const std::string& kind)
{
    return brokenDir + "/osgvis_module_broken-" + kind + ".so";
}

// Puts the broken plugins' folder first on the search path for the test's duration.
class Plugins : public ::testing::Test
{
protected:
    void SetUp() override { setenv("OSGVIS_MODULE_PATH", brokenDir.c_str(), 1); }
    void TearDown() override { unsetenv("OSGVIS_MODULE_PATH"); }
};

std::string loadError(const std::string& modes)
{
    try
    {
        createChain(modes);
    }
    catch (const ModuleLoadError& e)
    {
        return e.what();
    }
    catch (const std::exception& e)
    {
        return std::string("not a ModuleLoadError: ") + e.what();
    }
    return "no error";
}

std::vector<ObjectId> answer(ModuleChain& chain, const View& view)
{
    VisibleSet visible;
    chain.cull(view, visible);
    return visible.ids();
}

CallbackModule& callbackStage(ModuleChain& chain, std::size_t stage)
{
    auto* module = dynamic_cast<CallbackModule*>(&chain.module(stage));
    if (!module)
        throw std::logic_error("stage is not a CallbackModule");
    return *module;
}
} // namespace

TEST_F(Plugins, SearchPathIsTheVariableThenBesideTheLibrary)
{
    const std::vector<std::string> path = pluginSearchPath();
    ASSERT_EQ(path.size(), 2u);
    EXPECT_EQ(path[0], brokenDir);
    EXPECT_EQ(path[1], std::string(OSGVIS_BINARY_DIR) + "/lib/osgvis-modules");
    EXPECT_EQ(pluginFileName("cfrustum"), "osgvis_module_cfrustum.so");
}

TEST_F(Plugins, CFrustumAnswersWhatFrustumAnswers)
{
    const Scene scene = osgVis::test::randomBoxScene(7, 600);
    const std::vector<View> views = osgVis::test::randomViews(11, 300);
    ModuleChain builtIn = createChain("frustum");
    ModuleChain plugin = createChain("cfrustum");
    ModuleChain chained = createChain("frustum+cfrustum");
    builtIn.setScene(scene);
    plugin.setScene(scene);
    chained.setScene(scene);
    ASSERT_EQ(plugin.name(), "cfrustum");
    double builtInMs = 0.0, pluginMs = 0.0;
    std::size_t culledSome = 0;
    for (const View& view : views)
    {
        const std::vector<ObjectId> expected = answer(builtIn, view);
        builtInMs += builtIn.lastTimings()[0].milliseconds;
        EXPECT_EQ(answer(plugin, view), expected);
        pluginMs += plugin.lastTimings()[0].milliseconds;
        EXPECT_EQ(answer(chained, view), expected);
        culledSome += expected.size() < scene.objects.size();
    }
    EXPECT_GT(culledSome, views.size() / 2); // the views do cull: the comparison means something
    std::cout << "cfrustum == frustum on " << views.size() << " views of " << scene.objects.size()
              << " boxes; mean cull ms: frustum " << builtInMs / views.size() << ", cfrustum "
              << pluginMs / views.size() << "\n";
}

TEST_F(Plugins, MissingPluginIsAnUnknownMode)
{
    EXPECT_THROW(createChain("frustum+no-such-module"), UnknownModeError);
    EXPECT_EQ(loadError("no-such-module").rfind("not a ModuleLoadError: unknown mode 'no-such-module'", 0), 0u);
    // Names that could reach outside the search folders are never looked up.
    EXPECT_THROW(createModule("../lib/osgvis-modules/cfrustum"), UnknownModeError);
}

TEST_F(Plugins, FileThatIsNoLibrary)
{
    const std::string path = brokenDir + "/osgvis_module_garbage.so";
    std::ofstream(path) << "not an ELF file\n";
    const std::string error = loadError("garbage");
    EXPECT_EQ(error.rfind("mode 'garbage': plugin " + path + ": cannot load: " + path, 0), 0u) << error;
}

TEST_F(Plugins, MissingEntryPoint)
{
    const std::string error = loadError("frustum+broken-nosymbol");
    const std::string expected =
        "mode 'broken-nosymbol': plugin " + brokenPath("nosymbol") + ": no entry point osgvis_module_entry (";
    EXPECT_EQ(error.rfind(expected, 0), 0u) << error;
    EXPECT_NE(error.find("undefined symbol: osgvis_module_entry"), std::string::npos) << error;
}

TEST_F(Plugins, WrongApiVersion)
{
    EXPECT_EQ(loadError("broken-version"), "mode 'broken-version': plugin " + brokenPath("version") +
                                               ": built against visapi 2.0, this osgVis has 1." +
                                               std::to_string(OSGVIS_VISAPI_VERSION_MINOR));
}

TEST_F(Plugins, EntryRefuses)
{
    EXPECT_EQ(loadError("broken-refuses"), "mode 'broken-refuses': plugin " + brokenPath("refuses") +
                                               ": osgvis_module_entry returned no callback table");
}

TEST_F(Plugins, TableWithoutCull)
{
    EXPECT_EQ(loadError("broken-nocull"),
              "mode 'broken-nocull': plugin " + brokenPath("nocull") + ": the callback table has no cull");
}

TEST_F(Plugins, CreateFails)
{
    EXPECT_EQ(loadError("broken-nocreate"),
              "mode 'broken-nocreate': plugin " + brokenPath("nocreate") + ": create failed");
}

// The failing modules clear every candidate before failing: the chain must answer frustum's sets.
TEST_F(Plugins, FailingOrThrowingCullKeepsEveryCandidate)
{
    const Scene scene = osgVis::test::randomBoxScene(3, 200);
    const std::vector<View> views = osgVis::test::randomViews(5, 20);
    ModuleChain builtIn = createChain("frustum");
    builtIn.setScene(scene);
    const std::pair<const char*, const char*> cases[] = {
        {"frustum+broken-fails", "cull failed: OSGVIS_ERROR_MODULE_FAILED: no luck today"},
        {"frustum+broken-throws", "cull failed: threw cull exploded"},
        {"frustum+broken-scenefails", "set_scene failed: OSGVIS_ERROR_INVALID_ARGUMENT: scene refused"},
    };
    for (const auto& [modes, failure] : cases)
    {
        ModuleChain chain = createChain(modes);
        chain.setScene(scene);
        for (const View& view : views)
            EXPECT_EQ(answer(chain, view), answer(builtIn, view)) << modes;
        EXPECT_EQ(callbackStage(chain, 1).lastFailure(), failure) << modes;
        EXPECT_EQ(callbackStage(chain, 1).failureCount(),
                  std::string(modes).find("scenefails") != std::string::npos ? 1u : views.size())
            << modes;
    }
}
