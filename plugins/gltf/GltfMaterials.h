// SPDX-License-Identifier: MIT
#pragma once
// glTF materials as OSG state: pbrMetallicRoughness base colour (factor → osg::Material diffuse and
// ambient, texture → osg::Texture2D on unit 0 with the sampler's wrap and filter modes), emissive
// factor, alpha mode (BLEND → blending in the transparent bin, MASK → alpha test) and doubleSided
// (else back faces culled). Images are decoded by OSG's own image plugins; an image that cannot be
// decoded is a warning and the material goes untextured.
#include <osg/StateSet>
#include <osg/Texture2D>
#include <tiny_gltf.h>

#include <map>
#include <string>
#include <utility>

namespace osgDB
{
class Options;
}

namespace osgVis::gltfplugin
{
class MaterialBuilder
{
public:
    MaterialBuilder(const tinygltf::Model& model, std::string fileName, const osgDB::Options* options);

    // The state set of material `materialIndex` (-1: glTF's default material, white), shared by
    // every primitive using it. `vertexColors`: the primitive has COLOR_0, which then drives
    // diffuse and ambient (the geometry's colours are premultiplied by baseColorFactor).
    osg::ref_ptr<osg::StateSet> stateSet(int materialIndex, bool vertexColors);
    // The base colour factor of material `materialIndex` (white for -1).
    osg::Vec4 baseColorFactor(int materialIndex) const;

private:
    osg::ref_ptr<osg::Texture2D> texture(int textureIndex);
    osg::ref_ptr<osg::Image> image(int imageIndex);

    const tinygltf::Model& _model;
    std::string _fileName;
    const osgDB::Options* _options;
    std::map<std::pair<int, bool>, osg::ref_ptr<osg::StateSet>> _stateSets;
    std::map<int, osg::ref_ptr<osg::Texture2D>> _textures;
    std::map<int, osg::ref_ptr<osg::Image>> _images;
};
} // namespace osgVis::gltfplugin
