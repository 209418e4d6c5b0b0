// SPDX-License-Identifier: MIT
#include <osgVis/core/plugin/CallbackModule.h>

#include <osgVis/core/capi/ModuleSideHandles.h>

#include <iostream>

namespace osgVis::core
{
namespace
{
std::string versionText(std::uint32_t version)
{
    return std::to_string(version >> 16) + "." + std::to_string(version & 0xFFFFu);
}
} // namespace

void checkCallbacks(const osgvis_module_callbacks* callbacks, const std::string& origin)
{
    if (!callbacks)
        throw ModuleLoadFailure(origin + ": no callback table");
    const std::uint32_t version = callbacks->api_version;
    if ((version >> 16) != OSGVIS_VISAPI_VERSION_MAJOR || (version & 0xFFFFu) > OSGVIS_VISAPI_VERSION_MINOR)
        throw ModuleLoadFailure(origin + ": built against visapi " + versionText(version) + ", this osgVis has " +
                                versionText(OSGVIS_VISAPI_VERSION));
    const std::pair<const char*, bool> required[] = {
        {"name", callbacks->name && *callbacks->name}, {"create", callbacks->create != nullptr},
        {"destroy", callbacks->destroy != nullptr},    {"set_scene", callbacks->set_scene != nullptr},
        {"cull", callbacks->cull != nullptr},
    };
    for (const auto& [field, present] : required)
    {
        if (!present)
            throw ModuleLoadFailure(origin + ": the callback table has no " + field);
    }
}

CallbackModule::CallbackModule(const osgvis_module_callbacks& callbacks, void* userData, std::string origin)
    : _callbacks(callbacks), _origin(std::move(origin)), _sceneHandle(std::make_unique<osgvis_scene>())
{
    checkCallbacks(&callbacks, _origin);
    _name = callbacks.name;
    std::string why;
    try
    {
        _state = _callbacks.create(userData);
    }
    catch (const std::exception& e)
    {
        why = std::string(": threw ") + e.what();
    }
    catch (...)
    {
        why = ": threw a non-standard exception";
    }
    if (!_state)
        throw ModuleLoadFailure(_origin + ": create failed" + why);
}

CallbackModule::~CallbackModule()
{
    try
    {
        _callbacks.destroy(_state);
    }
    catch (...)
    {
        std::cerr << "osgVis: module '" << _name << "' (" << _origin << "): destroy threw; ignored\n";
    }
}

template <class Call> bool CallbackModule::invoke(const char* callback, Call call)
{
    std::string why;
    try
    {
        const osgvis_status status = call();
        if (status == OSGVIS_OK)
            return true;
        const char* message = _callbacks.error_message ? _callbacks.error_message(_state) : nullptr;
        why = std::string(osgvis_status_name(status)) + (message && *message ? std::string(": ") + message : "");
    }
    catch (const std::exception& e)
    {
        why = std::string("threw ") + e.what();
    }
    catch (...)
    {
        why = "threw a non-standard exception";
    }
    const std::string failure = std::string(callback) + " failed: " + why;
    ++_failures;
    if (failure != _lastFailure) // note: a failure repeated every frame is printed once
        std::cerr << "osgVis: module '" << _name << "' (" << _origin << "): " << failure
                  << "; it culls nothing until it succeeds\n";
    _lastFailure = failure;
    return false;
}

void CallbackModule::setScene(const Scene& scene)
{
    _scene = &scene;
    _sceneHandle->scene = &scene;
    _hasScene = invoke("set_scene", [&] { return _callbacks.set_scene(_state, _sceneHandle.get()); });
}

void CallbackModule::sceneChanged(const SceneChange& change)
{
    if (!_callbacks.scene_changed || !_scene)
    {
        if (_scene)
            setScene(*_scene);
        return;
    }
    const osgvis_change_kind kind = change.kind == SceneChange::Kind::Inserted ? OSGVIS_CHANGE_INSERTED
                                    : change.kind == SceneChange::Kind::Moved  ? OSGVIS_CHANGE_MOVED
                                                                               : OSGVIS_CHANGE_REMOVED;
    // note: a module that missed a change no longer knows the scene; only a new set_scene mends that.
    if (!invoke("scene_changed",
                [&] {
                    return _callbacks.scene_changed(_state, _sceneHandle.get(), kind, change.objects.data(),
                                                    change.objects.size());
                }))
        _hasScene = false;
}

template <class Call> void CallbackModule::query(const char* callback, VisibleSet& visible, Call call)
{
    if (!_hasScene)
        return;
    _candidates = visible;
    osgvis_visible handle{&visible};
    if (!invoke(callback, [&] { return call(handle); }))
        visible = _candidates;
}

void CallbackModule::cull(const View& view, VisibleSet& visible)
{
    const osgvis_view handle{&view};
    query("cull", visible, [&](osgvis_visible& v) { return _callbacks.cull(_state, &handle, &v); });
}

void CallbackModule::cullRegion(const ViewRegion& region, VisibleSet& visible)
{
    if (!_callbacks.cull_region)
        return;
    const osgvis_region handle{&region};
    query("cull_region", visible, [&](osgvis_visible& v) { return _callbacks.cull_region(_state, &handle, &v); });
}
} // namespace osgVis::core
