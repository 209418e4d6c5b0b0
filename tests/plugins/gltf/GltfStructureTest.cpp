// SPDX-License-Identifier: MIT
// What osgdb_gltf makes of real Khronos sample models (Debian's assimp-testmodels): exact counts,
// bounds, names, materials and modes; malformed files as ReadResult errors naming the problem.
#include "GltfTestModels.h"

#include <AppProcess.h>
#include <osg/ComputeBoundsVisitor>
#include <osg/CullFace>
#include <osg/Geode>
#include <osg/Material>
#include <osg/MatrixTransform>
#include <osg/Texture2D>
#include <osgDB/ReadFile>
#include <osgVis/SceneExtractor>

#include <gtest/gtest.h>

#include <sstream>

using namespace osgVis::test::gltf;

namespace
{
const char* const boxTexturedFiles[] = {"BoxTextured-glTF/BoxTextured.gltf",
                                        "BoxTextured-glTF-Embedded/BoxTextured.gltf",
                                        "BoxTextured-glTF-Binary/BoxTextured.glb"};

osg::Geometry* firstGeometry(osg::Node& root)
{
    struct Find : public osg::NodeVisitor
    {
        Find() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        void apply(osg::Geometry& geometry) override
        {
            if (!found)
                found = &geometry;
        }
        osg::Geometry* found = nullptr;
    } find;
    root.accept(find);
    return find.found;
}

std::string errorOf(const std::string& relative)
{
    osgDB::ReaderWriter::ReadResult result = readFile(samplePath(relative));
    EXPECT_FALSE(result.validNode()) << relative << " should not load";
    EXPECT_TRUE(result.error()) << relative;
    return result.message();
}
} // namespace

