// SPDX-License-Identifier: MIT
// Forest: trees of closed tessellated surfaces (the scenes of Marsden & Guibas' multifocal z-buffer
// experiments: one tree, six in a line, a dense stand of ~32). A tree is a tapered trunk, a few
// branches off it, twigs off each branch and a leaf clump (an ellipsoid) at the top of the trunk and
// at the tip of every branch and twig; every part is its own closed drawable, so one tree is many
// objects and its leaf clumps hide each other and the parts behind them.
//
//   z                 ( top )               line:   T   T   T   T   T   T  → x (8 m apart)
//   ^          (tw)   ( cl  )   (tw)
//   |            \  (br)  |  (br)  /        dense:  T  T  T  T  T  T  T  T   8 × 4 on a 7 m grid,
//   |             \__\    |    /__/                 T  T  T  T  T  T  T  T   jittered ±1 m
//   |                 \   |   /                     ....................... the walk: along the
//   |                  \__|__/                      T  T  T  T  T  T  T  T   aisles between rows
//   |                     |  trunk                  T  T  T  T  T  T  T  T
//   +---------------------+-----------> x
//
// The trees stand on nothing: a ground plane would hide nothing from eyes above it and would be one
// more object every eye sees.
#include <osgVis/gen/Forest.h>

#include "Circle.h"
#include "NameTable.h"
#include "Palette.h"
#include "Scenes.h"
#include "WalkPath.h"

#include <algorithm>

namespace osgVis::gen
{
namespace
{
constexpr double nominalHeight = 10.0; // metres; each tree's scale is this × U[0.9, 1.1]
constexpr double lineSpacing = 8.0;
constexpr double gridSpacing = 7.0, gridJitter = 1.0;
constexpr int gridColumns = 8, gridRows = 4;
constexpr double barkDensityScale = 4.0; // bark is meshed finer than leaves: branches are slender
constexpr double eyeHeight = 1.7;
constexpr double walkMargin = 6.0;                        // the walk's loop keeps this far outside the outermost trunks
constexpr double turnOffset = 2.0;                        // corners of the walk are cut this far before and after
constexpr double volumeDistance = 2.0, volumeEdge = 0.02; // in tree heights

constexpr Named<ForestLayout> layoutNames[] = {
    {ForestLayout::Single, "single"}, {ForestLayout::Line, "line"}, {ForestLayout::Dense, "dense"}};

// One tree in its own coordinates: trunk foot at the origin, z up.
struct Tree
{
    Tube trunk;
    std::vector<Tube> branches; // branches and twigs, each followed by the twigs growing off it
    std::vector<Ellipsoid> clumps;
    double height = 0.0; // top of its highest part
};

double degreesToTurns(double degrees)
{
    return degrees / 360.0;
}

double radiusAt(const Tube& tube, double fraction)
{
    return tube.baseRadius + (tube.topRadius - tube.baseRadius) * fraction;
}

osg::Vec3d pointAt(const Tube& tube, double fraction)
{
    return tube.base + (tube.top - tube.base) * fraction;
}

// A clump wider than tall, turned by a random angle about z.
Ellipsoid clumpAt(const osg::Vec3d& centre, double size, Random& rng)
{
    const double a = size * rng.uniform(0.85, 1.15);
    const double b = a * rng.uniform(0.8, 1.0), c = a * rng.uniform(0.6, 0.8);
    const osg::Vec2d heading = unitCircle(rng.unit());
    // (a, b, c) right-handed: a × b points up, along c.
    return {centre, osg::Vec3d(heading.x(), heading.y(), 0.0) * a, osg::Vec3d(-heading.y(), heading.x(), 0.0) * b,
            osg::Vec3d(0.0, 0.0, c)};
}

double topOf(const Tube& tube)
{
    return std::max(tube.base.z(), tube.top.z()) + std::max(tube.baseRadius, tube.topRadius);
}

Tree growTree(Random& rng)
{
    const double h = nominalHeight * rng.uniform(0.9, 1.1);
    Tree tree;
    const double trunkRadius = 0.022 * h * rng.uniform(0.9, 1.1);
    tree.trunk = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.72 * h}, trunkRadius, 0.4 * trunkRadius};

