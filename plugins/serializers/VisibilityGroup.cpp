// osgVis::VisibilityGroup: its modes, asynchronous visibility and extraction options; children come
// through osg::Group's wrapper.
#include "VisibilityGroupOptions.h"

#include <osgVis/VisibilityGroup>
#include <osgVis/core/ModuleRegistry.h>

#include <osg/Notify>
#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/OutputStream>
#include <osgDB/Serializer>

#include <map>
#include <mutex>

namespace
{
using osgVis::VisibilityGroup;
using osgVis::serializers::asyncOptionsOf;
using osgVis::serializers::extractionOptionsOf;

// The async switch and its options arrive as three properties; setAsync takes them at once (and
// restarts the views' workers), so they are collected per group while it is read and applied when
// the group's properties are all read.
struct PendingAsync
{
    bool on = false;
    osgVis::core::AsyncOptions options;
};
std::mutex pendingMutex;
std::map<const VisibilityGroup*, PendingAsync> pendingAsync; // groups being read, on any reading thread

template <class Update>
void updatePending(VisibilityGroup& group, Update update)
{
    std::lock_guard<std::mutex> lock(pendingMutex);
    auto found = pendingAsync.find(&group);
    if (found == pendingAsync.end())
        found = pendingAsync.emplace(&group, PendingAsync{group.getAsync(), asyncOptionsOf(group)}).first;
    update(found->second);
}

struct ApplyPendingAsync : osgDB::FinishedObjectReadCallback
{
    void objectRead(osgDB::InputStream&, osg::Object& object) override
    {
        auto& group = static_cast<VisibilityGroup&>(object);
        PendingAsync pending;
        {
            std::lock_guard<std::mutex> lock(pendingMutex);
            auto found = pendingAsync.find(&group);
            if (found == pendingAsync.end())
                return;
            pending = found->second;
            pendingAsync.erase(found);
        }
        group.setAsync(pending.on, pending.options);
    }
};

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
    updatePending(group, [on](PendingAsync& pending) { pending.on = on; });
    return true;
}

bool writeAsync(osgDB::OutputStream& os, const VisibilityGroup& group)
{
    os << group.getAsync() << std::endl;
    return true;
}

bool checkOptions(const VisibilityGroup&)
{
    return osgVis::serializers::canReadOptions;
}

bool readAsyncLookAheadFrames(osgDB::InputStream& is, VisibilityGroup& group)
{
    unsigned frames = 0;
    is >> frames;
    if (is.getException())
        return false;
    updatePending(group, [frames](PendingAsync& pending) { pending.options.lookAheadFrames = frames; });
    return true;
}

bool writeAsyncLookAheadFrames(osgDB::OutputStream& os, const VisibilityGroup& group)
{
    os << static_cast<unsigned>(asyncOptionsOf(group).lookAheadFrames) << std::endl;
    return true;
}

bool readAsyncSlack(osgDB::InputStream& is, VisibilityGroup& group)
{
    double slack = 0.0;
    is >> slack;
    if (is.getException())
        return false;
    updatePending(group, [slack](PendingAsync& pending) { pending.options.slack = slack; });
    return true;
}

bool writeAsyncSlack(osgDB::OutputStream& os, const VisibilityGroup& group)
{
    os << asyncOptionsOf(group).slack << std::endl;
    return true;
}

bool readKeepTriangles(osgDB::InputStream& is, VisibilityGroup& group)
{
    bool keep = true;
    is >> keep;
    if (is.getException())
        return false;
    osgVis::ExtractionOptions options = extractionOptionsOf(group);
    options.keepTriangles = keep;
    group.setExtractionOptions(options);
    return true;
}

bool writeKeepTriangles(osgDB::OutputStream& os, const VisibilityGroup& group)
{
    os << extractionOptionsOf(group).keepTriangles << std::endl;
    return true;
}
} // namespace

REGISTER_OBJECT_WRAPPER(osgVis_VisibilityGroup, new osgVis::VisibilityGroup, osgVis::VisibilityGroup,
                        "osg::Object osg::Node osg::Group osgVis::VisibilityGroup")
{
    ADD_USER_SERIALIZER(Modes);
    ADD_USER_SERIALIZER(Async);
    // The options share one checker: written exactly when they can be read back from the group.
    wrapper->addSerializer(new osgDB::UserSerializer<MyClass>("AsyncLookAheadFrames", &checkOptions,
                                                              &readAsyncLookAheadFrames, &writeAsyncLookAheadFrames),
                           osgDB::BaseSerializer::RW_USER);
    wrapper->addSerializer(
        new osgDB::UserSerializer<MyClass>("AsyncSlack", &checkOptions, &readAsyncSlack, &writeAsyncSlack),
        osgDB::BaseSerializer::RW_USER);
    wrapper->addSerializer(
        new osgDB::UserSerializer<MyClass>("KeepTriangles", &checkOptions, &readKeepTriangles, &writeKeepTriangles),
        osgDB::BaseSerializer::RW_USER);
    wrapper->addFinishedObjectReadCallback(new ApplyPendingAsync);
}
