// SPDX-License-Identifier: MIT
// osgvis_register_module: a C module of the host process joins the registry, so mode strings and
// the C++ createChain reach it by name like a built-in module.
#include <osgVis/visapi.h>

#include <osgVis/core/plugin/CallbackModule.h>

#include "ErrorBoundary.h"

using namespace osgVis::core;

extern "C" osgvis_status osgvis_register_module(const char* name, const osgvis_module_callbacks* callbacks,
                                                void* user_data)
{
    return capi::guarded("osgvis_register_module",
                         [&]
                         {
                             if (!name || !*name)
                                 throw capi::ApiFailure(OSGVIS_ERROR_INVALID_ARGUMENT, "a module needs a name");
                             const std::string origin = std::string("module registered as '") + name + "'";
                             try
                             {
                                 checkCallbacks(callbacks, origin);
                             }
                             catch (const ModuleLoadFailure& e)
                             {
                                 throw capi::ApiFailure(OSGVIS_ERROR_MODULE_LOAD, e.what());
                             }
                             // A create that fails throws ModuleLoadFailure, which createModule reports as
                             // ModuleLoadError.
                             registerModule(name,
                                            [callbacks, user_data, origin]() -> std::unique_ptr<VisibilityModule> {
                                                return std::make_unique<CallbackModule>(*callbacks, user_data, origin);
                                            });
                         });
}
