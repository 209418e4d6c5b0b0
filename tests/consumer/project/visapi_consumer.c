/* SPDX-License-Identifier: MIT */
/* A C99 program against the installed tree: the installed header, libosgVisCore, and the plugin
 * mode `cfrustum` found in lib/osgvis-modules beside the installed library. */
#include <osgVis/visapi.h>

#include <stdio.h>
#include <string.h>

int main(void)
{
    osgvis_context* context = NULL;
    osgvis_object_desc box;
    osgvis_view_desc view;
    size_t count = 0;
    int i;
    memset(&box, 0, sizeof box);
    memset(&view, 0, sizeof view);
    box.bounds_min[0] = box.bounds_min[1] = -1.0;
    box.bounds_max[0] = box.bounds_max[1] = 1.0;
    box.bounds_min[2] = -0.5;
    box.bounds_max[2] = 0.5; /* inside the unit cube the identity matrices see */
    for (i = 0; i < 4; ++i)
        view.view_matrix[5 * i] = view.projection_matrix[5 * i] = 1.0;
    if (osgvis_version() != OSGVIS_VISAPI_VERSION || osgvis_context_create(&context) != OSGVIS_OK ||
        osgvis_scene_add_object(context, &box, NULL) != OSGVIS_OK ||
        osgvis_context_set_mode(context, "cfrustum") != OSGVIS_OK || osgvis_cull(context, &view) != OSGVIS_OK ||
        osgvis_visible_ids(context, NULL, 0, NULL, &count) != OSGVIS_OK)
    {
        fprintf(stderr, "visapi consumer: %s\n", osgvis_last_error());
        return 1;
    }
    osgvis_context_destroy(context);
    printf("visapi consumer ok (%u visible)\n", (unsigned)count);
    return 0;
}
