// SPDX-License-Identifier: MIT
// osgdb_pvs through osgDB, as an application uses it: write x.pvs (bake + model beside), read it
// back as a trusted cell-portal group, and every way the pair can go wrong; version 1 files are
// checked by the fingerprint they have.
#include "PagedOffice.h"
#include "PvsSample.h"

#include <osgVis/PagedDatabase>
#include <osgVis/SceneExtractor>
#include <osgVis/VisibilityGroup>
#include <osgVis/core/cellportal/CellPortalBake.h>
#include <osgVis/core/cellportal/CellPortalModule.h>
#include <osgVis/core/multifocal/MultifocalModule.h>
#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/core/scene/SceneFingerprint.h>
#include <osgVis/gen/Generator.h>
#include <osgVis/gen/PagedScene.h>

#include <osg/Geode>
#include <osg/Geometry>

#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace
{
osg::ref_ptr<osg::Group> makeOffice(std::uint32_t seed)
{
    osgVis::gen::GenerateOptions options;
    options.kind = osgVis::gen::SceneKind::Office;
    options.triangles = 2000;
    options.seed = seed;
    return osgVis::gen::generate(options).root;
}

//   z
//   4 +---+---+---+---+      a wall in the plane y = 0, a 4 x 4 grid of quads drawn as 32 separate
//     |   |   |   |   |      triangles, and a box behind it (y 2..3). The hole: the two triangles of
//   2 +---+---+---+---+      quad (1, 1) (marked #) collapse onto its corner, so the wall keeps its
//     |   |###|   |   |      bounds, triangle count and state: only the geometry fingerprint sees it.
//   0 +---+---+---+---+ x
//     0   1   2   3   4
osg::ref_ptr<osg::Group> makeWallAndBox(bool withHole)
{
    osg::ref_ptr<osg::Vec3Array> wall = new osg::Vec3Array;
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k)
        {
            const bool hole = withHole && i == 1 && k == 1;
            const auto at = [&](int di, int dk)
            { return hole ? osg::Vec3(float(i), 0, float(k)) : osg::Vec3(float(i + di), 0, float(k + dk)); };
            for (const osg::Vec3& v : {at(0, 0), at(1, 0), at(1, 1), at(0, 0), at(1, 1), at(0, 1)})
                wall->push_back(v);
        }
    osg::ref_ptr<osg::Vec3Array> box = new osg::Vec3Array;
    const osg::Vec3 lo(1, 2, 1), hi(2, 3, 2);
    for (int face = 0; face < 6; ++face)
    {
        // Two triangles per face of the box [lo, hi]; winding does not matter to these tests.
        const int axis = face / 2;
        const float side = face % 2 ? hi[axis] : lo[axis];
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const auto corner = [&](bool du, bool dv)
        {
            osg::Vec3 p;
            p[axis] = side;
            p[u] = du ? hi[u] : lo[u];
            p[v] = dv ? hi[v] : lo[v];
            return p;
        };
        for (const osg::Vec3& p : {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 0), corner(1, 1), corner(0, 1)})
            box->push_back(p);
    }
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    for (osg::Vec3Array* vertices : {wall.get(), box.get()})
    {
        osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
        geometry->setVertexArray(vertices);
        geometry->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, GLsizei(vertices->size())));
        geode->addDrawable(geometry);
    }
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(geode);
    return root;
}

class PvsPlugin : public testing::Test
{
protected:
    void SetUp() override
    {
        osgDB::FilePathList& paths = osgDB::Registry::instance()->getLibraryFilePathList();
        if (paths.empty() || paths.front() != OSGVIS_PLUGIN_OUTPUT_DIR)
            paths.push_front(OSGVIS_PLUGIN_OUTPUT_DIR);
        const testing::TestInfo* test = testing::UnitTest::GetInstance()->current_test_info();
        _dir = fs::temp_directory_path() / (std::string("osgvis-pvs-plugin-") + test->name());
        fs::remove_all(_dir);
        fs::create_directories(_dir);
    }
    void TearDown() override { fs::remove_all(_dir); }

