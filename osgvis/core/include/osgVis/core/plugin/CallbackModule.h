// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A visibility module implemented elsewhere (a plugin, or C code in the host) through the
/// callbacks of osgVis/visapi.h, wrapped as a VisibilityModule so it works in ModuleChain like the
/// built-in ones. It keeps the chain safe from the module: what a callback throws is caught, and a
/// failed query leaves every candidate visible.
#include <osgVis/visapi.h>

#include <osgVis/core/module/VisibilityModule.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace osgVis::core
{
/// A module (or its plugin file) that cannot be used; the message names the origin and the reason.
struct ModuleLoadFailure : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

/// Checks a callback table: the API version (same major, minor no newer than ours) and the required
/// callbacks (create, destroy, set_scene, cull, a name). Throws ModuleLoadFailure("<origin>: why").
void checkCallbacks(const osgvis_module_callbacks* callbacks, const std::string& origin);

class CallbackModule final : public VisibilityModule
{
public:
    /// Checks the table and calls create(userData); throws ModuleLoadFailure when either fails.
    /// `origin` names where the module comes from in messages (the plugin's path).
    CallbackModule(const osgvis_module_callbacks& callbacks, void* userData, std::string origin);
    ~CallbackModule() override;
    CallbackModule(const CallbackModule&) = delete;
    CallbackModule& operator=(const CallbackModule&) = delete;

    const char* name() const override { return _name.c_str(); }
    bool approximate() const override { return _callbacks.approximate != 0; }
    void setScene(const Scene& scene) override;
    void sceneChanged(const SceneChange& change) override;
    /// Never culls a visible object as long as the module keeps that guarantee; keeps every
    /// candidate when the module fails (or failed to take the scene).
    void cull(const View& view, VisibleSet& visible) override;
    bool supportsRegions() const override { return _callbacks.cull_region != nullptr; }
    void cullRegion(const ViewRegion& region, VisibleSet& visible) override;

    /// "<callback> failed: <reason>" of the last failure, "" while none has happened.
    const std::string& lastFailure() const { return _lastFailure; }
    /// How many callbacks have failed so far.
    std::size_t failureCount() const { return _failures; }

private:
    /// Runs one callback; false when it returns a failure status or throws, with lastFailure set
    /// (and printed on stderr when it differs from the previous failure).
    template <class Call> bool invoke(const char* callback, Call call);
    /// A query with the candidates restored when the module fails, so failing costs no visibility.
    template <class Call> void query(const char* callback, VisibleSet& visible, Call call);

    osgvis_module_callbacks _callbacks;
    std::string _origin, _name;
    void* _state = nullptr;
    /// The handle set_scene hands out; modules may keep it until the next set_scene (visapi.h).
    std::unique_ptr<osgvis_scene> _sceneHandle;
    bool _hasScene = false; ///< the last set_scene (or change) succeeded
    VisibleSet _candidates; ///< what the current query started with (reused: no allocation per frame)
    std::string _lastFailure;
    std::size_t _failures = 0;
};
} // namespace osgVis::core
