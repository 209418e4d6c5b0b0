// SPDX-License-Identifier: MIT
#include "PluginPaths.h"

#include <osgDB/Registry>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace osgVis::apps
{
namespace
{
#ifdef OSGVIS_PLUGIN_INSTALL_SUBDIR
// Plugin folders as seen from the running executable: <prefix>/bin/exe → <prefix>/<plugin dir>, for
// an installation moved away from its configured prefix.
std::string pluginDirBesideExecutable(const std::string& relativePluginDir)
{
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error || relativePluginDir.empty())
        return "";
    return (exe.parent_path().parent_path() / relativePluginDir).lexically_normal().string();
}
#endif

} // namespace

void addOsgVisPluginPaths()
{
    std::vector<std::string> folders;
#ifdef OSGVIS_PLUGIN_BUILD_DIR
    folders.emplace_back(OSGVIS_PLUGIN_BUILD_DIR);
#endif
#ifdef OSGVIS_PLUGIN_INSTALL_DIR
    folders.emplace_back(OSGVIS_PLUGIN_INSTALL_DIR);
#endif
#ifdef OSGVIS_PLUGIN_INSTALL_SUBDIR
    folders.push_back(pluginDirBesideExecutable(OSGVIS_PLUGIN_INSTALL_SUBDIR));
#endif
    osgDB::FilePathList& paths = osgDB::Registry::instance()->getLibraryFilePathList();
    for (const std::string& folder : folders)
    {
        std::error_code error;
        if (!folder.empty() && std::filesystem::is_directory(folder, error) &&
            std::find(paths.begin(), paths.end(), folder) == paths.end())
            paths.push_back(folder); // after OSG_LIBRARY_PATH's entries: the user's plugins win
    }
}
} // namespace osgVis::apps