    std::string path(const std::string& name) const { return (_dir / name).string(); }

    // Writes the office (seed 1) as x.pvs + x.osgb.
    void writeOffice()
    {
        ASSERT_TRUE(osgDB::writeNodeFile(*makeOffice(1), path("x.pvs")));
        ASSERT_TRUE(fs::exists(path("x.pvs")));
        ASSERT_TRUE(fs::exists(path("x.osgb")));
    }

    static osg::ref_ptr<osgVis::VisibilityGroup> readGroup(const std::string& file)
    {
        osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(file);
        return dynamic_cast<osgVis::VisibilityGroup*>(node.get());
    }

    static std::string description(const osg::Node& node)
    {
        const osg::Node::DescriptionList& list = node.getDescriptions();
        return list.size() == 1 ? list.front() : "(" + std::to_string(list.size()) + " descriptions)";
    }

    static void truncateToHalf(const std::string& file) { fs::resize_file(file, fs::file_size(file) / 2); }

    // Reads `file` and expects the model under frustum culling, untrusted for a reason starting with `reason`.
    static osg::ref_ptr<osgVis::VisibilityGroup> readUntrusted(const std::string& file, const std::string& reason)
    {
        osg::ref_ptr<osgVis::VisibilityGroup> group = readGroup(file);
        EXPECT_TRUE(group.valid());
        if (!group)
            return group;
        EXPECT_EQ(group->getModes(), "frustum");
        EXPECT_EQ(group->getNumChildren(), 1u);
        EXPECT_EQ(description(*group).rfind("osgVis:pvs-untrusted: " + reason, 0), 0u) << description(*group);
        return group;
    }

    fs::path _dir;
};
} // namespace

TEST_F(PvsPlugin, WrittenPvsReadsAsTrustedCellPortalGroup)
{
    writeOffice();
    const osgVis::core::PvsFile pvs = osgVis::core::readPvsFile(path("x.pvs"));
    EXPECT_EQ(pvs.modelPath, "x.osgb"); // relative to the .pvs's folder
    EXPECT_GT(pvs.data.graph.cells.size(), 1u);

    const osg::ref_ptr<osgVis::VisibilityGroup> group = readGroup(path("x.pvs"));
    ASSERT_TRUE(group.valid());
    EXPECT_EQ(group->getModes(), "cellportal");
    EXPECT_EQ(description(*group), "osgVis:pvs-trusted");
    EXPECT_EQ(group->getName(), "x.pvs");
    ASSERT_EQ(group->getNumChildren(), 1u);

    // The group holds the data, baked for the model as read.
    const auto extracted = osgVis::extractScene(*group->getChild(0));
    EXPECT_EQ(osgVis::core::sceneFingerprint(extracted->scene), pvs.data.fingerprint);
    ASSERT_TRUE(group->getBakedData());
    const auto registered = group->getBakedData()->get<osgVis::core::CellPortalData>();
    ASSERT_TRUE(registered);
    EXPECT_FALSE(group->getBakedData()->get<osgVis::core::BakedViewCells>());
    EXPECT_EQ(registered->graph.cells.size(), pvs.data.graph.cells.size());
    EXPECT_EQ(registered->objectCount, extracted->scene.objects.size());
}

TEST_F(PvsPlugin, ReplacedModelIsShownWithFrustumOnly)
{
    writeOffice();
    ASSERT_TRUE(osgDB::writeNodeFile(*makeOffice(2), path("x.osgb")));
    readUntrusted(path("x.pvs"), "baked for another model (geometry fingerprint 0x");
}