// BoxTextured: one node (matrix swapping Y and Z) above one mesh "Mesh" of one primitive, 24
// vertices (accessor 2: min -0.5, max 0.5 on every axis), 36 indices, 12 triangles, textured with
// CesiumLogoFlat.png (211 × 211) through a sampler NEAREST_MIPMAP_LINEAR / LINEAR, wrapping
// REPEAT (assimp's copy with external files: MIRRORED_REPEAT / CLAMP_TO_EDGE). The three containers
// (external .bin + .png, data: URIs, .glb) give the same OSG scene.
TEST(GltfPlugin, BoxTexturedSameInEveryContainer)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    for (const char* file : boxTexturedFiles)
    {
        SCOPED_TRACE(file);
        const bool external = file == boxTexturedFiles[0];
        osgDB::ReaderWriter::ReadResult result = readFile(samplePath(file), "noRotation");
        ASSERT_TRUE(result.validNode()) << result.message();
        osg::ref_ptr<osg::Node> root = result.getNode();
        SceneCounts counts;
        root->accept(counts);
        EXPECT_EQ(counts.transforms, 2u); // node0 (the matrix) and node1 (the mesh)
        EXPECT_EQ(counts.geometryInstances, 1u);
        EXPECT_EQ(counts.triangleInstances, 12u);

        osg::Geometry* geometry = firstGeometry(*root);
        ASSERT_NE(geometry, nullptr);
        EXPECT_EQ(geometry->getName(), "Mesh#0");
        ASSERT_EQ(geometry->getNumParents(), 1u);
        EXPECT_EQ(geometry->getParent(0)->getName(), "Mesh");
        EXPECT_EQ(geometry->getParent(0)->getParent(0)->getName(), "node1");
        EXPECT_EQ(geometry->getVertexArray()->getNumElements(), 24u);
        ASSERT_NE(geometry->getNormalArray(), nullptr);
        EXPECT_EQ(geometry->getNormalArray()->getNumElements(), 24u);
        ASSERT_NE(geometry->getTexCoordArray(0), nullptr);
        EXPECT_EQ(geometry->getTexCoordArray(0)->getNumElements(), 24u);
        ASSERT_EQ(geometry->getNumPrimitiveSets(), 1u);
        EXPECT_EQ(geometry->getPrimitiveSet(0)->getMode(), GLenum(GL_TRIANGLES));
        EXPECT_EQ(geometry->getPrimitiveSet(0)->getNumIndices(), 36u);

        osg::ComputeBoundsVisitor bounds;
        root->accept(bounds);
        const osg::BoundingBox& box = bounds.getBoundingBox();
        EXPECT_NEAR(box.xMin(), -0.5, 1e-6);
        EXPECT_NEAR(box.yMin(), -0.5, 1e-6);
        EXPECT_NEAR(box.zMin(), -0.5, 1e-6);
        EXPECT_NEAR(box.xMax(), 0.5, 1e-6);
        EXPECT_NEAR(box.yMax(), 0.5, 1e-6);
        EXPECT_NEAR(box.zMax(), 0.5, 1e-6);

        const osg::StateSet* state = geometry->getStateSet();
        ASSERT_NE(state, nullptr);
        const auto* texture =
            dynamic_cast<const osg::Texture2D*>(state->getTextureAttribute(0, osg::StateAttribute::TEXTURE));
        ASSERT_NE(texture, nullptr);
        ASSERT_NE(texture->getImage(), nullptr);
        EXPECT_EQ(texture->getImage()->s(), 211);
        EXPECT_EQ(texture->getImage()->t(), 211);
        EXPECT_EQ(texture->getWrap(osg::Texture::WRAP_S), external ? osg::Texture::MIRROR : osg::Texture::REPEAT);
        EXPECT_EQ(texture->getWrap(osg::Texture::WRAP_T), external ? osg::Texture::CLAMP_TO_EDGE : osg::Texture::REPEAT);
        EXPECT_EQ(texture->getFilter(osg::Texture::MIN_FILTER), osg::Texture::NEAREST_MIPMAP_LINEAR);
        EXPECT_EQ(texture->getFilter(osg::Texture::MAG_FILTER), osg::Texture::LINEAR);
        const auto* material = dynamic_cast<const osg::Material*>(state->getAttribute(osg::StateAttribute::MATERIAL));
        ASSERT_NE(material, nullptr);
        EXPECT_EQ(material->getName(), "Texture");
        EXPECT_EQ(material->getDiffuse(osg::Material::FRONT), osg::Vec4(1, 1, 1, 1));
        // Not doubleSided: back faces culled.
        EXPECT_NE(state->getAttribute(osg::StateAttribute::CULLFACE), nullptr);
        EXPECT_EQ(state->getMode(GL_CULL_FACE) & osg::StateAttribute::ON, unsigned(osg::StateAttribute::ON));
    }
}

TEST(GltfPlugin, YUpSceneHangsUnderOneRotationToZUp)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    osgDB::ReaderWriter::ReadResult result = readFile(samplePath(boxTexturedFiles[0]));
    ASSERT_TRUE(result.validNode()) << result.message();
    auto* zUp = dynamic_cast<osg::MatrixTransform*>(result.getNode());
    ASSERT_NE(zUp, nullptr);
    EXPECT_EQ(zUp->getName(), "gltf Y-up to Z-up");
    const osg::Vec3d up = osg::Vec3d(0, 1, 0) * zUp->getMatrix();
    EXPECT_NEAR(up.x(), 0.0, 1e-12);
    EXPECT_NEAR(up.y(), 0.0, 1e-12);
    EXPECT_NEAR(up.z(), 1.0, 1e-12);
    const osg::Vec3d forward = osg::Vec3d(0, 0, 1) * zUp->getMatrix();
    EXPECT_NEAR(forward.y(), -1.0, 1e-12);
    ASSERT_EQ(zUp->getNumChildren(), 1u);
    EXPECT_EQ(zUp->getChild(0)->getName(), "BoxTextured.gltf"); // the scene has no name
}