    const int branches = rng.between(4, 6);
    const double firstHeading = rng.unit();
    for (int i = 0; i < branches; ++i)
    {
        // Spread up the upper trunk and around it by the golden angle, so no two branches overlap.
        const double along = 0.38 + 0.30 * (i + rng.uniform(0.2, 0.8)) / branches;
        const osg::Vec2d heading = unitCircle(firstHeading + 0.381966 * i + rng.uniform(-0.05, 0.05));
        const osg::Vec2d elevation = unitCircle(degreesToTurns(rng.uniform(30.0, 55.0)));
        const osg::Vec3d direction(elevation.x() * heading.x(), elevation.x() * heading.y(), elevation.y());
        // Lower branches reach further.
        const double length = 0.32 * h * rng.uniform(0.85, 1.1) * (1.15 - 0.5 * (along - 0.38) / 0.30);
        const double radius = 0.5 * radiusAt(tree.trunk, along);
        const osg::Vec3d start = pointAt(tree.trunk, along);
        const Tube branch{start, start + direction * length, radius, 0.35 * radius};
        tree.branches.push_back(branch);

        const int twigs = rng.between(2, 4);
        for (int j = 0; j < twigs; ++j)
        {
            const double from = 0.45 + 0.4 * (j + rng.uniform(0.2, 0.8)) / twigs;
            const osg::Vec2d spread = unitCircle(degreesToTurns(rng.uniform(25.0, 45.0)));
            osg::Vec3d twigDirection = direction * spread.x() + aroundAxis(direction, rng.unit()) * spread.y();
            twigDirection.z() = std::max(twigDirection.z(), 0.2); // twigs grow upwards, clear of eye height
            twigDirection.normalize();
            const double twigLength = 0.45 * length * rng.uniform(0.8, 1.2);
            const double twigRadius = 0.6 * radiusAt(branch, from);
            const osg::Vec3d twigStart = pointAt(branch, from);
            const Tube twig{twigStart, twigStart + twigDirection * twigLength, twigRadius, 0.4 * twigRadius};
            tree.branches.push_back(twig);
            tree.clumps.push_back(clumpAt(twig.top, 0.085 * h, rng));
        }
        tree.clumps.push_back(clumpAt(branch.top, 0.10 * h, rng));
    }
    tree.clumps.push_back(clumpAt(tree.trunk.top + osg::Vec3d(0.0, 0.0, 0.04 * h), 0.12 * h, rng));

    tree.height = topOf(tree.trunk);
    for (const Tube& t : tree.branches)
        tree.height = std::max(tree.height, topOf(t));
    for (const Ellipsoid& e : tree.clumps)
        tree.height = std::max(tree.height, e.centre.z() + e.c.length());
    return tree;
}

struct Forest
{
    std::vector<osg::Vec3d> positions; // trunk feet
    std::vector<Tree> trees;
};

Forest plantForest(ForestLayout layout, std::uint32_t seed)
{
    Random rng(seed);
    Forest forest;
    switch (layout)
    {
    case ForestLayout::Single:
        forest.positions.emplace_back(0.0, 0.0, 0.0);
        break;
    case ForestLayout::Line:
        for (unsigned i = 0; i < forestTreeCount(layout); ++i)
            forest.positions.emplace_back(lineSpacing * i, 0.0, 0.0);
        break;
    case ForestLayout::Dense:
        for (int row = 0; row < gridRows; ++row)
            for (int column = 0; column < gridColumns; ++column)
                forest.positions.emplace_back(gridSpacing * column + rng.uniform(-gridJitter, gridJitter),
                                              gridSpacing * row + rng.uniform(-gridJitter, gridJitter), 0.0);
        break;
    }
    for (std::size_t i = 0; i < forest.positions.size(); ++i)
        forest.trees.push_back(growTree(rng));
    return forest;
}

// Bounds of the trunk feet.
osg::BoundingBoxd footprint(const Forest& forest)
{
    osg::BoundingBoxd box;
    for (const osg::Vec3d& p : forest.positions)
        box.expandBy(p);
    return box;
}

// Waypoints through `corners` with every inner corner (every corner of a closed loop) cut `offset`
// before and after it, so the walk turns smoothly.
std::vector<osg::Vec3d> cutCorners(const std::vector<osg::Vec3d>& corners, bool closed)
{
    const std::size_t n = corners.size();
    std::vector<osg::Vec3d> points{closed ? (corners[0] + corners[1]) * 0.5 : corners.front()};
    for (std::size_t i = 1; i < (closed ? n + 1 : n - 1); ++i)
    {
        const osg::Vec3d& corner = corners[i % n];
        osg::Vec3d in = corner - corners[i - 1], out = corners[(i + 1) % n] - corner;
        const double offset = std::min({turnOffset, 0.4 * in.length(), 0.4 * out.length()});
        in.normalize();
        out.normalize();
        points.push_back(corner - in * offset);
        points.push_back(corner + out * offset);
    }
    points.push_back(closed ? points.front() : corners.back());
    return points;
}

// Dense: along the aisles between the grid's rows, turning outside the forest; otherwise a loop
// around the trees.
std::vector<osg::Vec3d> walkRoute(ForestLayout layout, const Forest& forest)
{
    const osg::BoundingBoxd feet = footprint(forest);
    const double x0 = feet.xMin() - walkMargin, x1 = feet.xMax() + walkMargin;
    if (layout == ForestLayout::Dense)
    {
        std::vector<osg::Vec3d> corners;
        for (int aisle = 0; aisle + 1 < gridRows; ++aisle)
        {
            const double y = gridSpacing * (aisle + 0.5);
            const bool east = aisle % 2 == 0;
            corners.emplace_back(east ? x0 : x1, y, eyeHeight);
            corners.emplace_back(east ? x1 : x0, y, eyeHeight);
        }
        return cutCorners(corners, false);
    }
    const double y0 = feet.yMin() - walkMargin, y1 = feet.yMax() + walkMargin;
    return cutCorners({{x0, y0, eyeHeight}, {x1, y0, eyeHeight}, {x1, y1, eyeHeight}, {x0, y1, eyeHeight}}, true);
}

