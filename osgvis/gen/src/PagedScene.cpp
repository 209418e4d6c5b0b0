// SPDX-License-Identifier: MIT
#include <osgVis/gen/PagedScene.h>

#include <osg/ComputeBoundsVisitor>
#include <osg/Geode>
#include <osg/MatrixTransform>
#include <osg/NodeVisitor>
#include <osg/PagedLOD>
#include <osg/ValueObject>
#include <osgDB/WriteFile>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <vector>

namespace osgVis::gen
{
namespace
{
// A drawable instance with what its path gave it: the matrix to the scene root and the state sets.
struct Piece
{
    osg::ref_ptr<osg::Drawable> drawable;
    osg::Matrixd world;
    osg::ref_ptr<osg::StateSet> state; // null when no node on the path has one
    osg::Vec3d centre;
};

class PieceCollector : public osg::NodeVisitor
{
public:
    PieceCollector() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}

    std::vector<Piece> pieces;

    void apply(osg::Drawable& drawable) override
    {
        const osg::BoundingBox& bound = drawable.getBoundingBox();
        if (!bound.valid())
            return;
        Piece piece;
        piece.drawable = &drawable;
        piece.world = osg::computeLocalToWorld(getNodePath());
        piece.centre = osg::Vec3d(bound.center()) * piece.world;
        // note: the path's state sets merged top down, so a child's setting wins as OSG's inheritance
        // lets it (OVERRIDE and PROTECTED follow StateSet::merge's rules); the drawable keeps its own.
        for (osg::Node* node : getNodePath())
            if (node != &drawable && node->getStateSet())
            {
                if (!piece.state)
                    piece.state = new osg::StateSet;
                piece.state->merge(*node->getStateSet());
            }
        pieces.push_back(std::move(piece));
    }
};

void write(osg::Node& node, const std::filesystem::path& path, PagedSummary& summary)
{
    if (!osgDB::writeNodeFile(node, path.string()))
        throw std::runtime_error("cannot write '" + path.string() + "'");
    summary.bytes += std::filesystem::file_size(path);
}
} // namespace

PagedSummary writePagedScene(osg::Node& scene, const std::string& dir, const PagedOptions& options)
{
    if (options.tiles == 0)
        throw std::invalid_argument("a paged scene needs at least one tile");
    if (!std::filesystem::is_directory(dir))
        throw std::runtime_error("'" + dir + "' is no directory");
    PieceCollector collector;
    scene.accept(collector);

    // The grid spans the two widest axes of the pieces' centres, its cells as square as the count allows.
    osg::BoundingBoxd box;
    for (const Piece& piece : collector.pieces)
        box.expandBy(piece.centre);
    const osg::Vec3d extent = box.valid() ? box._max - box._min : osg::Vec3d(1, 1, 1);
    int axes[3] = {0, 1, 2};
    std::sort(axes, axes + 3, [&](int a, int b) { return extent[a] > extent[b]; });
    const double wide = std::max(extent[axes[0]], 1e-9), narrow = std::max(extent[axes[1]], 1e-9);
    const unsigned along =
        std::clamp(unsigned(std::lround(std::sqrt(options.tiles * wide / narrow))), 1u, options.tiles);
    const unsigned across = std::max(1u, options.tiles / along); // along × across ≤ tiles
    const auto cellOf = [&](const osg::Vec3d& p, int axis, unsigned count)
    {
        const double t = extent[axis] > 0 ? (p[axis] - box._min[axis]) / extent[axis] : 0.0;
        return std::min(count - 1, unsigned(std::max(0.0, t * count)));
    };

    std::map<unsigned, osg::ref_ptr<osg::Group>> tiles; // by cell index, in grid order
    for (const Piece& piece : collector.pieces)
    {
        const unsigned cell = cellOf(piece.centre, axes[1], across) * along + cellOf(piece.centre, axes[0], along);
        osg::ref_ptr<osg::Group>& tile = tiles[cell];
        if (!tile)
            tile = new osg::Group;
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(piece.drawable.get());
        osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(piece.world);
        placed->setStateSet(piece.state.get());
        placed->addChild(geode.get());
        tile->addChild(placed.get());
    }

    PagedSummary summary;
    summary.drawables = collector.pieces.size();
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->setName("paged " + scene.getName());
    const float range = options.range > 0.0 ? float(options.range) : FLT_MAX;
    for (const auto& [cell, tile] : tiles)
    {
        char name[32];
        std::snprintf(name, sizeof name, "tile_%04u.osgb", cell);
        tile->setName(name);
        write(*tile, std::filesystem::path(dir) / name, summary);
        // note: the stated bound is the box of the tile's drawn geometry grown to a sphere, so the
        // geometry surely lies inside it (a looser sphere only keeps a tile traversed more often).
        osg::ComputeBoundsVisitor bounds;
        tile->accept(bounds);
        const osg::BoundingBox& b = bounds.getBoundingBox();
        osg::ref_ptr<osg::PagedLOD> paged = new osg::PagedLOD;
        paged->setName(name);
        paged->setCenterMode(osg::LOD::USER_DEFINED_CENTER);
        paged->setCenter(b.center());
        paged->setRadius(b.radius() * 1.001f);
        // note: the box as user values, the names osgVis::PagedBoundsMin/Max (osgVis/SceneExtractor),
        // which read them as a bound tighter than the sphere; plain OSG ignores them.
        paged->setUserValue("osgVis bounds min", osg::Vec3d(b._min));
        paged->setUserValue("osgVis bounds max", osg::Vec3d(b._max));
        paged->setFileName(0, name);
        paged->setRange(0, 0.0f, range);
        root->addChild(paged.get());
        ++summary.tiles;
    }
    const std::filesystem::path rootPath = std::filesystem::path(dir) / "root.osgb";
    write(*root, rootPath, summary);
    summary.rootPath = rootPath.string();

    // The same database under an osgVis::VisibilityGroup, as text that osgVis's serializers read
    // (note: OSG's text header names a generator and its version, two words)
    // (stock osgviewer with osgVis's plugins on OSG_LIBRARY_PATH); written without them.
    const std::filesystem::path culledPath = std::filesystem::path(dir) / "culled.osgt";
    std::ofstream culled(culledPath);
    culled << "#Ascii Scene\n#Version 161\n#Generator osgvisgen 1\n\n"
              "osgVis::VisibilityGroup {\n  UniqueID 1\n  Children 1 {\n    osg::ProxyNode {\n      UniqueID 2\n"
              "      FileNames 1 {\n        \"root.osgb\"\n      }\n    }\n  }\n  Modes \"octree\"\n}\n";
    if (!culled)
        throw std::runtime_error("cannot write '" + culledPath.string() + "'");
    summary.culledPath = culledPath.string();
    return summary;
}
} // namespace osgVis::gen
