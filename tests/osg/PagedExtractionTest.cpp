// SPDX-License-Identifier: MIT
// Paged nodes in the extraction (docs/paging.md): each osg::PagedLOD and osg::ProxyNode is a
// placeholder object with the box of its stated bound; where that bound does not hold the tiles
// to come, or a loaded tile reaches outside it, the placeholder is always visible; a merge or an
// expiry shows as a changed child count and re-extracts with stable ids.
#include "TestScenes.h"

#include <osgVis/Occluder>
#include <osgVis/SceneExtractor>
#include <osgVis/VisibilityGroup>

#include <osgVis/gen/Generator.h>
#include <osgVis/gen/PagedScene.h>

#include <osg/Geode>
#include <osg/Notify>
#include <osg/PagedLOD>
#include <osg/ProxyNode>

#include <osg/ValueObject>
#include <osgDB/ReadFile>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

#include <map>
#include <string>
#include <tuple>

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

namespace
{
// Live objects by (node, path) with their bounds, triangle count and flags: what two extractions
// of the same graph must agree on, whatever their ids.
std::map<std::pair<const osg::Node*, osg::NodePath>, std::tuple<osgVis::core::Vec3, osgVis::core::Vec3, unsigned, unsigned>>
liveObjects(const osgVis::ExtractedScene& scene)
{
    std::map<std::pair<const osg::Node*, osg::NodePath>,
             std::tuple<osgVis::core::Vec3, osgVis::core::Vec3, unsigned, unsigned>>
        out;
    for (const osgVis::core::SceneObject& object : scene.scene.objects)
        if (!scene.removed(object.id))
            out[{scene.refs[object.id].node(), scene.refs[object.id].path}] = {object.bounds.min, object.bounds.max,
                                                                               object.triangleCount, object.flags};
    return out;
}
} // namespace

TEST(PagedExtraction, UpdateExtractsOnlyTheChangedTilesAndAgreesWithAFullExtraction)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(boxGeode({0, 0, 0}, {1, 1, 1}));
    osg::ref_ptr<osg::Group> district = new osg::Group; // paged nodes one level down
    root->addChild(district);
    osg::ref_ptr<osg::PagedLOD> a = statedTile("a.osgb", {5, 5, 5}, 3.0f);
    osg::ref_ptr<osg::PagedLOD> b = statedTile("b.osgb", {15, 5, 5}, 3.0f);
    district->addChild(a);
    district->addChild(b);
    osg::ref_ptr<osgVis::ExtractedScene> first = osgVis::extractScene(*root);
    ASSERT_EQ(first->scene.objects.size(), 3u);

    // Tile a merges, holding a box and a paged node of its own.
    osg::ref_ptr<osg::Group> tileA = new osg::Group;
    tileA->addChild(boxGeode({4, 4, 4}, {6, 6, 6}));
    osg::ref_ptr<osg::PagedLOD> nested = statedTile("a1.osgb", {5, 5, 7}, 1.0f);
    tileA->addChild(nested);
    a->addChild(tileA);
    osg::ref_ptr<osgVis::ExtractedScene> merged = osgVis::updatePagedScene(*first);
    ASSERT_TRUE(merged);
    EXPECT_EQ(merged->replaces, first.get());
    ASSERT_EQ(merged->scene.objects.size(), 5u);
    ASSERT_EQ(merged->changes.size(), 1u);
    EXPECT_EQ(merged->changes[0].kind, osgVis::core::SceneChange::Kind::Inserted);
    EXPECT_EQ(merged->changes[0].objects, (std::vector<osgVis::core::ObjectId>{3, 4}));
    EXPECT_TRUE(merged->placeholder(4));
    EXPECT_EQ(merged->pagedNodes.size(), 3u);
    EXPECT_FALSE(merged->pagedNodesChanged());
    EXPECT_EQ(liveObjects(*merged), liveObjects(*osgVis::extractScene(*root)));
    EXPECT_EQ(merged->childRanges[1].ids, (std::vector<osgVis::core::ObjectId>{1, 2, 3, 4}));

    // The nested tile merges, then tile a expires with everything below it; b merges meanwhile.
    nested->addChild(boxGeode({4.5f, 4.5f, 6.5f}, {5.5f, 5.5f, 7.5f}));
    osg::ref_ptr<osgVis::ExtractedScene> deeper = osgVis::updatePagedScene(*merged);
    ASSERT_TRUE(deeper);
    EXPECT_EQ(deeper->scene.objects.size(), 6u);
    EXPECT_EQ(liveObjects(*deeper), liveObjects(*osgVis::extractScene(*root)));
    a->removeChildren(0, 1);
    b->addChild(boxGeode({14, 4, 4}, {16, 6, 6}));
    osg::ref_ptr<osgVis::ExtractedScene> expired = osgVis::updatePagedScene(*deeper);
    ASSERT_TRUE(expired);
    ASSERT_EQ(expired->changes.size(), 2u);
    EXPECT_EQ(expired->changes[0].kind, osgVis::core::SceneChange::Kind::Removed);
    EXPECT_EQ(expired->changes[0].objects, (std::vector<osgVis::core::ObjectId>{3, 4, 5}));
    EXPECT_EQ(expired->changes[1].kind, osgVis::core::SceneChange::Kind::Inserted);
    EXPECT_EQ(expired->changes[1].objects, (std::vector<osgVis::core::ObjectId>{6}));
    EXPECT_EQ(expired->pagedNodes.size(), 2u); // the nested node went with its tile
    EXPECT_EQ(liveObjects(*expired), liveObjects(*osgVis::extractScene(*root)));
    EXPECT_EQ(expired->childRanges[1].ids, (std::vector<osgVis::core::ObjectId>{1, 2, 6}));
    EXPECT_EQ(expired->find(a.get(), osg::NodePath{root.get(), district.get(), a.get()}), 1u);
}

