// SPDX-License-Identifier: MIT
#include "GltfImages.h"

#include <osgDB/FileNameUtils>
#include <osgDB/Registry>

#include <cstring>
#include <sstream>

namespace osgVis::gltfplugin
{
namespace
{
// The image format's file extension from what the file says about it, falling back to the bytes.
std::string imageExtension(const unsigned char* bytes, std::size_t size, const std::string& mimeType,
                           const std::string& uri)
{
    if (mimeType == "image/png")
        return "png";
    if (mimeType == "image/jpeg")
        return "jpeg";
    const bool dataUri = uri.rfind("data:", 0) == 0;
    if (!uri.empty() && !dataUri)
    {
        const std::string extension = osgDB::getLowerCaseFileExtension(uri);
        if (!extension.empty())
            return extension;
    }
    if (size >= 8 && std::memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0)
        return "png";
    if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF)
        return "jpeg";
    return "";
}
} // namespace

osg::ref_ptr<osg::Image> decodeImage(const unsigned char* bytes, std::size_t size, const std::string& mimeType,
                                     const std::string& uri, const osgDB::Options* options, std::string& problem)
{
    const std::string extension = imageExtension(bytes, size, mimeType, uri);
    if (extension.empty())
    {
        problem = "unknown image format (mime type '" + mimeType + "')";
        return nullptr;
    }
    osgDB::ReaderWriter* reader = osgDB::Registry::instance()->getReaderWriterForExtension(extension);
    if (!reader)
    {
        problem = "no OSG image plugin for '" + extension + "'";
        return nullptr;
    }
    std::istringstream stream(std::string(reinterpret_cast<const char*>(bytes), size));
    osgDB::ReaderWriter::ReadResult result = reader->readImage(stream, options);
    osg::ref_ptr<osg::Image> image = result.getImage();
    if (!image || image->s() <= 0 || image->t() <= 0 || !image->data())
    {
        problem = "the " + extension + " plugin cannot decode it" +
                  (result.message().empty() ? std::string() : " (" + result.message() + ")");
        return nullptr;
    }
    if (!uri.empty() && uri.rfind("data:", 0) != 0)
        image->setFileName(uri);
    return image;
}
} // namespace osgVis::gltfplugin
