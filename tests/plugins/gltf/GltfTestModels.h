// SPDX-License-Identifier: MIT
#pragma once
// The Khronos sample models Debian's assimp-testmodels installs, and small helpers the glTF plugin
// tests share: reading through osgDB and counting what a loaded scene holds.
#include <osg/Geometry>
#include <osg/NodeVisitor>
#include <osgDB/ReaderWriter>

#include <set>
#include <string>

namespace osgVis::test::gltf
{
// "/usr/share/assimp/models/glTF2/" + relative.
std::string samplePath(const std::string& relative);
// Whether the sample models are installed; tests GTEST_SKIP when not.
bool haveSamples();
#define OSGVIS_REQUIRE_GLTF_SAMPLES()                                                                                    \
    if (!osgVis::test::gltf::haveSamples())                                                                            \
    GTEST_SKIP() << "assimp-testmodels not installed (/usr/share/assimp/models absent)"

// The osgdb_gltf reader itself (loaded from OSG_LIBRARY_PATH like any plugin).
osgDB::ReaderWriter& gltfReader();
// readNode(file) with an optional option string ("noRotation").
osgDB::ReaderWriter::ReadResult readFile(const std::string& path, const std::string& options = "");
// The whole file as bytes.
std::string fileBytes(const std::string& path);

// What a scene holds, counted per traversal (a shared mesh counts once per instance) and per
// distinct Geometry.
struct SceneCounts : public osg::NodeVisitor
{
    SceneCounts() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::MatrixTransform& transform) override;
    void apply(osg::Geometry& geometry) override;

    unsigned transforms = 0;
    unsigned geometryInstances = 0;
    unsigned triangleInstances = 0;
    std::set<const osg::Geometry*> geometries;
};
// Triangles a geometry's primitive sets draw (strips and fans as their triangle count).
unsigned triangleCount(const osg::Geometry& geometry);
} // namespace osgVis::test::gltf
