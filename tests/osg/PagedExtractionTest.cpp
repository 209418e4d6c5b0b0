// SPDX-License-Identifier: MIT
// Paged nodes in the extraction (docs/paging.md): each osg::PagedLOD and osg::ProxyNode is a
// placeholder object with the box of its stated bound; where that bound does not hold the tiles
// to come, or a loaded tile reaches outside it, the placeholder is always visible; a merge or an
// expiry shows as a changed child count and re-extracts with stable ids.
#include "TestScenes.h"

#include <osgVis/SceneExtractor>

#include <osg/Geode>
#include <osg/Notify>
#include <osg/PagedLOD>
#include <osg/ProxyNode>

#include <gtest/gtest.h>

#include <string>

using osgVis::test::makeBox;

namespace
{
osg::ref_ptr<osg::Geode> boxGeode(const osg::Vec3& lo, const osg::Vec3& hi)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(makeBox(lo, hi));
    return geode;
}

osg::ref_ptr<osg::PagedLOD> statedTile(const std::string& file, const osg::Vec3& centre, float radius)
{
    osg::ref_ptr<osg::PagedLOD> paged = new osg::PagedLOD;
    paged->setName(file);
    paged->setCenterMode(osg::LOD::USER_DEFINED_CENTER);
    paged->setCenter(centre);
    paged->setRadius(radius);
    paged->setFileName(0, file);
    paged->setRange(0, 0.0f, 1e30f);
    return paged;
}

// Collects warnings while alive (osg::setNotifyHandler), restoring the previous handler after.
struct WarningCapture : public osg::NotifyHandler
{
    std::string text;
    void notify(osg::NotifySeverity severity, const char* message) override
    {
        if (severity <= osg::WARN)
            text += message;
    }
};

class CapturedWarnings
{
public:
    CapturedWarnings() : _previous(osg::getNotifyHandler()), _capture(new WarningCapture)
    {
        osg::setNotifyLevel(osg::WARN);
        osg::setNotifyHandler(_capture.get());
    }
    ~CapturedWarnings() { osg::setNotifyHandler(_previous.get()); }
    const std::string& text() const { return _capture->text; }

private:
    osg::ref_ptr<osg::NotifyHandler> _previous;
    osg::ref_ptr<WarningCapture> _capture;
};
} // namespace

TEST(PagedExtraction, UnloadedTileIsAPlaceholderWithTheBoxOfItsStatedBound)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(boxGeode({0, 0, 0}, {1, 1, 1}));
    osg::ref_ptr<osg::PagedLOD> tile = statedTile("a.osgb", {10, 20, 3}, 2.0f);
    root->addChild(tile);

    osg::ref_ptr<osgVis::ExtractedScene> scene = osgVis::extractScene(*root);
    ASSERT_EQ(scene->scene.objects.size(), 2u);
    const osgVis::core::ObjectId id = scene->find(tile.get(), osg::NodePath{root.get(), tile.get()});
    ASSERT_EQ(id, 1u);
    EXPECT_TRUE(scene->placeholder(id));
    EXPECT_FALSE(scene->removed(id));
    const osgVis::core::SceneObject& object = scene->scene.objects[id];
    EXPECT_EQ(object.triangleCount, 0u);
    EXPECT_EQ(object.flags, osgVis::core::OBJECT_NONE);
    EXPECT_EQ(object.bounds.min, osgVis::core::Vec3(8, 18, 1));
    EXPECT_EQ(object.bounds.max, osgVis::core::Vec3(12, 22, 5));
    ASSERT_EQ(scene->pagedNodes.size(), 1u);
    EXPECT_EQ(scene->pagedNodes[0].placeholder, id);
    EXPECT_EQ(scene->pagedNodes[0].children, 0u);
    EXPECT_FALSE(scene->pagedNodesChanged());
}

TEST(PagedExtraction, BoundFromLoadedChildrenOnlyIsNoBoundForTheTilesToCome)
{
    // A bound from the loaded children (a PagedLOD's default: no radius stated) says nothing of
    // where the next tile lies, and a node with none loaded has no bound at all.
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::PagedLOD> partly = new osg::PagedLOD;
    partly->addChild(boxGeode({0, 0, 0}, {1, 1, 1}), 0.0f, 100.0f, "");
    partly->setFileName(1, "finer.osgb");
    partly->setRange(1, 0.0f, 10.0f);
    root->addChild(partly);
    osg::ref_ptr<osg::ProxyNode> proxy = new osg::ProxyNode;
    proxy->setFileName(0, "proxied.osgb");
    root->addChild(proxy);

    osg::ref_ptr<osgVis::ExtractedScene> scene = osgVis::extractScene(*root);
    ASSERT_EQ(scene->scene.objects.size(), 3u); // placeholder, its loaded box, the proxy's placeholder
    EXPECT_TRUE(scene->placeholder(0));
    EXPECT_FALSE(scene->placeholder(1));
    EXPECT_TRUE(scene->placeholder(2));
    EXPECT_TRUE(scene->scene.objects[0].flags & osgVis::core::OBJECT_ALWAYS_VISIBLE);
    EXPECT_FALSE(scene->scene.objects[1].flags & osgVis::core::OBJECT_ALWAYS_VISIBLE);
    EXPECT_TRUE(scene->scene.objects[2].flags & osgVis::core::OBJECT_ALWAYS_VISIBLE);
}

