#include "ViewerProcess.h"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace osgVis::test
{
ViewerRun runViewer(const std::string& arguments)
{
    const std::filesystem::path log = std::filesystem::path(OSGVIS_BINARY_DIR) / "tests" / "apps" /
                                      ("viewer-run-" + std::to_string(::getpid()) + ".log");
    std::filesystem::create_directories(log.parent_path());
    const std::string command =
        std::string("\"") + OSGVIS_VIEWER_EXE + "\" " + arguments + " > \"" + log.string() + "\" 2>&1";
    const int status = std::system(command.c_str());

    ViewerRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::ifstream in(log);
    std::ostringstream text;
    text << in.rdbuf();
    run.output = text.str();
    std::filesystem::remove(log);
    return run;
}

std::string scratchDirectory(const std::string& name)
{
    const std::filesystem::path dir = std::filesystem::path(OSGVIS_BINARY_DIR) / "tests" / "apps" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

bool haveDisplay()
{
    const char* display = std::getenv("DISPLAY");
    return display && *display;
}
} // namespace osgVis::test
