// SPDX-License-Identifier: MIT
#include "GltfParse.h"

#include <osgVis/gltf/GltfError.h>

#include <osg/Notify>
#include <osgDB/FileUtils>
#include <osgDB/fstream>

#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>

namespace osgVis::gltfplugin
{
using gltf::GltfError;

namespace
{
// tinygltf's file system callbacks over osgDB: a path that does not exist as joined is looked up
// with osgDB::findDataFile, which searches the options' database paths (how a stream finds its .bin).
std::string expandThroughOsgDB(const std::string& path, void* options)
{
    if (osgDB::fileExists(path))
        return path;
    const std::string found = osgDB::findDataFile(path, static_cast<const osgDB::Options*>(options));
    return found.empty() ? path : found;
}

bool fileExists(const std::string& path, void*)
{
    return osgDB::fileType(path) == osgDB::REGULAR_FILE;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*)
{
    osgDB::ifstream in(path.c_str(), std::ios::binary);
    if (!in)
    {
        if (err)
            *err += "cannot open " + path;
        return false;
    }
    out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

bool writeNothing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*)
{
    if (err)
        *err += "the glTF reader writes no files";
    return false;
}

// Keeps an image's encoded bytes for OSG's image plugins. note: bytes of an image in a buffer view
// are not touched here, since tinygltf passes them before checking the view lies in its buffer;
// the material builder reads them after that check.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*)
{
    if (image->bufferView < 0 && bytes && size > 0)
        image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

bool isBinary(const std::string& bytes) { return bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0; }

// The text between `key`'s first occurrence and the next `close` character, searched without a
// JSON parser (and without std::regex, whose recursion a long input can overflow): enough to spot
// what tinygltf would otherwise fail on with an unrelated message.
std::string sectionAfter(const std::string& bytes, const std::string& key, char close)
{
    const std::size_t start = bytes.find(key);
    if (start == std::string::npos)
        return "";
    const std::size_t end = bytes.find(close, start);
    return bytes.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// glTF 1.0 parses partly as 2.0 and then fails on something unrelated; say what it is instead.
void rejectVersion1(const std::string& bytes)
{
    if (isBinary(bytes))
    {
        std::uint32_t version = 0;
        if (bytes.size() >= 8)
            std::memcpy(&version, bytes.data() + 4, 4);
        if (version != 2)
            throw GltfError("binary glTF version " + std::to_string(version) + " is not supported (only glTF 2.0)");
        return;
    }
    const std::string asset = sectionAfter(bytes, "\"asset\"", '}');
    const std::size_t key = asset.find("\"version\"");
    if (key == std::string::npos)
        return;
    const std::size_t open = asset.find('"', asset.find(':', key));
    if (open == std::string::npos)
        return;
    const std::string version = asset.substr(open + 1, asset.find('"', open + 1) - open - 1);
    if (version.rfind("1", 0) == 0)
        throw GltfError("glTF " + version + " is not supported (only glTF 2.0)");
}

// tinygltf rejects a Draco-compressed file's accessors (they have no buffer view) before the
// model's extension list can be looked at.
void rejectRequiredDraco(const std::string& bytes)
{
    if (sectionAfter(bytes, "\"extensionsRequired\"", ']').find("\"KHR_draco_mesh_compression\"") != std::string::npos)
        throw GltfError("Draco mesh compression (KHR_draco_mesh_compression) is not supported");
}

void rejectRequiredExtensions(const tinygltf::Model& model)
{
    for (const std::string& extension : model.extensionsRequired)
    {
        if (extension == "KHR_draco_mesh_compression")
            throw GltfError("Draco mesh compression (KHR_draco_mesh_compression) is not supported");
        throw GltfError("required extension " + extension + " is not supported");
    }
}
} // namespace

tinygltf::Model parseGltf(const std::string& bytes, const std::string& baseDir, const std::string& fileName,
                          const osgDB::Options* options)
{
    if (bytes.size() > std::numeric_limits<unsigned>::max())
        throw GltfError("larger than 4 GiB, which tinygltf cannot read");
    rejectVersion1(bytes);
    rejectRequiredDraco(bytes);
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&fileExists, &expandThroughOsgDB, &readWholeFile, &writeNothing,
                           const_cast<osgDB::Options*>(options)});
    loader.SetImageLoader(&keepEncodedImage, nullptr);
    tinygltf::Model model;
    std::string error, warning;
    bool parsed = false;
    try
    {
        const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
        if (isBinary(bytes))
            parsed = loader.LoadBinaryFromMemory(&model, &error, &warning, data, unsigned(bytes.size()), baseDir);
        else
            parsed = loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), unsigned(bytes.size()), baseDir);
    }
    catch (const std::exception& e)
    {
        throw GltfError(std::string("tinygltf failed: ") + e.what());
    }
    while (!warning.empty() && warning.back() == '\n')
        warning.pop_back();
    if (!warning.empty())
        OSG_WARN << "gltf: " << fileName << ": " << warning << std::endl;
    while (!error.empty() && error.back() == '\n')
        error.pop_back();
    if (!parsed)
        throw GltfError(error.empty() ? std::string("tinygltf cannot parse it") : error);
    rejectRequiredExtensions(model);
    return model;
}
} // namespace osgVis::gltfplugin