// A range file of a split cell-portal bake holds empty placeholders for the other sources: used as
// visibility they would cull everything seen from those cells.
TEST_F(PvsPlugin, CellPortalRangeFileIsShownWithFrustumOnly)
{
    writeOffice();
    osgVis::core::PvsFile pvs = osgVis::core::readPvsFile(path("x.pvs"));
    const std::size_t cells = pvs.data.sources.size();
    ASSERT_GT(cells, 2u);
    for (std::size_t c = 1; c < cells; ++c)
        pvs.data.sources[c] = osgVis::core::placeholderSource(cells, pvs.data.objectCount);
    pvs.sourceRange = std::make_pair(0u, 1u);
    osgVis::core::writePvsFile(path("x.pvs"), pvs);
    readUntrusted(path("x.pvs"), "holds only source cells 0-0 of " + std::to_string(cells) +
                                     " (a range file of a split bake: join the ranges with osgvispvs merge)");
}

TEST_F(PvsPlugin, WrittenPvsRecordsItsBake)
{
    writeOffice();
    const osgVis::core::PvsFile pvs = osgVis::core::readPvsFile(path("x.pvs"));
    EXPECT_EQ(pvs.version, 2u);
    EXPECT_EQ(pvs.method, "cellportal");
    EXPECT_EQ(pvs.options, osgVis::core::canonicalBakeOptions({}));
    EXPECT_EQ(pvs.nearDistance, 0.0);
    EXPECT_TRUE(pvs.hasCellPortal);
    EXPECT_FALSE(pvs.hasViewCells);
    const auto extracted = osgVis::extractScene(*makeOffice(1));
    EXPECT_EQ(pvs.geometryFingerprint, osgVis::core::sceneGeometryFingerprint(extracted->scene));
}

TEST_F(PvsPlugin, HoleCutIntoAWallIsAnotherModel)
{
    ASSERT_TRUE(osgDB::writeNodeFile(*makeWallAndBox(false), path("x.pvs")));
    const osg::ref_ptr<osgVis::VisibilityGroup> baked = readGroup(path("x.pvs"));
    ASSERT_TRUE(baked.valid());
    EXPECT_EQ(description(*baked), "osgVis:pvs-trusted");
    ASSERT_TRUE(osgDB::writeNodeFile(*makeWallAndBox(true), path("x.osgb")));
    const osg::ref_ptr<osgVis::VisibilityGroup> group =
        readUntrusted(path("x.pvs"), "baked for another model (geometry fingerprint 0x");
    ASSERT_TRUE(group.valid());
    // The version 1 fingerprint cannot tell the two apart: bounds, triangle counts and flags agree.
    const auto before = osgVis::extractScene(*makeWallAndBox(false));
    const auto after = osgVis::extractScene(*group->getChild(0));
    EXPECT_EQ(osgVis::core::sceneFingerprint(after->scene), osgVis::core::sceneFingerprint(before->scene));
    EXPECT_EQ(osgVis::core::sceneFingerprint(after->scene), osgVis::core::readPvsFile(path("x.pvs")).data.fingerprint);
}

TEST_F(PvsPlugin, Version1FileIsCheckedByItsFingerprint)
{
    writeOffice();
    const std::vector<std::uint8_t> v2 = osgVis::core::encodePvs(osgVis::core::readPvsFile(path("x.pvs")));
    const std::vector<std::uint8_t> v1 = osgVis::test::rewriteAsVersion1(v2);
    std::ofstream(path("x.pvs"), std::ios::binary)
        .write(reinterpret_cast<const char*>(v1.data()), std::streamsize(v1.size()));
    ASSERT_EQ(osgVis::core::readPvsFile(path("x.pvs")).version, 1u);
    const osg::ref_ptr<osgVis::VisibilityGroup> trusted = readGroup(path("x.pvs"));
    ASSERT_TRUE(trusted.valid());
    EXPECT_EQ(trusted->getModes(), "cellportal");
    EXPECT_EQ(description(*trusted), "osgVis:pvs-trusted");

    ASSERT_TRUE(osgDB::writeNodeFile(*makeOffice(2), path("x.osgb")));
    readUntrusted(path("x.pvs"), "baked for another model (fingerprint 0x");
}

