// SPDX-License-Identifier: MIT
#include "ObjectChain.h"

#include "IdColour.h"
#include "IdPassState.h"

#include <osg/MatrixTransform>
#include <osg/Uniform>

namespace osgVis::oracle
{
osg::ref_ptr<osg::Node> createObjectChain(const OracleObject& object, std::uint32_t objectIndex)
{
    osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(object.world);
    placed->getOrCreateStateSet()->addUniform(new osg::Uniform(IdUniformName, idColour(objectIndex)));
    placed->addChild(object.drawable.get());
    return underPathState(object, placed.get());
}

osg::ref_ptr<osg::Node> underPathState(const OracleObject& object, osg::Node* placed)
{
    osg::ref_ptr<osg::Node> chain = placed;
    // path.back() is the drawable itself, drawn with its own stateset
    for (std::size_t i = object.path.size() - 1; i-- > 0;)
    {
        osg::StateSet* stateSet = object.path[i]->getStateSet();
        if (!stateSet)
            continue;
        osg::ref_ptr<osg::Group> group = new osg::Group;
        group->setStateSet(stateSet);
        group->addChild(chain.get());
        chain = group;
    }
    return chain;
}
} // namespace osgVis::oracle
