// SPDX-License-Identifier: MIT
#include "PvsModelFiles.h"

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <filesystem>

namespace osgVis::pvsplugin
{
namespace fs = std::filesystem;

std::string findNamedModel(const std::string& modelPath, const std::string& pvsFile, const osgDB::Options* options)
{
    if (modelPath.empty())
        return "";
    const fs::path named = fs::u8path(modelPath);
    if (!named.is_absolute())
    {
        const fs::path besidePvs = fs::u8path(pvsFile).parent_path() / named;
        if (osgDB::fileExists(besidePvs.u8string()))
            return besidePvs.u8string();
    }
    if (osgDB::fileExists(modelPath))
        return modelPath;
    return osgDB::findDataFile(modelPath, options);
}

std::string findModelBeside(const std::string& pvsFile)
{
    const std::string stem = osgDB::getNameLessExtension(pvsFile);
    for (const char* extension : {".osgb", ".osgt", ".ive", ".osg"})
        if (osgDB::fileExists(stem + extension))
            return stem + extension;
    return "";
}

std::string modelPathFromPvs(const std::string& modelFile, const std::string& pvsFile)
{
    const fs::path model = fs::absolute(fs::u8path(modelFile));
    const fs::path relative = model.lexically_relative(fs::absolute(fs::u8path(pvsFile)).parent_path());
    return relative.empty() ? model.generic_u8string() : relative.generic_u8string();
}
} // namespace osgVis::pvsplugin