TEST_F(PvsPlugin, ViewCellsAloneShowTheModelUnderMultifocalWithTheCellsHeldByTheGroup)
{
    writeOffice();
    osgVis::core::PvsFile pvs = osgVis::core::readPvsFile(path("x.pvs"));
    pvs.method = "multifocal";
    pvs.nearDistance = 0.25;
    pvs.hasCellPortal = false;
    pvs.data.graph = {};
    pvs.data.sources.clear();
    pvs.hasViewCells = true;
    pvs.viewCells.totalCells = 1;
    pvs.viewCells.cellIndices = {0};
    pvs.viewCells.cells = {osgVis::core::Aabb(osgVis::core::Vec3(0.0), osgVis::core::Vec3(1.0))};
    pvs.viewCells.pvs = {osgVis::core::VisibleSet(pvs.data.objectCount, true)};
    osgVis::core::writePvsFile(path("x.pvs"), pvs);
    const osg::ref_ptr<osgVis::VisibilityGroup> group = readGroup(path("x.pvs"));
    ASSERT_TRUE(group.valid());
    EXPECT_EQ(group->getModes(), "multifocal");
    EXPECT_EQ(description(*group), "osgVis:pvs-trusted");
    ASSERT_TRUE(group->getBakedData());
    const auto cells = group->getBakedData()->get<osgVis::core::BakedViewCells>();
    ASSERT_TRUE(cells);
    EXPECT_EQ(cells->fingerprint, pvs.data.fingerprint);
    EXPECT_EQ(cells->objectCount, pvs.data.objectCount);
    EXPECT_EQ(cells->nearDistance, 0.25);
    ASSERT_EQ(cells->cells.cells.size(), 1u);

    // Neither kind of data: the model under frustum culling.
    pvs.hasViewCells = false;
    pvs.viewCells = {};
    osgVis::core::writePvsFile(path("x.pvs"), pvs);
    const osg::ref_ptr<osgVis::VisibilityGroup> empty =
        readUntrusted(path("x.pvs"), "holds neither cell-portal data nor view cells");
    ASSERT_TRUE(empty.valid());
    EXPECT_EQ(description(*empty),
              "osgVis:pvs-untrusted: holds neither cell-portal data nor view cells (method 'multifocal')");
}

TEST_F(PvsPlugin, TruncatedPvsShowsTheModelBesideWithFrustumOnly)
{
    writeOffice();
    truncateToHalf(path("x.pvs"));
    const osg::ref_ptr<osgVis::VisibilityGroup> group = readGroup(path("x.pvs"));
    ASSERT_TRUE(group.valid());
    EXPECT_EQ(group->getModes(), "frustum");
    const std::string expected = "osgVis:pvs-untrusted: corrupt .pvs: truncated at byte " +
                                 std::to_string(fs::file_size(path("x.pvs"))) + " while reading ";
    EXPECT_EQ(description(*group).rfind(expected, 0), 0u) << description(*group);
}

TEST_F(PvsPlugin, TruncatedPvsWithoutModelIsAnError)
{
    writeOffice();
    truncateToHalf(path("x.pvs"));
    fs::remove(path("x.osgb"));
    osgDB::ReaderWriter::ReadResult result =
        osgDB::Registry::instance()->readNode(path("x.pvs"), osgDB::Registry::instance()->getOptions());
    EXPECT_FALSE(result.validNode());
    EXPECT_EQ(result.message().rfind("osgVis: " + path("x.pvs") + " is corrupt (truncated at byte ", 0), 0u)
        << result.message();
    EXPECT_NE(result.message().find(") and no model lies beside it (" + path("x") + ".osgb, .osgt, .ive or .osg)"),
              std::string::npos)
        << result.message();
}

TEST_F(PvsPlugin, MissingNamedModelIsAnErrorNamingIt)
{
    writeOffice();
    fs::rename(path("x.osgb"), path("elsewhere.osgb"));
    osgDB::ReaderWriter::ReadResult result =
        osgDB::Registry::instance()->readNode(path("x.pvs"), osgDB::Registry::instance()->getOptions());
    EXPECT_FALSE(result.validNode());
    EXPECT_EQ(result.message().rfind("osgVis: cannot find model 'x.osgb' named by " + path("x.pvs"), 0), 0u)
        << result.message();
}

