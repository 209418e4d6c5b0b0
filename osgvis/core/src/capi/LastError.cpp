// SPDX-License-Identifier: MIT
// The version, the status names and the per-thread last error of osgVis/visapi.h.
#include <osgVis/core/capi/LastError.h>

#include <cstdarg>
#include <cstdio>

namespace
{
// note: a fixed buffer, so recording an error can never throw (it runs inside catch blocks).
thread_local char lastErrorText[1024] = "";
} // namespace

namespace osgVis::core::capi
{
osgvis_status failure(osgvis_status status, const char* message) noexcept
{
    return failuref(status, "%s", message ? message : "");
}

osgvis_status failuref(osgvis_status status, const char* format, ...) noexcept
{
    std::va_list arguments;
    va_start(arguments, format);
    std::vsnprintf(lastErrorText, sizeof(lastErrorText), format, arguments);
    va_end(arguments);
    return status;
}
} // namespace osgVis::core::capi

// note: C linkage comes from the declarations in osgVis/visapi.h.
uint32_t osgvis_version(void)
{
    return OSGVIS_VISAPI_VERSION;
}

const char* osgvis_status_name(osgvis_status status)
{
    switch (status)
    {
    case OSGVIS_OK:
        return "OSGVIS_OK";
    case OSGVIS_ERROR_INVALID_ARGUMENT:
        return "OSGVIS_ERROR_INVALID_ARGUMENT";
    case OSGVIS_ERROR_UNKNOWN_MODE:
        return "OSGVIS_ERROR_UNKNOWN_MODE";
    case OSGVIS_ERROR_MODULE_LOAD:
        return "OSGVIS_ERROR_MODULE_LOAD";
    case OSGVIS_ERROR_MODULE_FAILED:
        return "OSGVIS_ERROR_MODULE_FAILED";
    case OSGVIS_ERROR_BAD_STATE:
        return "OSGVIS_ERROR_BAD_STATE";
    case OSGVIS_ERROR_UNSUPPORTED:
        return "OSGVIS_ERROR_UNSUPPORTED";
    case OSGVIS_ERROR_OUT_OF_MEMORY:
        return "OSGVIS_ERROR_OUT_OF_MEMORY";
    case OSGVIS_ERROR_INTERNAL:
        return "OSGVIS_ERROR_INTERNAL";
    }
    return "unknown status";
}

const char* osgvis_last_error(void)
{
    return lastErrorText;
}
