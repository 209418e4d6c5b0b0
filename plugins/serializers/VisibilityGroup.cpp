// SPDX-License-Identifier: MIT
// osgVis::VisibilityGroup: its modes, asynchronous visibility and extraction options; children come
// through osg::Group's wrapper.
#include <osgVis/VisibilityGroup>
#include <osgVis/core/api/ModuleRegistry.h>

#include <osg/Notify>
#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/OutputStream>
#include <osgDB/Serializer>


namespace
{
using osgVis::VisibilityGroup;

bool checkModes(const VisibilityGroup&)
{
    return true;
}

// An unknown mode (a file from a newer osgVis, a typo) must not fail the whole load: warn and cull
// with the frustum alone, which is conservative.
bool readModes(osgDB::InputStream& is, VisibilityGroup& group)
{
    std::string modes;
    is.readWrappedString(modes);
    if (is.getException())
        return false;
    try
    {
        group.setModes(modes);
    }
    catch (const osgVis::core::UnknownModeError& error)
    {
        OSG_WARN << "osgVis::VisibilityGroup \"" << group.getName() << "\": " << error.what()
                 << "; culling with \"frustum\"" << std::endl;
        group.setModes("frustum");
    }
    return true;
}

bool writeModes(osgDB::OutputStream& os, const VisibilityGroup& group)
{
    os.writeWrappedString(group.getModes());
    os << std::endl;
    return true;
}

bool checkAsync(const VisibilityGroup&)
{
    return true;
}

bool readAsync(osgDB::InputStream& is, VisibilityGroup& group)
{
    bool on = false;
    is >> on;
    if (is.getException())
        return false;
    group.setAsync(on, group.getAsyncOptions()); // cheap on a group no view has culled yet
    return true;
}

bool writeAsync(osgDB::OutputStream& os, const VisibilityGroup& group)
{
    os << group.getAsync() << std::endl;
    return true;
}

bool checkOptions(const VisibilityGroup&)
{
    return true;
}

// Reads a Value into one field of `options` (a copy of the group's) and hands the copy to `set`.
template <class Value, class Options, class Field, class Set>
bool readOption(osgDB::InputStream& is, Options options, Field Options::*field, Set set)
{
    Value value{};
    is >> value;
    if (is.getException())
        return false;
    options.*field = value;
    set(options);
    return true;
}

bool readAsyncLookAheadFrames(osgDB::InputStream& is, VisibilityGroup& group)
{
    return readOption<unsigned>(is, group.getAsyncOptions(), &osgVis::core::AsyncOptions::lookAheadFrames,
                                [&](const auto& options) { group.setAsync(group.getAsync(), options); });
}

bool writeAsyncLookAheadFrames(osgDB::OutputStream& os, const VisibilityGroup& group)
{
    os << static_cast<unsigned>(group.getAsyncOptions().lookAheadFrames) << std::endl;
    return true;
}

bool readAsyncSlack(osgDB::InputStream& is, VisibilityGroup& group)
{
    return readOption<double>(is, group.getAsyncOptions(), &osgVis::core::AsyncOptions::slack,
                              [&](const auto& options) { group.setAsync(group.getAsync(), options); });
}

bool writeAsyncSlack(osgDB::OutputStream& os, const VisibilityGroup& group)
{
    os << group.getAsyncOptions().slack << std::endl;
    return true;
}

bool readKeepTriangles(osgDB::InputStream& is, VisibilityGroup& group)
{
    return readOption<bool>(is, group.getExtractionOptions(), &osgVis::ExtractionOptions::keepTriangles,
                            [&](const auto& options) { group.setExtractionOptions(options); });
}

bool writeKeepTriangles(osgDB::OutputStream& os, const VisibilityGroup& group)
{
    os << group.getExtractionOptions().keepTriangles << std::endl;
    return true;
}
} // namespace

REGISTER_OBJECT_WRAPPER(osgVis_VisibilityGroup, new osgVis::VisibilityGroup, osgVis::VisibilityGroup,
                        "osg::Object osg::Node osg::Group osgVis::VisibilityGroup")
{
    ADD_USER_SERIALIZER(Modes);
    ADD_USER_SERIALIZER(Async);
    wrapper->addSerializer(new osgDB::UserSerializer<MyClass>("AsyncLookAheadFrames", &checkOptions,
                                                              &readAsyncLookAheadFrames, &writeAsyncLookAheadFrames),
                           osgDB::BaseSerializer::RW_USER);
    wrapper->addSerializer(
        new osgDB::UserSerializer<MyClass>("AsyncSlack", &checkOptions, &readAsyncSlack, &writeAsyncSlack),
        osgDB::BaseSerializer::RW_USER);
    wrapper->addSerializer(
        new osgDB::UserSerializer<MyClass>("KeepTriangles", &checkOptions, &readKeepTriangles, &writeKeepTriangles),
        osgDB::BaseSerializer::RW_USER);
}