TEST_F(PvsPlugin, ModelOptionNamesAnExistingFileOfTheSameModel)
{
    writeOffice();
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options("model=" + path("x.osgb"));
    fs::create_directories(_dir / "pvs");
    ASSERT_TRUE(osgDB::writeNodeFile(*makeOffice(1), path("pvs/y.pvs"), options.get()));
    EXPECT_FALSE(fs::exists(path("pvs/y.osgb")));
    EXPECT_EQ(osgVis::core::readPvsFile(path("pvs/y.pvs")).modelPath, "../x.osgb");
    const osg::ref_ptr<osgVis::VisibilityGroup> group = readGroup(path("pvs/y.pvs"));
    ASSERT_TRUE(group.valid());
    EXPECT_EQ(description(*group), "osgVis:pvs-trusted");

    const osgDB::ReaderWriter::WriteResult other =
        osgDB::Registry::instance()->writeNode(*makeOffice(2), path("z.pvs"), options.get());
    EXPECT_FALSE(other.success());
    EXPECT_EQ(other.message(), "osgVis: model=" + path("x.osgb") + " is not the node being written to " +
                                   path("z.pvs") + " (their fingerprints differ)");
    EXPECT_FALSE(fs::exists(path("z.pvs")));
}

TEST_F(PvsPlugin, GroupReadFromPvsWritesItsModel)
{
    writeOffice();
    const osg::ref_ptr<osgVis::VisibilityGroup> group = readGroup(path("x.pvs"));
    ASSERT_TRUE(group.valid());
    ASSERT_TRUE(osgDB::writeNodeFile(*group, path("again.pvs")));
    const osg::ref_ptr<osgVis::VisibilityGroup> again = readGroup(path("again.pvs"));
    ASSERT_TRUE(again.valid());
    EXPECT_EQ(description(*again), "osgVis:pvs-trusted");
    EXPECT_EQ(osgVis::core::readPvsFile(path("again.pvs")).data.fingerprint,
              osgVis::core::readPvsFile(path("x.pvs")).data.fingerprint);
}

TEST_F(PvsPlugin, StreamReadFindsTheModelOnTheDatabasePath)
{
    writeOffice();
    osgDB::ReaderWriter* rw = osgDB::Registry::instance()->getReaderWriterForExtension("pvs");
    ASSERT_NE(rw, nullptr);
    std::ifstream in(path("x.pvs"), std::ios::binary);
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->getDatabasePathList().push_back(_dir.string());
    osgDB::ReaderWriter::ReadResult result = rw->readNode(in, options.get());
    ASSERT_TRUE(result.validNode()) << result.message();
    EXPECT_EQ(description(*result.getNode()), "osgVis:pvs-trusted");
}

TEST_F(PvsPlugin, PvsNamingAPvsIsAnError)
{
    writeOffice();
    osgVis::core::PvsFile pvs = osgVis::core::readPvsFile(path("x.pvs"));
    pvs.modelPath = "x.pvs";
    osgVis::core::writePvsFile(path("x.pvs"), pvs);
    osgDB::ReaderWriter::ReadResult result =
        osgDB::Registry::instance()->readNode(path("x.pvs"), osgDB::Registry::instance()->getOptions());
    EXPECT_FALSE(result.validNode());
    EXPECT_EQ(result.message(),
              "osgVis: " + path("x.pvs") + " names another .pvs, '" + path("x.pvs") + "', as its model");
}

