// SPDX-License-Identifier: MIT
#pragma once
// What the plugins' ReaderWriters share (included as "../NodeReaderWriter.h", so the glTF fuzzer
// that compiles the reader on its own needs no include path): their objects are nodes, and a file
// name is checked and looked up on the data path the same way before the plugin reads the file.
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/ReaderWriter>

#include <string>

namespace osgVis::plugins
{
class NodeReaderWriter : public osgDB::ReaderWriter
{
public:
    ReadResult readObject(const std::string& file, const Options* options) const override
    {
        return readNode(file, options);
    }
    ReadResult readObject(std::istream& in, const Options* options) const override { return readNode(in, options); }

    /// FILE_NOT_HANDLED for another extension, FILE_NOT_FOUND off the data path; else readFound.
    ReadResult readNode(const std::string& file, const Options* options) const override
    {
        if (!acceptsExtension(osgDB::getLowerCaseFileExtension(file)))
            return ReadResult::FILE_NOT_HANDLED;
        const std::string path = osgDB::findDataFile(file, options);
        if (path.empty())
            return ReadResult::FILE_NOT_FOUND;
        return readFound(file, path, options);
    }
    using osgDB::ReaderWriter::readNode;

protected:
    /// Reads `path`, where osgDB found the `file` a caller named.
    virtual ReadResult readFound(const std::string& file, const std::string& path, const Options* options) const = 0;
};
} // namespace osgVis::plugins
