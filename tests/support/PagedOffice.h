// SPDX-License-Identifier: MIT
#pragma once
// The small paged database the bake tests share: a 4000-triangle generated office written as
// DIR/root.osgb over six tiles (osgVis::gen::writePagedScene).
#include <osgVis/gen/Generator.h>
#include <osgVis/gen/PagedScene.h>

#include <string>

namespace osgVis::test
{
inline osgVis::gen::PagedSummary writePagedOffice(const std::string& dir)
{
    osgVis::gen::GenerateOptions options;
    options.kind = osgVis::gen::SceneKind::Office;
    options.triangles = 4000;
    osgVis::gen::PagedOptions paging;
    paging.tiles = 6;
    return osgVis::gen::writePagedScene(*osgVis::gen::generate(options).root, dir, paging);
}
} // namespace osgVis::test
