// SPDX-License-Identifier: MIT
#include "OcclusionQueryGraph.h"

#include <osg/Geode>
#include <osg/MatrixTransform>
#include <osg/OcclusionQueryNode>

#include <map>

namespace osgVis::bench
{
namespace
{
// The state a drawable inherits from the nodes above it, as one StateSet. StateSet::merge applies
// OSG's inheritance rules (a parent's OVERRIDE wins unless the child's attribute is PROTECTED).
// Objects below the same nodes share one merged set, so state sorting sees what the original graph
// gave it.
class MergedStateCache
{
public:
    osg::StateSet* stateAbove(const osg::NodePath& path)
    {
        std::vector<const osg::StateSet*> chain;
        for (std::size_t i = 0; i + 1 < path.size(); ++i) // the drawable keeps its own state set
            if (const osg::StateSet* stateSet = path[i]->getStateSet())
                chain.push_back(stateSet);
        if (chain.empty())
            return nullptr;
        osg::ref_ptr<osg::StateSet>& merged = _merged[chain];
        if (!merged)
        {
            merged = new osg::StateSet;
            for (const osg::StateSet* stateSet : chain)
                merged->merge(*stateSet);
        }
        return merged.get();
    }

private:
    std::map<std::vector<const osg::StateSet*>, osg::ref_ptr<osg::StateSet>> _merged;
};
} // namespace

osg::ref_ptr<osg::Group> buildOcclusionQueryGraph(const ExtractedScene& scene)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->setName("osg-oq");
    MergedStateCache states;
    for (const ObjectRef& ref : scene.refs)
    {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->setStateSet(states.stateAbove(ref.path));
        geode->addDrawable(ref.drawable.get());

        osg::ref_ptr<osg::OcclusionQueryNode> query = new osg::OcclusionQueryNode;
        query->addChild(geode);

        osg::ref_ptr<osg::MatrixTransform> placement = new osg::MatrixTransform(ref.world);
        placement->addChild(query);
        root->addChild(placement);
    }
    return root;
}
} // namespace osgVis::bench
