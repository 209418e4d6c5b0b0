// SPDX-License-Identifier: MIT
// osgdb_pvs through osgDB, as an application uses it: write x.pvs (bake + model beside), read it
// back as a trusted cell-portal group, and every way the pair can go wrong.
#include <osgVis/SceneExtractor>
#include <osgVis/VisibilityGroup>
#include <osgVis/core/cellportal/CellPortalModule.h>
#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/gen/Generator.h>

#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

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

    // The data are registered under the fingerprint of the model as read.
    const auto extracted = osgVis::extractScene(*group->getChild(0));
    EXPECT_EQ(osgVis::core::sceneFingerprint(extracted->scene), pvs.data.fingerprint);
    const auto registered = osgVis::core::findBakedCellPortalData(pvs.data.fingerprint);
    ASSERT_TRUE(registered);
    EXPECT_EQ(registered->graph.cells.size(), pvs.data.graph.cells.size());
    EXPECT_EQ(registered->objectCount, extracted->scene.objects.size());
}

TEST_F(PvsPlugin, ReplacedModelIsShownWithFrustumOnly)
{
    writeOffice();
    ASSERT_TRUE(osgDB::writeNodeFile(*makeOffice(2), path("x.osgb")));
    const osg::ref_ptr<osgVis::VisibilityGroup> group = readGroup(path("x.pvs"));
    ASSERT_TRUE(group.valid());
    EXPECT_EQ(group->getModes(), "frustum");
    EXPECT_EQ(description(*group).rfind("osgVis:pvs-untrusted: baked for another model (fingerprint 0x", 0), 0u)
        << description(*group);
    EXPECT_EQ(group->getNumChildren(), 1u);
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
