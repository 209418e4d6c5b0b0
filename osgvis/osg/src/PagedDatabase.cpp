// SPDX-License-Identifier: MIT
#include <osgVis/PagedDatabase>

#include "Extraction.h"

#include <osg/NodeVisitor>
#include <osg/PagedLOD>
#include <osg/ProxyNode>
#include <osgDB/ReadFile>

#include <set>

namespace osgVis
{
namespace
{
// Paged nodes with a file still to read (in the order a depth-first walk meets them).
struct UnloadedPagedNodes : osg::NodeVisitor
{
    UnloadedPagedNodes() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::PagedLOD& node) override { visitPaged(node); }
    void apply(osg::ProxyNode& node) override { visitPaged(node); }
    void visitPaged(osg::Group& node)
    {
        if (node.getNumChildren() < pagedFileCount(node))
            found.push_back(&node);
        traverse(node);
    }
    std::vector<osg::ref_ptr<osg::Group>> found;
};
} // namespace

WholeDatabase loadWholeDatabase(osg::Node& root, const std::function<void(std::size_t)>& progress)
{
    WholeDatabase whole;
    std::set<const osg::Group*> failed; // not tried again in the next round
    for (bool added = true; added;)
    {
        added = false;
        UnloadedPagedNodes unloaded;
        root.accept(unloaded);
        for (osg::Group* node : unloaded.found)
        {
            if (failed.count(node))
                continue;
            for (unsigned child = node->getNumChildren(); child < pagedFileCount(*node); ++child)
            {
                const std::string file = tileFile(*node, child);
                osg::ref_ptr<osg::Node> tile = file.empty() ? nullptr : osgDB::readRefNodeFile(file);
                if (!tile)
                {
                    // note: a later child cannot take this one's place, so the node stops here
                    whole.unreadable.push_back(file + " ('" + node->getName() + "')");
                    failed.insert(node);
                    break;
                }
                node->addChild(tile.get());
                added = true;
                ++whole.tilesRead;
                if (progress)
                    progress(whole.tilesRead);
            }
        }
    }
    return whole;
}
} // namespace osgVis
