// SPDX-License-Identifier: MIT
#pragma once
// Decoding a glTF image's encoded bytes (PNG, JPEG, ...) with OSG's image plugins, chosen by MIME
// type, file extension or the bytes' signature.
#include <osg/Image>

#include <string>

namespace osgDB
{
class Options;
}

namespace osgVis::gltfplugin
{
// The decoded image, or null with `problem` saying why (no plugin, decode failure).
osg::ref_ptr<osg::Image> decodeImage(const unsigned char* bytes, std::size_t size, const std::string& mimeType,
                                     const std::string& uri, const osgDB::Options* options, std::string& problem);
} // namespace osgVis::gltfplugin