// 2CylinderEngine.glb: 82 nodes (all reachable from the scene's two roots), 29 meshes of 34
// primitives in all; 67 nodes use a mesh, which draws 115 geometry instances and 121,496 triangles
// (75,730 in the 34 distinct primitives).
TEST(GltfPlugin, TwoCylinderEngineCounts)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    osgDB::ReaderWriter::ReadResult result = readFile(samplePath("2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
    ASSERT_TRUE(result.validNode()) << result.message();
    SceneCounts counts;
    result.getNode()->accept(counts);
    EXPECT_EQ(counts.transforms, 82u + 1u); // the glTF nodes and the Y-up rotation
    EXPECT_EQ(counts.geometries.size(), 34u);
    EXPECT_EQ(counts.geometryInstances, 115u);
    EXPECT_EQ(counts.triangleInstances, 121496u);
    unsigned distinctTriangles = 0;
    for (const osg::Geometry* geometry : counts.geometries)
        distinctTriangles += triangleCount(*geometry);
    EXPECT_EQ(distinctTriangles, 75730u);
}

// The extractor sees one object per primitive instance, each with non-empty bounds (clusters off:
// with them, large primitives are several objects each, docs/clusters.md).
TEST(GltfPlugin, ExtractorGivesOneObjectPerPrimitiveInstance)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    for (const auto& [file, objects] : {std::pair<std::string, std::size_t>{boxTexturedFiles[2], 1},
                                        {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 115}})
    {
        SCOPED_TRACE(file);
        osgDB::ReaderWriter::ReadResult result = readFile(samplePath(file));
        ASSERT_TRUE(result.validNode()) << result.message();
        osg::ref_ptr<osg::Node> root = result.getNode();
        osgVis::ExtractionOptions whole;
        whole.clusterThreshold = 0;
        osg::ref_ptr<osgVis::ExtractedScene> extracted = osgVis::extractScene(*root, whole);
        ASSERT_EQ(extracted->refs.size(), objects);
        for (std::size_t i = 0; i < extracted->refs.size(); ++i)
        {
            const osg::BoundingBox box = extracted->refs[i].drawable->getBoundingBox();
            EXPECT_TRUE(box.valid()) << extracted->refs[i].drawable->getName();
            EXPECT_GT(box.radius(), 0.0f) << extracted->refs[i].drawable->getName();
        }
    }
}

// glTF-Asset-Generator's Mesh_PrimitiveMode_00..15: each mode without indices (00-06) and with
// uint32 (07-13), uint8 (14) and uint16 (15) indices.
TEST(GltfPlugin, PrimitiveModes)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    struct Expected
    {
        GLenum mode;
        bool indexed;
        unsigned count;
    };
    const Expected expected[16] = {
        {GL_POINTS, false, 1024},  {GL_LINES, false, 8},         {GL_LINE_LOOP, false, 4},
        {GL_LINE_STRIP, false, 5}, {GL_TRIANGLE_STRIP, false, 4}, {GL_TRIANGLE_FAN, false, 4},
        {GL_TRIANGLES, false, 6},  {GL_POINTS, true, 1024},       {GL_LINES, true, 8},
        {GL_LINE_LOOP, true, 4},   {GL_LINE_STRIP, true, 5},      {GL_TRIANGLE_STRIP, true, 4},
        {GL_TRIANGLE_FAN, true, 4}, {GL_TRIANGLES, true, 6},      {GL_TRIANGLES, true, 6},
        {GL_TRIANGLES, true, 6}};
    for (int i = 0; i < 16; ++i)
    {
        const std::string file = std::string("glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_") +
                                 (i < 10 ? "0" : "") + std::to_string(i) + ".gltf";
        SCOPED_TRACE(file);
        osgDB::ReaderWriter::ReadResult result = readFile(samplePath(file));
        ASSERT_TRUE(result.validNode()) << result.message();
        osg::Geometry* geometry = firstGeometry(*result.getNode());
        ASSERT_NE(geometry, nullptr);
        ASSERT_EQ(geometry->getNumPrimitiveSets(), 1u);
        const osg::PrimitiveSet* primitives = geometry->getPrimitiveSet(0);
        EXPECT_EQ(primitives->getMode(), expected[i].mode);
        EXPECT_EQ(primitives->getDrawElements() != nullptr, expected[i].indexed);
        EXPECT_EQ(primitives->getNumIndices(), expected[i].count);
        // No normals: triangles get smooth ones, points and lines are drawn unlit in the base colour.
        const bool surface = expected[i].mode == GL_TRIANGLES || expected[i].mode == GL_TRIANGLE_STRIP ||
                             expected[i].mode == GL_TRIANGLE_FAN;
        EXPECT_EQ(geometry->getNormalArray() != nullptr, surface);
        EXPECT_EQ(geometry->getStateSet()->getMode(GL_LIGHTING),
                  surface ? unsigned(osg::StateAttribute::INHERIT) : unsigned(osg::StateAttribute::OFF));
        if (!surface)
        {
            ASSERT_NE(geometry->getColorArray(), nullptr);
            EXPECT_EQ(geometry->getColorArray()->getBinding(), osg::Array::BIND_OVERALL);
        }
    }
}

