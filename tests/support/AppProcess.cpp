// SPDX-License-Identifier: MIT
#include "AppProcess.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace osgVis::test
{
AppRun runApp(const std::string& executable, const std::string& arguments)
{
    // note: output goes through a file, not a pipe, so a chatty child can never block on a full pipe
    const std::filesystem::path log =
        std::filesystem::path(OSGVIS_BINARY_DIR) / "tests" / ("app-run-" + std::to_string(::getpid()) + ".log");
    std::filesystem::create_directories(log.parent_path());
    const std::string command = "\"" + executable + "\" " + arguments + " > \"" + log.string() + "\" 2>&1";
    const int status = std::system(command.c_str());

    AppRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    run.output = readText(log);
    std::filesystem::remove(log);
    return run;
}

std::filesystem::path scratchDirectory(const std::string& area, const std::string& name)
{
    const std::filesystem::path dir = std::filesystem::path(OSGVIS_BINARY_DIR) / "tests" / area / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

bool haveDisplay()
{
    const char* display = std::getenv("DISPLAY");
    return display && *display;
}

std::string readText(const std::filesystem::path& path)
{
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}
} // namespace osgVis::test
