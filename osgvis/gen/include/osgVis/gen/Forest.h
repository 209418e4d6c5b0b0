// SPDX-License-Identifier: MIT
#pragma once
// The forest of Marsden & Guibas' multifocal z-buffer experiments: tessellated trees whose trunk,
// branches and leaf clumps are closed surfaces, each its own drawable, in three layouts (one tree,
// six in a line, a dense stand), and the box of viewpoints each layout is judged from. Frozen
// parameters: docs/scenes.md.
#include <osg/BoundingBox>

#include <cstdint>
#include <string>
#include <vector>

namespace osgVis::gen
{
enum class ForestLayout
{
    Single, // one tree
    Line,   // six trees in a row along +x, 8 m apart
    Dense   // 32 trees on a jittered 8 × 4 grid, 7 m apart
};

// "single" | "line" | "dense"; throws std::invalid_argument naming the known layouts.
ForestLayout parseForestLayout(const std::string& name);
const char* forestLayoutName(ForestLayout layout);
std::vector<std::string> forestLayoutNames();

unsigned forestTreeCount(ForestLayout layout); // 1, 6, 32

// The paper's view volume for a layout, an axis-aligned box of eye positions with edges 2 % of the
// tree height h, centred at height h/2, 2h from the trunk axis of the nearest tree on the −x side:
// single: the tree; line: the first tree, on the line's axis, looking along the line; dense: the
// forest's west edge (its westmost trunk), at the middle of its north–south extent, h the mean
// height. Heights are those of the layout built with `seed`, whatever the triangle budget.
osg::BoundingBoxd forestViewVolume(ForestLayout layout, std::uint32_t seed = 1);
} // namespace osgVis::gen