TEST(GltfPlugin, MalformedFilesGiveErrorsNamingTheProblem)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    EXPECT_EQ(errorOf("IndexOutOfRange/IndexOutOfRange.gltf"),
              "gltf: IndexOutOfRange.gltf: index 255 at position 0 of accessor 0 is out of range (the primitive has "
              "24 vertices)");
    EXPECT_EQ(errorOf("IndexOutOfRange/AllIndicesOutOfRange.gltf"),
              "gltf: AllIndicesOutOfRange.gltf: index 65535 at position 0 of accessor 0 is out of range (the "
              "primitive has 24 vertices)");
    EXPECT_EQ(errorOf("MissingBin/BoxTextured.gltf"), "gltf: BoxTextured.gltf: File not found : BoxTextured0.bin");
    EXPECT_EQ(errorOf("RecursiveNodes/RecursiveNodes.gltf"),
              "gltf: RecursiveNodes.gltf: node 0 is its own ancestor (a cycle through node 1)");
    EXPECT_EQ(errorOf("draco/2CylinderEngine.gltf"),
              "gltf: 2CylinderEngine.gltf: Draco mesh compression (KHR_draco_mesh_compression) is not supported");
    EXPECT_EQ(errorOf("wrongTypes/badArray.gltf"),
              "gltf: badArray.gltf: mesh 0 has no primitives (glTF requires at least one)");
    EXPECT_EQ(errorOf("../glTF/TwoBoxes/TwoBoxes.gltf"), "gltf: TwoBoxes.gltf: glTF 1.0.2 is not supported (only glTF 2.0)");
    EXPECT_EQ(errorOf("../glTF/BoxTextured-glTF-Binary/BoxTextured.glb"),
              "gltf: BoxTextured.glb: binary glTF version 1 is not supported (only glTF 2.0)");
    // "scene": "hello" is ignored by tinygltf; the file then fails on its missing buffer file.
    EXPECT_EQ(errorOf("SchemaFailures/sceneWrongType.gltf"),
              "gltf: sceneWrongType.gltf: File not found : BoxTextured0.bin");
}

