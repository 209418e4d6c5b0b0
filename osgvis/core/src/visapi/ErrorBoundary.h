// SPDX-License-Identifier: MIT
#pragma once
// The exception boundary of the C interface: every C entry point runs its body through guarded(),
// which turns whatever the body throws into a status and this thread's last error, since an
// exception thrown across C is undefined.
#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/capi/LastError.h>

#include <new>
#include <stdexcept>

namespace osgVis::core::capi
{
/// A failure the body states itself: its status and message.
struct ApiFailure : std::runtime_error
{
    ApiFailure(osgvis_status s, const std::string& message) : std::runtime_error(message), status(s) {}
    osgvis_status status;
};

template <class Body> osgvis_status guarded(const char* function, Body body) noexcept
{
    try
    {
        body();
        return OSGVIS_OK;
    }
    catch (const ApiFailure& e)
    {
        return failuref(e.status, "%s: %s", function, e.what());
    }
    catch (const ModuleLoadError& e)
    {
        return failuref(OSGVIS_ERROR_MODULE_LOAD, "%s: %s", function, e.what());
    }
    catch (const UnknownModeError& e)
    {
        return failuref(OSGVIS_ERROR_UNKNOWN_MODE, "%s: %s", function, e.what());
    }
    catch (const std::bad_alloc&)
    {
        return failuref(OSGVIS_ERROR_OUT_OF_MEMORY, "%s: out of memory", function);
    }
    catch (const std::exception& e)
    {
        return failuref(OSGVIS_ERROR_INTERNAL, "%s: %s", function, e.what());
    }
    catch (...)
    {
        return failuref(OSGVIS_ERROR_INTERNAL, "%s: a non-standard exception", function);
    }
}
} // namespace osgVis::core::capi
