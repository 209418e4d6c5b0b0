// SPDX-License-Identifier: MIT
// Plugins that go wrong in one way each, for the loading and failure tests: compiled once per
// BROKEN_* macro into osgvis_module_broken-<kind>.so (tests/core/CMakeLists.txt).
#include <osgVis/visapi.h>

#include <stdexcept>

namespace
{
void* create(void*)
{
#ifdef BROKEN_NOCREATE
    return nullptr;
#else
    static int state = 0;
    return &state;
#endif
}

void destroy(void*) {}

osgvis_status setScene(void*, const osgvis_scene*)
{
#ifdef BROKEN_SCENEFAILS
    return OSGVIS_ERROR_INVALID_ARGUMENT;
#else
    return OSGVIS_OK;
#endif
}

// Clears every candidate first, so a host that did not restore them would cull visible objects.
[[maybe_unused]] osgvis_status cull(void*, const osgvis_view*, osgvis_visible* visible)
{
    for (uint32_t id = 0; id < osgvis_visible_capacity(visible); ++id)
        osgvis_visible_clear(visible, id);
#ifdef BROKEN_THROWS
    throw std::runtime_error("cull exploded");
#endif
    return OSGVIS_ERROR_MODULE_FAILED;
}

const char* errorMessage(void*)
{
#ifdef BROKEN_SCENEFAILS
    return "scene refused";
#else
    return "no luck today";
#endif
}

osgvis_module_callbacks callbacks()
{
    osgvis_module_callbacks table{};
    table.api_version = OSGVIS_VISAPI_VERSION;
#ifdef BROKEN_VERSION
    table.api_version = (OSGVIS_VISAPI_VERSION_MAJOR + 1) << 16;
#endif
    table.name = "broken";
    table.create = create;
    table.destroy = destroy;
    table.set_scene = setScene;
#ifndef BROKEN_NOCULL
    table.cull = cull;
#endif
    table.error_message = errorMessage;
    return table;
}

const osgvis_module_callbacks table = callbacks();
} // namespace

#ifdef BROKEN_NOSYMBOL
extern "C" OSGVIS_VISAPI_EXPORT const osgvis_module_callbacks* osgvis_module_entry_misspelt(uint32_t)
{
    return &table;
}
#else
extern "C" OSGVIS_VISAPI_EXPORT const osgvis_module_callbacks* osgvis_module_entry(uint32_t)
{
#ifdef BROKEN_REFUSES
    return nullptr;
#else
    return &table;
#endif
}
#endif
