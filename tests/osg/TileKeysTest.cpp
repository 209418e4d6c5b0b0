// SPDX-License-Identifier: MIT
// Tile keys (docs/paging.md, "Baked visibility for a paged database"): every extraction of a
// paged scene names each object's tile by file and rank, so a scene with tiles loaded in any order,
// merged and expired through updatePagedScene or reextractScene, maps onto the whole database's
// objects; loadWholeDatabase reads every tile a bake needs.
#include "TestScenes.h"

#include <osgVis/PagedDatabase>
#include <osgVis/SceneExtractor>

#include <osg/Geode>
#include <osg/PagedLOD>
#include <osg/ProxyNode>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

using osgVis::test::makeBox;
namespace core = osgVis::core;

namespace
{
osg::ref_ptr<osg::Geode> boxes(const osg::Vec3& at, int count)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    for (int i = 0; i < count; ++i)
        geode->addDrawable(makeBox(at + osg::Vec3(float(i), 0, 0), at + osg::Vec3(float(i) + 0.5f, 1, 1)));
    return geode;
}

osg::ref_ptr<osg::PagedLOD> pagedNode(const std::string& file, const osg::Vec3& centre)
{
    osg::ref_ptr<osg::PagedLOD> paged = new osg::PagedLOD;
    paged->setName(file);
    paged->setCenterMode(osg::LOD::USER_DEFINED_CENTER);
    paged->setCenter(centre);
    paged->setRadius(20.0f);
    paged->setFileName(0, file);
    paged->setRange(0, 0.0f, 1e30f);
    return paged;
}

// A root with a box of its own and three paged tiles a, b, c; b holds a nested paged tile n. The
// tiles' contents are made by tileContent(file), so two databases built apart are alike.
struct Database
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    std::map<std::string, osg::ref_ptr<osg::PagedLOD>> nodes;

    Database()
    {
        root->addChild(boxes({0, -5, 0}, 1));
        for (const char* file : {"a.osgb", "b.osgb", "c.osgb"})
        {
            nodes[file] = pagedNode(file, {float(10 * nodes.size()), 0, 0});
            root->addChild(nodes[file]);
        }
        nodes["n.osgb"] = pagedNode("n.osgb", {10, 0, 0});
    }
    osg::ref_ptr<osg::Node> content(const std::string& file) const
    {
        osg::ref_ptr<osg::Group> tile = new osg::Group;
        const float x = file == "n.osgb" ? 12.0f : 10.0f * float(file[0] - 'a');
        tile->addChild(boxes({x, 0, 0}, file == "n.osgb" ? 1 : 2));
        if (file == "b.osgb")
            tile->addChild(nodes.at("n.osgb"));
        return tile;
    }
    void load(const std::string& file) { nodes[file]->addChild(content(file)); }
};

core::Vec3 centreOf(const core::Scene& scene, core::ObjectId id) { return scene.objects[id].bounds.center(); }
} // namespace

TEST(TileKeys, AnyLoadOrderMapsOntoTheWholeDatabase)
{
    Database whole;
    for (const char* file : {"a.osgb", "b.osgb", "n.osgb", "c.osgb"})
        whole.load(file);
    const osg::ref_ptr<osgVis::ExtractedScene> all = osgVis::extractScene(*whole.root);
    ASSERT_TRUE(all->scene.tiles);
    const core::SceneTiles& baked = *all->scene.tiles;
    EXPECT_TRUE(baked.complete);
    EXPECT_EQ(baked.files, (std::vector<std::string>{"a.osgb", "b.osgb", "n.osgb", "c.osgb"}));
    // n's placeholder belongs to b's tile, and owns n.
    const core::ObjectId nPlaceholder = all->idsOf(whole.nodes["n.osgb"].get()).at(0);
    EXPECT_EQ(baked.keys[nPlaceholder].tile, 1u);
    EXPECT_EQ(baked.owners[2], nPlaceholder);
    EXPECT_EQ(baked.keys[0].tile, core::RootTile);

    // Loaded the other way round, merge by merge, then c expired.
    Database part;
    osg::ref_ptr<osgVis::ExtractedScene> scene = osgVis::extractScene(*part.root);
    ASSERT_TRUE(scene->scene.tiles);
    EXPECT_FALSE(scene->scene.tiles->complete);
    for (const char* file : {"c.osgb", "b.osgb", "n.osgb"})
    {
        part.load(file);
        scene = osgVis::updatePagedScene(*scene);
        ASSERT_TRUE(scene);
    }
    part.nodes["c.osgb"]->removeChildren(0, 1);
    scene = osgVis::reextractScene(*part.root, *scene);
    ASSERT_TRUE(scene->scene.tiles);
    std::vector<core::ObjectId> bakedOf;
    std::string why;
    ASSERT_TRUE(core::mapToBakedObjects(baked, *scene->scene.tiles, bakedOf, why)) << why;
    std::size_t live = 0;
    for (core::ObjectId id = 0; id < scene->scene.objects.size(); ++id)
    {
        if (scene->removed(id))
        {
            EXPECT_EQ(scene->scene.tiles->keys[id].tile, core::NoTile);
            EXPECT_EQ(bakedOf[id], core::InvalidObject);
            continue;
        }
        ++live;
        ASSERT_NE(bakedOf[id], core::InvalidObject);
        EXPECT_EQ(centreOf(scene->scene, id), centreOf(all->scene, bakedOf[id])) << "object " << id;
        EXPECT_EQ(scene->refs[id].node()->getName(), all->refs[bakedOf[id]].node()->getName());
    }
    EXPECT_EQ(live, 1u + 4u + 2u + 1u); // root box, placeholders, b's boxes, n's box

    // A tile whose content differs from the bake's is named.
    Database edited;
    edited.nodes["a.osgb"]->addChild(boxes({0, 0, 0}, 3));
    const osg::ref_ptr<osgVis::ExtractedScene> other = osgVis::extractScene(*edited.root);
    EXPECT_FALSE(core::mapToBakedObjects(baked, *other->scene.tiles, bakedOf, why));
    EXPECT_EQ(why, "tile 'a.osgb' differs from the one baked");
}

