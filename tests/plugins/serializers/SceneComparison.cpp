// SPDX-License-Identifier: MIT
#include "SceneComparison.h"

#include <osgVis/Cell>
#include <osgVis/Occluder>
#include <osgVis/Portal>
#include <osgVis/SceneExtractor>
#include <osgVis/VisibilityGroup>

#include <osg/Geometry>
#include <osg/Group>

#include <gtest/gtest.h>

namespace osgVis::test
{
namespace
{
void expectSameProperties(const osg::Node& expected, const osg::Node& actual)
{
    if (auto* group = dynamic_cast<const VisibilityGroup*>(&expected))
    {
        auto& loaded = static_cast<const VisibilityGroup&>(actual);
        EXPECT_EQ(loaded.getModes(), group->getModes());
        EXPECT_EQ(loaded.getAsync(), group->getAsync());
    }
    if (auto* occluder = dynamic_cast<const Occluder*>(&expected))
    {
        EXPECT_EQ(static_cast<const Occluder&>(actual).getPolygons(), occluder->getPolygons());
    }
    if (auto* cell = dynamic_cast<const Cell*>(&expected))
    {
        const osg::BoundingBoxd& bounds = static_cast<const Cell&>(actual).getBounds();
        EXPECT_EQ(bounds._min, cell->getBounds()._min);
        EXPECT_EQ(bounds._max, cell->getBounds()._max);
    }
    if (auto* portal = dynamic_cast<const Portal*>(&expected))
    {
        auto& loaded = static_cast<const Portal&>(actual);
        EXPECT_EQ(loaded.getPolygon(), portal->getPolygon());
        EXPECT_EQ(loaded.getCellA(), portal->getCellA());
        EXPECT_EQ(loaded.getCellB(), portal->getCellB());
    }
}

void expectSameTree(const osg::Node& expected, const osg::Node& actual)
{
    SCOPED_TRACE(expected.getName());
    ASSERT_STREQ(actual.className(), expected.className());
    ASSERT_STREQ(actual.libraryName(), expected.libraryName());
    EXPECT_EQ(actual.getName(), expected.getName());
    expectSameProperties(expected, actual);
    const osg::Group* expectedGroup = expected.asGroup();
    if (!expectedGroup)
        return;
    const osg::Group* actualGroup = actual.asGroup();
    ASSERT_NE(actualGroup, nullptr);
    ASSERT_EQ(actualGroup->getNumChildren(), expectedGroup->getNumChildren());
    for (unsigned i = 0; i < expectedGroup->getNumChildren(); ++i)
        expectSameTree(*expectedGroup->getChild(i), *actualGroup->getChild(i));
}

void expectSameExtraction(const osg::Node& expected, const osg::Node& actual)
{
    // note: extraction only reads the graph; the const_cast serves its non-const signature.
    const osg::ref_ptr<ExtractedScene> a = extractScene(const_cast<osg::Node&>(expected));
    const osg::ref_ptr<ExtractedScene> b = extractScene(const_cast<osg::Node&>(actual));
    const core::Scene& sa = a->scene;
    const core::Scene& sb = b->scene;

    ASSERT_EQ(sb.objects.size(), sa.objects.size());
    for (std::size_t i = 0; i < sa.objects.size(); ++i)
    {
        EXPECT_EQ(sb.objects[i].bounds.min, sa.objects[i].bounds.min) << "object " << i;
        EXPECT_EQ(sb.objects[i].bounds.max, sa.objects[i].bounds.max) << "object " << i;
        EXPECT_EQ(sb.objects[i].triangleCount, sa.objects[i].triangleCount) << "object " << i;
        EXPECT_EQ(sb.objects[i].flags, sa.objects[i].flags) << "object " << i;
    }
    ASSERT_EQ(sb.occluders.size(), sa.occluders.size());
    for (std::size_t i = 0; i < sa.occluders.size(); ++i)
    {
        EXPECT_EQ(sb.occluders[i].polygon.vertices(), sa.occluders[i].polygon.vertices()) << "occluder " << i;
        EXPECT_EQ(sb.occluders[i].owner, sa.occluders[i].owner) << "occluder " << i;
    }
    ASSERT_EQ(sb.cells.size(), sa.cells.size());
    for (std::size_t i = 0; i < sa.cells.size(); ++i)
    {
        EXPECT_EQ(sb.cells[i].name, sa.cells[i].name);
        EXPECT_EQ(sb.cells[i].bounds.min, sa.cells[i].bounds.min) << sa.cells[i].name;
        EXPECT_EQ(sb.cells[i].bounds.max, sa.cells[i].bounds.max) << sa.cells[i].name;
    }
    ASSERT_EQ(sb.portals.size(), sa.portals.size());
    for (std::size_t i = 0; i < sa.portals.size(); ++i)
    {
        EXPECT_EQ(sb.portals[i].polygon.vertices(), sa.portals[i].polygon.vertices()) << "portal " << i;
        EXPECT_EQ(sb.portals[i].cellA, sa.portals[i].cellA) << "portal " << i;
        EXPECT_EQ(sb.portals[i].cellB, sa.portals[i].cellB) << "portal " << i;
    }
}
} // namespace

void expectSameGraph(const osg::Node& expected, const osg::Node& actual)
{
    expectSameTree(expected, actual);
    expectSameExtraction(expected, actual);
}
} // namespace osgVis::test