// Optional properties of the wrong JSON type are ignored (tinygltf keeps their defaults): the files
// load; NaN/inf positions are allowed.
TEST(GltfPlugin, TolerableOddities)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    for (const char* file : {"wrongTypes/badNumber.gltf", "wrongTypes/badObject.gltf", "wrongTypes/badString.gltf",
                             "wrongTypes/badUint.gltf", "wrongTypes/badExtension.gltf",
                             "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "TestNoRootNode/SceneWithoutNodes.gltf"})
    {
        osgDB::ReaderWriter::ReadResult result = readFile(samplePath(file));
        EXPECT_TRUE(result.validNode()) << file << ": " << result.message();
    }
    // No scenes and no nodes: an empty scene.
    osgDB::ReaderWriter::ReadResult empty = readFile(samplePath("TestNoRootNode/NoScene.gltf"), "noRotation");
    ASSERT_TRUE(empty.validNode()) << empty.message();
    EXPECT_EQ(empty.getNode()->asGroup()->getNumChildren(), 0u);
}

// A stream has no folder: its external .bin and .png resolve through the options' database path.
TEST(GltfPlugin, StreamFindsExternalFilesOnTheDatabasePath)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    std::istringstream in(fileBytes(samplePath(boxTexturedFiles[0])));
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setDatabasePath(samplePath("BoxTextured-glTF"));
    osgDB::ReaderWriter::ReadResult result = gltfReader().readNode(in, options.get());
    ASSERT_TRUE(result.validNode()) << result.message();
    SceneCounts counts;
    result.getNode()->accept(counts);
    EXPECT_EQ(counts.triangleInstances, 12u);

    std::istringstream lost(fileBytes(samplePath(boxTexturedFiles[0])));
    osgDB::ReaderWriter::ReadResult missing = gltfReader().readNode(lost, nullptr);
    EXPECT_EQ(missing.message(), "gltf: <stream>: File not found : BoxTextured0.bin");
}

// OSG loads osgdb_<ext> for x.<ext>: .glb must find the reader in a fresh process with nothing but
// OSG_LIBRARY_PATH, here through the stock osgconv.
TEST(GltfPlugin, GlbLoadsInAFreshOsgconv)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    const std::filesystem::path scratch = osgVis::test::scratchDirectory("plugins", "gltf-osgconv");
    const std::string out = (scratch / "engine.osgt").string();
    const osgVis::test::AppRun run =
        osgVis::test::runApp("/usr/bin/env", "-i PATH=/usr/bin:/bin OSG_LIBRARY_PATH=" OSGVIS_BINARY_DIR "/lib osgconv '" +
                                                 samplePath("2CylinderEngine-glTF-Binary/2CylinderEngine.glb") + "' '" +
                                                 out + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string written = osgVis::test::readText(out);
    EXPECT_NE(written.find("gltf Y-up to Z-up"), std::string::npos);
    EXPECT_NE(written.find("Piston_123-844_0_Parts_1#0"), std::string::npos);
}