TEST(TileKeys, InlineChildrenBelongToTheirNodesFileAndRepeatedFilesGetNoKeys)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::PagedLOD> paged = pagedNode("fine.osgb", {0, 0, 0});
    paged->setFileName(0, ""); // child 0: a coarse level inline in this file
    paged->setRange(0, 100.0f, 1e30f);
    paged->setFileName(1, "fine.osgb");
    paged->setRange(1, 0.0f, 100.0f);
    paged->addChild(boxes({0, 0, 0}, 1));
    root->addChild(paged);
    const osg::ref_ptr<osgVis::ExtractedScene> coarse = osgVis::extractScene(*root);
    ASSERT_TRUE(coarse->scene.tiles);
    EXPECT_FALSE(coarse->scene.tiles->complete);
    EXPECT_TRUE(coarse->scene.tiles->files.empty());
    for (const core::TileKey& key : coarse->scene.tiles->keys)
        EXPECT_EQ(key.tile, core::RootTile);

    osg::ref_ptr<osg::Group> twice = new osg::Group;
    for (float x : {0.0f, 50.0f})
    {
        osg::ref_ptr<osg::PagedLOD> node = pagedNode("same.osgb", {x, 0, 0});
        node->addChild(boxes({x, 0, 0}, 1));
        twice->addChild(node);
    }
    EXPECT_FALSE(osgVis::extractScene(*twice)->scene.tiles);
}

TEST(TileKeys, LoadWholeDatabaseReadsNestedTilesAndNamesTheUnreadable)
{
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("osgvis-tile-keys-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    Database db;
    for (const char* file : {"a.osgb", "b.osgb", "n.osgb"})
        ASSERT_TRUE(osgDB::writeNodeFile(*db.content(file), (dir / file).string()));
    // c.osgb is never written; b's copy on disk holds n unloaded.
    ASSERT_TRUE(osgDB::writeNodeFile(*db.root, (dir / "root.osgb").string()));
    osg::ref_ptr<osg::Node> root = osgDB::readRefNodeFile((dir / "root.osgb").string());
    ASSERT_TRUE(root.valid());
    std::vector<std::size_t> progress;
    const osgVis::WholeDatabase whole = osgVis::loadWholeDatabase(*root, [&](std::size_t n) { progress.push_back(n); });
    EXPECT_EQ(whole.tilesRead, 3u);
    EXPECT_EQ(progress, (std::vector<std::size_t>{1, 2, 3}));
    ASSERT_EQ(whole.unreadable.size(), 1u);
    EXPECT_NE(whole.unreadable[0].find("c.osgb ('c.osgb')"), std::string::npos) << whole.unreadable[0];
    const osg::ref_ptr<osgVis::ExtractedScene> scene = osgVis::extractScene(*root);
    ASSERT_TRUE(scene->scene.tiles);
    EXPECT_FALSE(scene->scene.tiles->complete); // c is missing
    EXPECT_EQ(scene->scene.tiles->files.size(), 3u);
    std::filesystem::remove_all(dir);
}
