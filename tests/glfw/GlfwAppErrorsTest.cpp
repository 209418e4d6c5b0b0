// SPDX-License-Identifier: MIT
// osgvisglfw refuses bad input with a message that names the problem and a non-zero exit code,
// before it opens a window (so these tests need no display).
#include "GlfwAppProcess.h"

#include <osgVis/core/api/ModuleRegistry.h>

#include <gtest/gtest.h>

#include <cstdlib>

using namespace osgVis::test;

namespace
{
void expectFailure(const std::string& arguments, int exitCode, const std::string& message)
{
    const AppRun run = runGlfwApp(arguments);
    EXPECT_EQ(run.exitCode, exitCode) << arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << arguments << ": expected '" << message << "' in:\n"
                                                           << run.output;
}
} // namespace

TEST(GlfwAppErrors, UnknownOption)
{
    expectFailure("--frames 1 --fullscreen", 2, "osgvisglfw: unknown option '--fullscreen' (see --help)");
}

TEST(GlfwAppErrors, BadNumbers)
{
    expectFailure("--frames x", 2, "--frames expects a non-negative integer, got 'x'");
    expectFailure("--frames 0", 2, "--frames must lie between 1 and 1000000000, got '0'");
    expectFailure("--frames 3 --size 0x0", 2, "--size must lie between 1x1 and 16384x16384, got '0x0'");
    expectFailure("--frames 3 --size 640", 2, "--size expects WxH (e.g. 1024x768), got '640'");
    expectFailure("--frames 3 --eye 1,2 --center 0,0,0", 2, "--eye expects x,y,z (three numbers), got '1,2'");
    expectFailure("--frames", 2, "--frames expects a value");
}

TEST(GlfwAppErrors, OptionsThatGoTogether)
{
    expectFailure("--frames 3 --eye 1,2,3", 2, "--eye and --center go together");
    expectFailure("--frames 3 --eye 1,2,3 --center 1,2,3", 2, "--eye and --center must differ");
    expectFailure("--screenshot a.png", 2, "--screenshot needs --frames N");
}

TEST(GlfwAppErrors, MissingModelIsNamed)
{
    const std::string model = (scratchDirectory("glfw", "missing") / "not-there.osgt").string();
    expectFailure("\"" + model + "\" --frames 1", 1, "cannot read model '" + model + "': no such file");
}

TEST(GlfwAppErrors, UnknownModeListsTheModes)
{
    const AppRun run = runGlfwApp("--frames 1 --mode nonsense");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("unknown mode 'nonsense'; modes: osg, "), std::string::npos) << run.output;
    for (const std::string& module : osgVis::core::moduleNames())
        EXPECT_NE(run.output.find(module), std::string::npos) << "mode list lacks " << module << ":\n" << run.output;
}

TEST(GlfwAppErrors, NoDisplayGivesGlfwsReason)
{
    // The child inherits this process's environment; restored so later tests see the display.
    const char* display = std::getenv("DISPLAY");
    const std::string saved = display ? display : "";
    ::unsetenv("DISPLAY");
    const AppRun run = runGlfwApp("--frames 1");
    if (!saved.empty())
        ::setenv("DISPLAY", saved.c_str(), 1);
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("osgvisglfw: cannot initialise GLFW: "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("DISPLAY"), std::string::npos) << "GLFW's own text names the missing display:\n"
                                                             << run.output;
}

TEST(GlfwAppErrors, HelpListsEveryOption)
{
    const AppRun run = runGlfwApp("--help");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    for (const char* option : {"--mode", "--size", "--frames", "--screenshot", "--eye", "--center", "--help"})
        EXPECT_NE(run.output.find(option), std::string::npos) << "help lacks " << option << ":\n" << run.output;
}