// NaN positions are allowed, but OSG's SmoothingVisitor crashes on them (its ordered vertex set
// loses its ordering; found by the libFuzzer target): such a primitive without normals gets one
// overall normal instead of generated ones.
TEST(GltfPlugin, NanPositionsWithoutNormalsGetOneNormal)
{
    // Six vertices (0,0,0) (1,0,0) (0,1,0) (NaN,0,0) (1,NaN,1) (0,1,NaN), two triangles, no normals.
    const std::string gltf = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":6,"type":"VEC3"}],
        "bufferViews":[{"buffer":0,"byteLength":72}],
        "buffers":[{"byteLength":72,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAADAfwAAAAAAAAAAAACAPwAAwH8AAIA/AAAAAAAAgD8AAMB/"}]})";
    std::istringstream in(gltf);
    osgDB::ReaderWriter::ReadResult result = gltfReader().readNode(in, nullptr);
    ASSERT_TRUE(result.validNode()) << result.message();
    osg::Geometry* geometry = firstGeometry(*result.getNode());
    ASSERT_NE(geometry, nullptr);
    EXPECT_EQ(geometry->getName(), "mesh0#0");
    EXPECT_EQ(geometry->getVertexArray()->getNumElements(), 6u);
    ASSERT_NE(geometry->getNormalArray(), nullptr);
    EXPECT_EQ(geometry->getNormalArray()->getBinding(), osg::Array::BIND_OVERALL);
    EXPECT_EQ(geometry->getNormalArray()->getNumElements(), 1u);
}

// One mesh "tri" of two primitives over the same triangle: the first with COLOR_0 (normalized
// bytes: white, black, red with alpha 0) and a material that blends, is double-sided and emissive;
// the second with no material (glTF's default: opaque white, back faces culled).
TEST(GltfPlugin, MaterialsAndVertexColours)
{
    const std::string gltf = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"name":"holder","mesh":0}],
        "meshes":[{"name":"tri","primitives":[{"attributes":{"POSITION":0,"COLOR_0":1},"material":0},
                                              {"attributes":{"POSITION":0}}]}],
        "materials":[{"name":"glass","alphaMode":"BLEND","doubleSided":true,"emissiveFactor":[0.1,0.2,0.3],
                      "pbrMetallicRoughness":{"baseColorFactor":[1,0.5,0.25,0.5]}}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
                     {"bufferView":0,"byteOffset":36,"componentType":5121,"normalized":true,"count":3,"type":"VEC4"}],
        "bufferViews":[{"buffer":0,"byteLength":48}],
        "buffers":[{"byteLength":48,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA/////wAAAP//AAAA"}]})";
    std::istringstream in(gltf);
    osgDB::ReaderWriter::ReadResult result = gltfReader().readNode(in, nullptr);
    ASSERT_TRUE(result.validNode()) << result.message();
    osg::Geometry* coloured = firstGeometry(*result.getNode());
    ASSERT_NE(coloured, nullptr);
    osg::Geode* geode = coloured->getParent(0)->asGeode();
    EXPECT_EQ(geode->getName(), "tri");
    EXPECT_EQ(geode->getParent(0)->getName(), "holder");
    ASSERT_EQ(geode->getNumDrawables(), 2u);
    EXPECT_EQ(coloured->getName(), "tri#0");
    osg::Geometry* plain = geode->getDrawable(1)->asGeometry();
    EXPECT_EQ(plain->getName(), "tri#1");

    // Vertex colours carry the base colour factor (fixed function cannot multiply both).
    const auto* colours = dynamic_cast<const osg::Vec4Array*>(coloured->getColorArray());
    ASSERT_NE(colours, nullptr);
    ASSERT_EQ(colours->size(), 3u);
    EXPECT_EQ((*colours)[0], osg::Vec4(1, 0.5f, 0.25f, 0.5f));
    EXPECT_EQ((*colours)[1], osg::Vec4(0, 0, 0, 0.5f));
    EXPECT_EQ((*colours)[2], osg::Vec4(1, 0, 0, 0));
    const osg::StateSet* glass = coloured->getStateSet();
    EXPECT_EQ(glass->getRenderingHint(), int(osg::StateSet::TRANSPARENT_BIN));
    EXPECT_NE(glass->getAttribute(osg::StateAttribute::BLENDFUNC), nullptr);
    EXPECT_EQ(glass->getMode(GL_CULL_FACE), unsigned(osg::StateAttribute::OFF));
    const auto* material = dynamic_cast<const osg::Material*>(glass->getAttribute(osg::StateAttribute::MATERIAL));
    ASSERT_NE(material, nullptr);
    EXPECT_EQ(material->getName(), "glass");
    EXPECT_EQ(material->getColorMode(), osg::Material::AMBIENT_AND_DIFFUSE);
    EXPECT_EQ(material->getEmission(osg::Material::FRONT), osg::Vec4(0.1f, 0.2f, 0.3f, 1));
    EXPECT_EQ(material->getDiffuse(osg::Material::FRONT), osg::Vec4(1, 0.5f, 0.25f, 0.5f));

    const osg::StateSet* white = plain->getStateSet();
    EXPECT_EQ(white->getRenderingHint(), int(osg::StateSet::DEFAULT_BIN));
    EXPECT_NE(white->getAttribute(osg::StateAttribute::CULLFACE), nullptr);
    const auto* defaultMaterial = dynamic_cast<const osg::Material*>(white->getAttribute(osg::StateAttribute::MATERIAL));
    ASSERT_NE(defaultMaterial, nullptr);
    EXPECT_EQ(defaultMaterial->getDiffuse(osg::Material::FRONT), osg::Vec4(1, 1, 1, 1));
    EXPECT_EQ(defaultMaterial->getColorMode(), osg::Material::OFF);
    // Normals were generated (no NORMAL attribute, finite positions): one per vertex.
    ASSERT_NE(plain->getNormalArray(), nullptr);
    EXPECT_EQ(plain->getNormalArray()->getNumElements(), 3u);
}

// Hand-made faults in a one-triangle file (positions in a 36-byte buffer): each is an error naming
// what is wrong.
TEST(GltfPlugin, BrokenReferencesAndRanges)
{
    const auto readTriangle = [](const std::string& accessor, const std::string& bufferView, const std::string& node) {
        const std::string gltf = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[)" + node +
                                 R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"accessors":[)" +
                                 accessor + R"(],"bufferViews":[)" + bufferView +
                                 R"(],"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
        std::istringstream in(gltf);
        return gltfReader().readNode(in, nullptr).message();
    };
    const std::string goodAccessor = R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"})";
    const std::string goodView = R"({"buffer":0,"byteLength":36})";
    const std::string goodNode = R"({"mesh":0})";
    EXPECT_EQ(readTriangle(goodAccessor, goodView, goodNode), "");
    EXPECT_EQ(readTriangle(R"({"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"})", goodView, goodNode),
              "gltf: <stream>: accessor 0 reads past the end of buffer view 0");
    EXPECT_EQ(readTriangle(R"({"bufferView":0,"byteOffset":4,"componentType":5126,"count":3,"type":"VEC3"})",
                           goodView, goodNode),
              "gltf: <stream>: accessor 0 reads past the end of buffer view 0");
    EXPECT_EQ(readTriangle(goodAccessor, R"({"buffer":0,"byteOffset":8,"byteLength":36})", goodNode),
              "gltf: <stream>: buffer view 0 reads past the end of buffer 0 (bytes 8+36 of 36)");
    EXPECT_EQ(readTriangle(goodAccessor, R"({"buffer":0,"byteLength":36,"byteStride":8})", goodNode),
              "gltf: <stream>: accessor 0 (POSITION): buffer view 0 has byte stride 8, smaller than the element "
              "size 12");
    EXPECT_EQ(readTriangle(R"({"bufferView":0,"componentType":5123,"count":3,"type":"VEC3"})", goodView, goodNode),
              "gltf: <stream>: accessor 0 (POSITION) has component type 5123, expected 5126");
    EXPECT_EQ(readTriangle(R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC2"})", goodView, goodNode),
              "gltf: <stream>: accessor 0 (POSITION) has type 2, expected 3");
    EXPECT_EQ(readTriangle(goodAccessor, goodView, R"({"mesh":3})"),
              "gltf: <stream>: a node refers to mesh 3, but there are 1");
    EXPECT_EQ(readTriangle(goodAccessor, goodView, R"({"mesh":0,"children":[5]})"),
              "gltf: <stream>: node 0 refers to node 5, but there are 1");
    EXPECT_EQ(readTriangle(goodAccessor, goodView, R"({"mesh":0,"children":[0]})"),
              "gltf: <stream>: node 0 is its own ancestor (a cycle through node 0)");
    // The node transform check osgvisrawgl shares (osgVis/gltf/GltfAccessors.h).
    EXPECT_EQ(readTriangle(goodAccessor, goodView, R"({"mesh":0,"matrix":[1,0,0]})"),
              "gltf: <stream>: node 0 has a matrix of 3 values, expected 16");
    EXPECT_EQ(readTriangle(goodAccessor, goodView, R"({"mesh":0,"rotation":[0,0,1]})"),
              "gltf: <stream>: node 0 has a rotation of 3 values, expected 4");
}
