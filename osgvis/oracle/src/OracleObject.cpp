// SPDX-License-Identifier: MIT
#include <osgVis/oracle/OracleObject.h>

#include "EffectiveState.h"

#include <osg/NodeVisitor>
#include <osg/Transform>

namespace osgVis::oracle
{
namespace
{
// Depth-first over active children; NodeVisitor::validNodeMask already skips nodes whose mask is 0.
class ObjectEnumerator : public osg::NodeVisitor
{
public:
    explicit ObjectEnumerator(std::vector<OracleObject>& objects)
        : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN)
        , _objects(objects)
    {
    }

    using osg::NodeVisitor::apply;

    void apply(osg::Drawable& drawable) override
    {
        OracleObject object;
        object.path = getNodePath();
        object.drawable = &drawable;
        object.world = osg::computeLocalToWorld(object.path);
        object.transparent = drawsWithoutOccluding(object.path);
        _objects.push_back(std::move(object));
    }

private:
    std::vector<OracleObject>& _objects;
};
} // namespace

std::vector<OracleObject> enumerateObjects(osg::Node& root)
{
    std::vector<OracleObject> objects;
    ObjectEnumerator enumerator(objects);
    root.accept(enumerator);
    return objects;
}
} // namespace osgVis::oracle
