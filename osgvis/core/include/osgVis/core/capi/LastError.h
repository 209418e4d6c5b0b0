// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The per-thread message osgvis_last_error() returns: every C entry point that fails sets it.
#include <osgVis/visapi.h>

namespace osgVis::core::capi
{
/// Records `message` as this thread's last error and returns `status`, so a failing call can
/// `return failure(OSGVIS_ERROR_..., "why")`. Never throws nor allocates (a long message is cut).
osgvis_status failure(osgvis_status status, const char* message) noexcept;
/// The same with a message printf formats.
osgvis_status failuref(osgvis_status status, const char* format, ...) noexcept __attribute__((format(printf, 2, 3)));
} // namespace osgVis::core::capi
