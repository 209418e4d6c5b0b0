// SPDX-License-Identifier: MIT
#include "SerializerTestSupport.h"

#include <osgDB/ReaderWriter>
#include <osgDB/Registry>

#include <gtest/gtest.h>

#include <sstream>

namespace osgVis::test
{
void useBuiltPlugins()
{
    osgDB::FilePathList& paths = osgDB::Registry::instance()->getLibraryFilePathList();
    if (paths.empty() || paths.front() != OSGVIS_PLUGIN_OUTPUT_DIR)
        paths.push_front(OSGVIS_PLUGIN_OUTPUT_DIR);
}

namespace
{
osgDB::ReaderWriter& readerWriterFor(const SerializerFormat& format)
{
    osgDB::ReaderWriter* rw = osgDB::Registry::instance()->getReaderWriterForExtension(format.extension);
    if (!rw)
        throw std::runtime_error("no ReaderWriter for ." + format.extension);
    return *rw;
}
// note: on a stream the serializer plugin takes its format from the "fileType" plugin data that it
// otherwise derives from a file's extension.
osg::ref_ptr<osgDB::Options> streamOptions(const SerializerFormat& format)
{
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setPluginStringData("fileType", format.fileType);
    return options;
}
} // namespace

std::string writeToString(const osg::Node& node, const SerializerFormat& format)
{
    std::ostringstream out;
    const osg::ref_ptr<osgDB::Options> options = streamOptions(format);
    const osgDB::ReaderWriter::WriteResult result = readerWriterFor(format).writeNode(node, out, options.get());
    EXPECT_TRUE(result.success()) << result.message();
    return out.str();
}

osg::ref_ptr<osg::Node> readFromString(const std::string& data, const SerializerFormat& format)
{
    std::istringstream in(data);
    const osg::ref_ptr<osgDB::Options> options = streamOptions(format);
    osgDB::ReaderWriter::ReadResult result = readerWriterFor(format).readNode(in, options.get());
    return result.success() ? result.getNode() : nullptr;
}

struct CapturedWarnings::Handler : osg::NotifyHandler
{
    std::string text;
    void notify(osg::NotifySeverity severity, const char* message) override
    {
        if (severity <= osg::WARN)
            text += message;
    }
};

CapturedWarnings::CapturedWarnings()
    : _handler(new Handler), _previous(osg::getNotifyHandler()), _previousLevel(osg::getNotifyLevel())
{
    osg::setNotifyHandler(_handler.get());
    if (_previousLevel < osg::WARN)
        osg::setNotifyLevel(osg::WARN);
}

CapturedWarnings::~CapturedWarnings()
{
    osg::setNotifyLevel(_previousLevel);
    osg::setNotifyHandler(_previous.get());
}

const std::string& CapturedWarnings::text() const
{
    return _handler->text;
}
} // namespace osgVis::test
