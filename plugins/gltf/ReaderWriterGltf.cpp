// SPDX-License-Identifier: MIT
// osgdb_gltf: glTF 2.0 (.gltf JSON and .glb binary) as an osgDB format, read with tinygltf.
//
// Reading gives the model's default scene (else scene 0, else every parentless node):
// - glTF is Y-up, OSG Z-up: the scene hangs under one osg::MatrixTransform named
//   "gltf Y-up to Z-up" that rotates +90° about X (glTF +Y becomes OSG +Z, glTF +Z becomes OSG -Y).
//   The option string word `noRotation` leaves it out and returns the scene's Group itself.
// - each glTF node is an osg::MatrixTransform named after it ("node<i>" when unnamed); each mesh an
//   osg::Geode named after it ("mesh<i>"), shared by every node using it; each primitive an
//   osg::Geometry "<mesh>#<primitive index>" with its material as state (GltfMaterials.h).
// - user values "osgVis.gltf.node" (node index, on each node's MatrixTransform) and
//   "osgVis.gltf.primitive" (primitive index, on each Geometry) name an object by its glTF node path
//   and primitive, whatever the names (apps/common/GltfIdentity.h).
// - external buffers and images resolve beside the file; for readNode(istream), through the
//   options' database path list.
// Malformed input is a ReadResult error "gltf: <file>: <what is wrong>", never a crash: every
// reference, byte range, count and index is checked before use. glTF 1.0 and required extensions
// (Draco compression, ...) are errors saying they are not supported. Reading keeps no state, so
// pager threads may read at once.
//
// `.glb` reaches this plugin through osgdb_glb, a link to this module (OSG looks for osgdb_<ext>).
#include "../NodeReaderWriter.h"
#include "GltfParse.h"
#include "GltfScene.h"

#include <osgVis/gltf/GltfError.h>

#include <osg/MatrixTransform>
#include <osgDB/FileNameUtils>
#include <osgDB/Registry>
#include <osgDB/fstream>

#include <iterator>
#include <new>
#include <sstream>

namespace osgVis::gltfplugin
{
using gltf::GltfError;

namespace
{
bool hasOption(const osgDB::Options* options, const std::string& word)
{
    if (!options)
        return false;
    std::istringstream words(options->getOptionString());
    std::string each;
    while (words >> each)
        if (each == word)
            return true;
    return false;
}
} // namespace

class ReaderWriterGltf : public plugins::NodeReaderWriter
{
public:
    ReaderWriterGltf()
    {
        supportsExtension("gltf", "glTF 2.0 (JSON)");
        supportsExtension("glb", "glTF 2.0 (binary)");
        supportsOption("noRotation", "keep glTF's Y-up axes (no rotation to OSG's Z-up)");
    }
    const char* className() const override { return "osgVis glTF 2.0 reader"; }

    using NodeReaderWriter::readNode;
    ReadResult readNode(std::istream& in, const Options* options) const override
    {
        const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        return read(bytes, "<stream>", "", options);
    }

protected:
    ReadResult readFound(const std::string& file, const std::string& path, const Options* options) const override
    {
        osgDB::ifstream in(path.c_str(), std::ios::binary);
        if (!in)
            return ReadResult("gltf: " + file + ": cannot open " + path);
        const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        return read(bytes, osgDB::getSimpleFileName(path), osgDB::getFilePath(path), options);
    }

private:
    static ReadResult read(const std::string& bytes, const std::string& fileName, const std::string& baseDir,
                           const Options* options)
    {
        try
        {
            const tinygltf::Model model = parseGltf(bytes, baseDir, fileName, options);
            osg::ref_ptr<osg::Group> scene = buildScene(model, fileName, options);
            if (hasOption(options, "noRotation"))
                return scene.get();
            osg::ref_ptr<osg::MatrixTransform> zUp =
                new osg::MatrixTransform(osg::Matrixd::rotate(osg::PI_2, osg::X_AXIS));
            zUp->setName("gltf Y-up to Z-up");
            zUp->addChild(scene.get());
            return zUp.get();
        }
        catch (const GltfError& e)
        {
            return ReadResult("gltf: " + fileName + ": " + e.what());
        }
        catch (const std::bad_alloc&)
        {
            return ReadResult("gltf: " + fileName + ": out of memory");
        }
    }
};
} // namespace osgVis::gltfplugin

using osgVis::gltfplugin::ReaderWriterGltf;
REGISTER_OSGPLUGIN(gltf, ReaderWriterGltf)
