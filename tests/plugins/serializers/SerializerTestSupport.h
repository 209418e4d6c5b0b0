// SPDX-License-Identifier: MIT
#pragma once
// What the serializer tests share: the built plugins first on osgDB's library path, writing and
// reading a node through a format's ReaderWriter and a string, and catching OSG's warnings.
#include <osg/Node>
#include <osg/Notify>
#include <osgDB/Options>

#include <ostream>
#include <string>

namespace osgVis::test
{
// One of OSG's serializer formats: its extension and the plugin's name for it on a stream.
struct SerializerFormat
{
    std::string extension; // osgt, osgb, osgx
    std::string fileType;  // Ascii, Binary, XML
};
// gtest names a format by its extension (instead of a byte dump).
inline void PrintTo(const SerializerFormat& format, std::ostream* out)
{
    *out << format.extension;
}

// Puts <build>/lib/osgPlugins-<version> first on osgDB's library path, so the plugin under test is the
// one osgDB loads for osgVis classes.
void useBuiltPlugins();

// The node as the format's ReaderWriter writes it to a stream (fails the test on error).
std::string writeToString(const osg::Node& node, const SerializerFormat& format);
// Reads a stream of the format; null when the ReaderWriter reports an error.
osg::ref_ptr<osg::Node> readFromString(const std::string& data, const SerializerFormat& format);

// Collects OSG's notify output at WARN and above while alive (the previous handler restored after).
class CapturedWarnings
{
public:
    CapturedWarnings();
    ~CapturedWarnings();
    CapturedWarnings(const CapturedWarnings&) = delete;
    CapturedWarnings& operator=(const CapturedWarnings&) = delete;

    const std::string& text() const;

private:
    struct Handler;
    osg::ref_ptr<Handler> _handler;
    osg::ref_ptr<osg::NotifyHandler> _previous;
    osg::NotifySeverity _previousLevel;
};
} // namespace osgVis::test
