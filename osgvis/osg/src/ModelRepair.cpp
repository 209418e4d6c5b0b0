// SPDX-License-Identifier: MIT
#include <osgVis/ModelRepair>

#include <osg/Drawable>
#include <osg/NodeVisitor>
#include <osgDB/FileNameUtils>

namespace osgVis
{
namespace
{
class PolygonModeRemover : public osg::NodeVisitor
{
public:
    PolygonModeRemover() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    unsigned removed = 0;

    void apply(osg::Node& node) override
    {
        clean(node.getStateSet());
        traverse(node);
    }
    void apply(osg::Drawable& drawable) override { clean(drawable.getStateSet()); }

private:
    void clean(osg::StateSet* stateSet)
    {
        if (stateSet && stateSet->getAttribute(osg::StateAttribute::POLYGONMODE))
        {
            stateSet->removeAttribute(osg::StateAttribute::POLYGONMODE);
            ++removed;
        }
    }
};
} // namespace

unsigned repairLoadedModel(osg::Node& model, const std::string& path)
{
    if (osgDB::getLowerCaseFileExtension(path) != "bsp")
        return 0;
    PolygonModeRemover remover;
    model.accept(remover);
    return remover.removed;
}
} // namespace osgVis
