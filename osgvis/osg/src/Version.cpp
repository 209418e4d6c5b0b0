// SPDX-License-Identifier: MIT
#include <osgVis/Version>

#define OSGVIS_STRINGIFY2(x) #x
#define OSGVIS_STRINGIFY(x) OSGVIS_STRINGIFY2(x)

extern "C" {
const char* osgVisGetVersion()
{
    return OSGVIS_STRINGIFY(OSGVIS_MAJOR_VERSION) "." OSGVIS_STRINGIFY(OSGVIS_MINOR_VERSION) "." OSGVIS_STRINGIFY(
        OSGVIS_PATCH_VERSION);
}

const char* osgVisGetLibraryName()
{
    return "osgVis Library";
}
}
