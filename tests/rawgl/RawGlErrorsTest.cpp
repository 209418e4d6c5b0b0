// SPDX-License-Identifier: MIT
// osgvisrawgl refuses bad command lines (exit 2) and bad input (exit 1) with a message naming the
// problem, before any window opens (no display needed).
#include "AppProcess.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace osgVis::test;

TEST(RawGlErrors, HelpTellsTheOptions)
{
    const AppRun run = runApp(OSGVIS_RAWGL_EXE, "--help");
    EXPECT_EQ(run.exitCode, 0);
    for (const char* option : {"--walk", "--modes", "--dump-visible", "--pixels", "--show"})
        EXPECT_NE(run.output.find(option), std::string::npos) << option;
}

TEST(RawGlErrors, BadCommandLinesExitTwo)
{
    for (const char* arguments : {"", "--frobnicate model.glb", "model.glb --walk", "a.glb b.glb",
                                  "model.glb --modes frustum,,octree", "model.glb --modes frustum,frustum"})
    {
        const AppRun run = runApp(OSGVIS_RAWGL_EXE, arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments << "\n" << run.output;
        EXPECT_NE(run.output.find("usage: osgvisrawgl"), std::string::npos) << arguments;
    }
}

TEST(RawGlErrors, BadInputExitsOneWithTheReason)
{
    const std::filesystem::path dir = scratchDirectory("rawgl", "errors");
    const AppRun missing = runApp(OSGVIS_RAWGL_EXE, (dir / "nothing.glb").string());
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.output.find("no such file"), std::string::npos) << missing.output;

    std::ofstream(dir / "broken.gltf") << "{ not json";
    const AppRun broken = runApp(OSGVIS_RAWGL_EXE, (dir / "broken.gltf").string());
    EXPECT_EQ(broken.exitCode, 1);
    EXPECT_NE(broken.output.find("broken.gltf"), std::string::npos) << broken.output;

    // A valid model (one triangle) without a walk beside it, then with a malformed walk.
    // One triangle under one node (`node` its JSON).
    const auto triangle = [](const std::string& node)
    {
        return R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[)" + node +
               R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
               R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
               R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
               R"("buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)"
               R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
    };
    std::ofstream(dir / "triangle.gltf") << triangle(R"({"mesh":0})");
    const AppRun noWalk = runApp(OSGVIS_RAWGL_EXE, (dir / "triangle.gltf").string());
    EXPECT_EQ(noWalk.exitCode, 1);
    EXPECT_NE(noWalk.output.find("no walk"), std::string::npos) << noWalk.output;

    // A node transform of the wrong size, in the words of the glTF plugin (the check they share).
    std::ofstream(dir / "scale.gltf") << triangle(R"({"mesh":0,"scale":[1,2]})");
    const AppRun badScale = runApp(OSGVIS_RAWGL_EXE, (dir / "scale.gltf").string());
    EXPECT_EQ(badScale.exitCode, 1);
    EXPECT_NE(badScale.output.find("scale.gltf: node 0 has a scale of 2 values, expected 3"), std::string::npos)
        << badScale.output;

    std::ofstream(dir / "bad.walk") << "osgvis-walk 1\nsize 0 480\n";
    const AppRun badWalk =
        runApp(OSGVIS_RAWGL_EXE, (dir / "triangle.gltf").string() + " --walk " + (dir / "bad.walk").string());
    EXPECT_EQ(badWalk.exitCode, 1);
    EXPECT_NE(badWalk.output.find("size must be between"), std::string::npos) << badWalk.output;

    std::ofstream(dir / "good.walk") << "osgvis-walk 1\nsize 64 64\nprojection perspective 60\nclip 0.1 10\n"
                                        "view 0 0.5 -3 0.5 0.5 0 0.5 0 0 1\n";
    const AppRun badMode = runApp(OSGVIS_RAWGL_EXE, (dir / "triangle.gltf").string() + " --walk " +
                                                        (dir / "good.walk").string() + " --modes nosuchmode");
    EXPECT_EQ(badMode.exitCode, 1);
    EXPECT_NE(badMode.output.find("unknown mode 'nosuchmode'"), std::string::npos) << badMode.output;
}
