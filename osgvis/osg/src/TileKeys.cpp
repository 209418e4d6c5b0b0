// SPDX-License-Identifier: MIT
// Each object's tile: the innermost paged node on its path whose child there names a file, keyed by
// that file relative to the root file's folder. A child without a file (a PagedLOD's inline coarse
// level) belongs to the file that holds its node.
#include "Extraction.h"

#include <osg/PagedLOD>
#include <osg/ProxyNode>

#include <filesystem>
#include <map>
#include <string>

namespace osgVis
{
namespace
{
const osg::Group* asPaged(const osg::Node* node)
{
    if (const auto* paged = dynamic_cast<const osg::PagedLOD*>(node))
        return paged;
    return dynamic_cast<const osg::ProxyNode*>(node);
}

std::string databasePath(const osg::Group& node)
{
    if (const auto* paged = dynamic_cast<const osg::PagedLOD*>(&node))
        return paged->getDatabasePath();
    return static_cast<const osg::ProxyNode&>(node).getDatabasePath();
}

// The tile's file relative to the folder of the root file (the database path of the outermost paged
// node, which the root's reader set): the same key wherever the database lies and however its root
// was named when read.
std::string keyOf(const std::string& file, const std::string& rootFolder)
{
    if (rootFolder.empty())
        return file;
    const std::string relative =
        std::filesystem::path(file).lexically_relative(std::filesystem::path(rootFolder)).generic_string();
    return relative.empty() || relative.rfind("..", 0) == 0 ? file : relative;
}
} // namespace

void assignTileKeys(ExtractedScene& out)
{
    out.scene.tiles.reset();
    if (out.pagedNodes.empty())
        return;
    auto tiles = std::make_shared<core::SceneTiles>();
    tiles->complete = true;
    for (const PagedNodeRecord& record : out.pagedNodes)
        if (const osg::Group* node = out.refs[record.placeholder].paged.get())
            tiles->complete = tiles->complete && node->getNumChildren() >= pagedFileCount(*node);
    std::map<std::string, std::uint32_t> tileOfFile;
    tiles->keys.resize(out.refs.size());
    for (core::ObjectId id = 0; id < out.refs.size(); ++id)
    {
        const ObjectRef& ref = out.refs[id];
        core::TileKey& key = tiles->keys[id];
        if (!ref.node())
        {
            key.tile = core::NoTile;
            continue;
        }
        std::string rootFolder;
        for (const osg::Node* node : ref.path)
            if (const osg::Group* paged = asPaged(node))
            {
                rootFolder = databasePath(*paged);
                break;
            }
        // path.back() is the object's own node (a drawable, or a placeholder's paged node).
        for (std::size_t k = ref.path.size() - 1; k-- > 0;)
        {
            const osg::Group* paged = asPaged(ref.path[k]);
            if (!paged)
                continue;
            const unsigned child = paged->getChildIndex(ref.path[k + 1]);
            const std::string file = tileFile(*paged, child);
            if (file.empty())
                continue;
            const std::string name = keyOf(file, rootFolder);
            const core::ObjectId owner = out.find(paged, osg::NodePath(ref.path.begin(), ref.path.begin() + k + 1));
            const auto [found, added] = tileOfFile.emplace(name, std::uint32_t(tiles->files.size()));
            if (added)
            {
                tiles->files.push_back(name);
                tiles->owners.push_back(owner);
            }
            else if (tiles->owners[found->second] != owner)
                return; // one file below two nodes: no key tells their objects apart
            key.tile = found->second;
            break;
        }
    }
    core::finishSceneTiles(out.scene, *tiles);
    out.scene.tiles = std::move(tiles);
}
} // namespace osgVis