TEST(PagedExtraction, TileReachingOutsideItsStatedBoundIsAlwaysVisibleAndNamedOnce)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::PagedLOD> fits = statedTile("fits.osgb", {0.5f, 0.5f, 0.5f}, 1.0f);
    fits->addChild(boxGeode({0, 0, 0}, {1, 1, 1}));
    osg::ref_ptr<osg::PagedLOD> big = statedTile("big.osgb", {10.5f, 0.5f, 0.5f}, 0.5f);
    big->setDatabasePath("tiles/");
    big->addChild(boxGeode({10, 0, 0}, {11, 1, 3}));
    root->addChild(fits);
    root->addChild(big);

    osg::ref_ptr<osgVis::ExtractedScene> scene;
    {
        CapturedWarnings warnings;
        scene = osgVis::extractScene(*root);
        EXPECT_NE(warnings.text().find("tile tiles/big.osgb ('big.osgb') reaches outside the bound"),
                  std::string::npos)
            << warnings.text();
        EXPECT_EQ(warnings.text().find("fits.osgb"), std::string::npos) << warnings.text();
    }
    const osgVis::core::ObjectId fitsId = scene->find(fits.get(), osg::NodePath{root.get(), fits.get()});
    const osgVis::core::ObjectId bigId = scene->find(big.get(), osg::NodePath{root.get(), big.get()});
    EXPECT_EQ(scene->scene.objects[fitsId].flags & osgVis::core::OBJECT_ALWAYS_VISIBLE, 0u);
    EXPECT_NE(scene->scene.objects[bigId].flags & osgVis::core::OBJECT_ALWAYS_VISIBLE, 0u);
    ASSERT_EQ(scene->oversizedTiles.size(), 1u);

    // Extracted again (a merge elsewhere), the same tile is not warned about again.
    CapturedWarnings again;
    osg::ref_ptr<osgVis::ExtractedScene> next = osgVis::reextractScene(*root, *scene);
    EXPECT_EQ(again.text(), "");
    EXPECT_NE(next->scene.objects[bigId].flags & osgVis::core::OBJECT_ALWAYS_VISIBLE, 0u);
}

TEST(PagedExtraction, MergedAndExpiredTilesShowAsChildCountsAndKeepIds)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(boxGeode({0, 0, 0}, {1, 1, 1}));
    osg::ref_ptr<osg::PagedLOD> tile = statedTile("t.osgb", {5, 5, 5}, 3.0f);
    root->addChild(tile);
    osg::ref_ptr<osgVis::ExtractedScene> first = osgVis::extractScene(*root);
    ASSERT_EQ(first->scene.objects.size(), 2u);

    // What DatabasePager::updateSceneGraph does on a merge.
    osg::ref_ptr<osg::Geode> loaded = boxGeode({4, 4, 4}, {6, 6, 6});
    tile->addChild(loaded);
    EXPECT_TRUE(first->pagedNodesChanged());
    osg::ref_ptr<osgVis::ExtractedScene> merged = osgVis::reextractScene(*root, *first);
    EXPECT_FALSE(merged->pagedNodesChanged());
    ASSERT_EQ(merged->replaces, first.get());
    ASSERT_EQ(merged->scene.objects.size(), 3u);
    EXPECT_EQ(merged->find(tile.get(), osg::NodePath{root.get(), tile.get()}), 1u); // the placeholder kept its id
    const osg::Drawable* drawable = loaded->getDrawable(0);
    const osgVis::core::ObjectId tileObject =
        merged->find(drawable, osg::NodePath{root.get(), tile.get(), loaded.get(), loaded->getDrawable(0)});
    EXPECT_EQ(tileObject, 2u);
    ASSERT_EQ(merged->changes.size(), 1u);
    EXPECT_EQ(merged->changes[0].kind, osgVis::core::SceneChange::Kind::Inserted);
    EXPECT_EQ(merged->changes[0].objects, std::vector<osgVis::core::ObjectId>{2});
    EXPECT_EQ(merged->pagedNodes[0].children, 1u);

    // What PagedLOD::removeExpiredChildren does on an expiry.
    tile->removeChildren(0, 1);
    EXPECT_TRUE(merged->pagedNodesChanged());
    osg::ref_ptr<osgVis::ExtractedScene> expired = osgVis::reextractScene(*root, *merged);
    EXPECT_TRUE(expired->removed(2));
    EXPECT_FALSE(expired->removed(1));
    ASSERT_EQ(expired->changes.size(), 1u);
    EXPECT_EQ(expired->changes[0].kind, osgVis::core::SceneChange::Kind::Removed);
    EXPECT_EQ(expired->changes[0].objects, std::vector<osgVis::core::ObjectId>{2});
}