TEST(PagedExtraction, UpdateFallsBackWhereOnlyAFullExtractionIsRight)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::PagedLOD> fromChildren = new osg::PagedLOD; // no stated radius
    fromChildren->setFileName(0, "c.osgb");
    root->addChild(fromChildren);
    osg::ref_ptr<osgVis::ExtractedScene> first = osgVis::extractScene(*root);
    fromChildren->addChild(boxGeode({0, 0, 0}, {1, 1, 1}));
    EXPECT_FALSE(osgVis::updatePagedScene(*first)); // its placeholder's box would change

    // A tile holding a stand-alone occluder.
    osg::ref_ptr<osg::Group> other = new osg::Group;
    osg::ref_ptr<osg::PagedLOD> tile = statedTile("o.osgb", {0, 0, 0}, 5.0f);
    other->addChild(tile);
    osg::ref_ptr<osgVis::ExtractedScene> before = osgVis::extractScene(*other);
    osg::ref_ptr<osgVis::Occluder> occluder = new osgVis::Occluder;
    occluder->addPolygon({{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}});
    tile->addChild(occluder);
    EXPECT_FALSE(osgVis::updatePagedScene(*before));
}

TEST(PagedExtraction, UpdateWarnsAboutAMergedTileOutsideItsBound)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::PagedLOD> tile = statedTile("wide.osgb", {0, 0, 0}, 1.0f);
    root->addChild(tile);
    osg::ref_ptr<osgVis::ExtractedScene> first = osgVis::extractScene(*root);
    EXPECT_EQ(first->scene.objects[0].flags, osgVis::core::OBJECT_NONE);
    tile->addChild(boxGeode({-3, 0, 0}, {3, 1, 1}));
    CapturedWarnings warnings;
    osg::ref_ptr<osgVis::ExtractedScene> merged = osgVis::updatePagedScene(*first);
    ASSERT_TRUE(merged);
    EXPECT_NE(merged->scene.objects[0].flags & osgVis::core::OBJECT_ALWAYS_VISIBLE, 0u);
    EXPECT_NE(warnings.text().find("tile wide.osgb ('wide.osgb') reaches outside"), std::string::npos)
        << warnings.text();
}

TEST(PagedExtraction, GeneratedTilesStateATighterBoxThanTheirSphere)
{
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("osgvis-paged-gen-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    osgVis::gen::GenerateOptions generate;
    generate.kind = osgVis::gen::SceneKind::City;
    generate.triangles = 20000;
    osgVis::gen::PagedOptions paging;
    paging.tiles = 16;
    const osgVis::gen::PagedSummary summary =
        osgVis::gen::writePagedScene(*osgVis::gen::generate(generate).root, dir.string(), paging);
    osg::ref_ptr<osg::Node> root = osgDB::readRefNodeFile(summary.rootPath);
    ASSERT_TRUE(root.valid());
    osg::ref_ptr<osgVis::ExtractedScene> unloaded = osgVis::extractScene(*root);
    ASSERT_EQ(unloaded->pagedNodes.size(), summary.tiles);
    double boxVolume = 0, sphereVolume = 0;
    for (const osgVis::PagedNodeRecord& record : unloaded->pagedNodes)
    {
        auto* paged = static_cast<osg::PagedLOD*>(unloaded->refs[record.placeholder].paged.get());
        osg::Vec3d lo, hi;
        ASSERT_TRUE(paged->getUserValue(osgVis::PagedBoundsMin, lo));
        ASSERT_TRUE(paged->getUserValue(osgVis::PagedBoundsMax, hi));
        const osgVis::core::SceneObject& placeholder = unloaded->scene.objects[record.placeholder];
        EXPECT_EQ(placeholder.flags, osgVis::core::OBJECT_NONE);
        const osgVis::core::Vec3 extent = placeholder.bounds.extent();
        boxVolume += extent.x * extent.y * extent.z;
        sphereVolume += std::pow(2.0 * paged->getRadius(), 3.0);
        // Loaded, every tile lies within its box: none is flagged.
        paged->addChild(osgDB::readRefNodeFile(paged->getDatabasePath() + paged->getFileName(0)));
    }
    EXPECT_LT(boxVolume, 0.5 * sphereVolume);
    CapturedWarnings warnings;
    osg::ref_ptr<osgVis::ExtractedScene> loaded = osgVis::updatePagedScene(*unloaded);
    ASSERT_TRUE(loaded);
    EXPECT_TRUE(loaded->oversizedTiles.empty());
    EXPECT_EQ(warnings.text(), "");
    for (const osgVis::PagedNodeRecord& record : loaded->pagedNodes)
        EXPECT_EQ(loaded->scene.objects[record.placeholder].flags, osgVis::core::OBJECT_NONE);

    // DIR/culled.osgt: the database under a VisibilityGroup, read through osgVis's serializers
    // (OSG_LIBRARY_PATH, as stock osgviewer would find them).
    osg::ref_ptr<osg::Node> culled = osgDB::readRefNodeFile(summary.culledPath);
    auto* group = dynamic_cast<osgVis::VisibilityGroup*>(culled.get());
    ASSERT_TRUE(group) << summary.culledPath;
    EXPECT_EQ(group->getModes(), "octree");
    ASSERT_EQ(group->getNumChildren(), 1u);
    auto* proxy = dynamic_cast<osg::ProxyNode*>(group->getChild(0));
    ASSERT_TRUE(proxy);
    ASSERT_EQ(proxy->getNumChildren(), 1u); // root.osgb, loaded with it
    EXPECT_EQ(proxy->getChild(0)->asGroup()->getNumChildren(), summary.tiles);
    std::filesystem::remove_all(dir);
}