// Clusters (docs/clusters.md) change the objects: a .pvs baked without them is reported as such
// and not used, once a drawable of the model is split.
TEST_F(PvsPlugin, PvsBakedWithoutClustersIsReportedAsSuchWhenClustersSplitTheModel)
{
    osg::ref_ptr<osg::Group> model = makeOffice(1);
    // One large drawable: a 32 x 32 grid of quads (2048 triangles) low over the floor.
    const osg::BoundingSphere bound = model->getBound();
    osg::ref_ptr<osg::Geometry> grid = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
    osg::ref_ptr<osg::DrawElementsUInt> triangles = new osg::DrawElementsUInt(GL_TRIANGLES);
    const float r = 0.5f * bound.radius();
    for (int j = 0; j <= 32; ++j)
        for (int i = 0; i <= 32; ++i)
            vertices->push_back(bound.center() + osg::Vec3(r * (i / 16.f - 1), r * (j / 16.f - 1), 0.0f));
    for (int j = 0; j < 32; ++j)
        for (int i = 0; i < 32; ++i)
            for (int k : {0, 1, 34, 0, 34, 33})
                triangles->push_back(GLuint(j * 33 + i + k)); // corners (i, j), (i+1, j), (i+1, j+1), (i, j+1)
    grid->setVertexArray(vertices.get());
    grid->addPrimitiveSet(triangles.get());
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(grid);
    model->addChild(geode);

    ::setenv("OSGVIS_CLUSTER_THRESHOLD", "0", 1);
    const bool written = osgDB::writeNodeFile(*model, path("x.pvs"));
    ::setenv("OSGVIS_CLUSTER_THRESHOLD", "1000", 1);
    ASSERT_TRUE(written);
    readUntrusted(path("x.pvs"), "baked without clusters (");
    ::unsetenv("OSGVIS_CLUSTER_THRESHOLD");
    // Without clusters the same file is trusted.
    const osg::ref_ptr<osgVis::VisibilityGroup> group = readGroup(path("x.pvs"));
    ASSERT_TRUE(group.valid());
    EXPECT_EQ(description(*group), "osgVis:pvs-trusted");
}

// A bake of a whole paged database (osgvispvs reads every tile): the plugin checks the root file's
// own objects, hands the data to the group, and leaves the tiles to the pager.
TEST_F(PvsPlugin, PagedDatabaseBakeReadsAsTrustedOverTheRootAlone)
{
    const osgVis::gen::PagedSummary paged = osgVis::test::writePagedOffice(_dir.string());
    osg::ref_ptr<osg::Node> whole = osgDB::readRefNodeFile(paged.rootPath);
    ASSERT_TRUE(whole.valid());
    ASSERT_TRUE(osgVis::loadWholeDatabase(*whole).unreadable.empty());
    osgVis::core::PvsFile file;
    file.modelPath = "root.osgb";
    file.method = "cellportal";
    file.data = osgVis::core::bakeCellPortal(osgVis::extractScene(*whole)->scene);
    ASSERT_TRUE(file.data.tiles);
    osgVis::core::writePvsFile(path("db.pvs"), file);

    const osg::ref_ptr<osgVis::VisibilityGroup> group = readGroup(path("db.pvs"));
    ASSERT_TRUE(group.valid());
    EXPECT_EQ(group->getModes(), "cellportal");
    EXPECT_EQ(description(*group), "osgVis:pvs-trusted");
    const auto root = osgVis::extractScene(*group->getChild(0));
    ASSERT_TRUE(root->scene.tiles);
    EXPECT_TRUE(root->scene.tiles->files.empty()); // nothing paged in yet
    ASSERT_TRUE(group->getBakedData());
    const auto registered = group->getBakedData()->get<osgVis::core::CellPortalData>();
    ASSERT_TRUE(registered && registered->tiles);
    EXPECT_EQ(registered->tiles->rootFingerprint, root->scene.tiles->rootFingerprint);
    EXPECT_EQ(registered->objectCount, file.data.objectCount);

    // Another root (one tile fewer) is another database.
    osg::ref_ptr<osg::Group> fewer = dynamic_cast<osg::Group*>(osgDB::readRefNodeFile(paged.rootPath).get());
    ASSERT_TRUE(fewer.valid());
    fewer->removeChildren(0, 1);
    ASSERT_TRUE(osgDB::writeNodeFile(*fewer, paged.rootPath));
    readUntrusted(path("db.pvs"), "baked for another paged database (the root file's objects differ from the bake's)");
}
