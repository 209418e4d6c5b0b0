// SPDX-License-Identifier: MIT
#include "GltfTestModels.h"

#include <osg/MatrixTransform>
#include <osg/TriangleFunctor>
#include <osgDB/Registry>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace osgVis::test::gltf
{
namespace
{
const std::string samplesRoot = "/usr/share/assimp/models/glTF2/";

struct TriangleCounter
{
    unsigned count = 0;
    void operator()(const osg::Vec3&, const osg::Vec3&, const osg::Vec3&) { ++count; }
};
} // namespace

std::string samplePath(const std::string& relative) { return samplesRoot + relative; }

bool haveSamples() { return std::filesystem::is_directory("/usr/share/assimp/models"); }

osgDB::ReaderWriter& gltfReader()
{
    osgDB::ReaderWriter* reader = osgDB::Registry::instance()->getReaderWriterForExtension("gltf");
    if (!reader)
        throw std::runtime_error("osgdb_gltf not found (is OSG_LIBRARY_PATH the build's lib folder?)");
    return *reader;
}

osgDB::ReaderWriter::ReadResult readFile(const std::string& path, const std::string& options)
{
    osg::ref_ptr<osgDB::Options> readOptions = new osgDB::Options(options);
    return gltfReader().readNode(path, readOptions.get());
}

std::string fileBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void SceneCounts::apply(osg::MatrixTransform& transform)
{
    ++transforms;
    traverse(transform);
}

void SceneCounts::apply(osg::Geometry& geometry)
{
    ++geometryInstances;
    triangleInstances += triangleCount(geometry);
    geometries.insert(&geometry);
}

unsigned triangleCount(const osg::Geometry& geometry)
{
    osg::TriangleFunctor<TriangleCounter> counter;
    geometry.accept(counter);
    return counter.count;
}
} // namespace osgVis::test::gltf