osg::BoundingBoxd treeBounds(const Tree& tree, const osg::Vec3d& at)
{
    osg::BoundingBoxd box;
    const auto addTube = [&](const Tube& t)
    {
        const double r = std::max(t.baseRadius, t.topRadius);
        for (const osg::Vec3d& p : {t.base, t.top})
        {
            box.expandBy(at + p - osg::Vec3d(r, r, r));
            box.expandBy(at + p + osg::Vec3d(r, r, r));
        }
    };
    addTube(tree.trunk);
    for (const Tube& t : tree.branches)
        addTube(t);
    for (const Ellipsoid& e : tree.clumps)
    {
        const double r = std::max({e.a.length(), e.b.length(), e.c.length()});
        box.expandBy(at + e.centre - osg::Vec3d(r, r, r));
        box.expandBy(at + e.centre + osg::Vec3d(r, r, r));
    }
    return box;
}

Mesh partMesh(const char* name, const osg::Vec4& colour, double densityScale)
{
    Mesh mesh;
    mesh.name = name;
    mesh.colour = colour;
    mesh.densityScale = densityScale;
    return mesh;
}
} // namespace

ForestLayout parseForestLayout(const std::string& name)
{
    return parseNamed(layoutNames, name, "forest layout");
}

const char* forestLayoutName(ForestLayout layout)
{
    return nameOf(layoutNames, layout);
}

std::vector<std::string> forestLayoutNames()
{
    return namesIn(layoutNames);
}

unsigned forestTreeCount(ForestLayout layout)
{
    switch (layout)
    {
    case ForestLayout::Single:
        return 1;
    case ForestLayout::Line:
        return 6;
    case ForestLayout::Dense:
        return unsigned(gridColumns * gridRows);
    }
    return 0;
}

osg::BoundingBoxd forestViewVolume(ForestLayout layout, std::uint32_t seed)
{
    const Forest forest = plantForest(layout, seed);
    double height = forest.trees.front().height;
    osg::Vec3d from = forest.positions.front();
    if (layout == ForestLayout::Dense)
    {
        height = 0.0;
        for (const Tree& tree : forest.trees)
            height += tree.height / double(forest.trees.size());
        const osg::BoundingBoxd feet = footprint(forest);
        from.set(feet.xMin(), 0.5 * (feet.yMin() + feet.yMax()), 0.0);
    }
    const osg::Vec3d centre(from.x() - volumeDistance * height, from.y(), 0.5 * height);
    const double half = 0.5 * volumeEdge * height;
    return {centre - osg::Vec3d(half, half, half), centre + osg::Vec3d(half, half, half)};
}

SceneModel forestModel(ForestLayout layout, std::uint32_t seed)
{
    const Forest forest = plantForest(layout, seed);
    Random colours(seed ^ 0x5eedu); // colours apart, so they never shift the shapes
    SceneModel scene;
    osg::BoundingBoxd bounds;
    for (std::size_t i = 0; i < forest.trees.size(); ++i)
    {
        const Tree& tree = forest.trees[i];
        const std::string id = std::to_string(i);
        ModelNode& placed =
            scene.model.root.add(ModelNode::transform("tree " + id, osg::Matrixd::translate(forest.positions[i])));
        ModelNode& parts = placed.add(ModelNode::geode("tree " + id + " parts"));
        const osg::Vec4 bark = varied(palette::bark, colours, 0.05);
        Mesh trunk = partMesh("trunk", bark, barkDensityScale);
        trunk.tubes.push_back(tree.trunk);
        parts.meshes.push_back(scene.model.addMesh(std::move(trunk)));
        for (const Tube& t : tree.branches)
        {
            Mesh branch = partMesh("branch", bark, barkDensityScale);
            branch.tubes.push_back(t);
            parts.meshes.push_back(scene.model.addMesh(std::move(branch)));
        }
        for (const Ellipsoid& e : tree.clumps)
        {
            Mesh leaves = partMesh("leaves", varied(palette::leaves, colours, 0.08), 1.0);
            leaves.ellipsoids.push_back(e);
            parts.meshes.push_back(scene.model.addMesh(std::move(leaves)));
        }
        bounds.expandBy(treeBounds(tree, forest.positions[i]));
    }
    const std::vector<osg::Vec3d> route = walkRoute(layout, forest);
    for (const osg::Vec3d& p : route)
        bounds.expandBy(p);
    scene.walk = perspectiveWalk(walkAlong(route, WalkPace{1.4, 0.1, 2.0, 200, 1000}), 0.1, farPlaneFor(bounds));
    return scene;
}
} // namespace osgVis::gen
