// SPDX-License-Identifier: MIT
#include "GltfMaterials.h"

#include "GltfImages.h"

#include <osgVis/gltf/GltfAccessors.h>
#include <osgVis/gltf/GltfError.h>

#include <osg/AlphaFunc>
#include <osg/BlendFunc>
#include <osg/CullFace>
#include <osg/LightModel>
#include <osg/Material>
#include <osg/Notify>

namespace osgVis::gltfplugin
{
using gltf::bufferViewBytes;
using gltf::ByteRange;
using gltf::checkReference;

namespace
{
osg::Texture::WrapMode wrapMode(int gltfWrap)
{
    switch (gltfWrap)
    {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
        return osg::Texture::CLAMP_TO_EDGE;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
        return osg::Texture::MIRROR;
    default:
        return osg::Texture::REPEAT;
    }
}

// glTF leaves filters undefined when absent; trilinear minification and linear magnification are
// the usual choice.
osg::Texture::FilterMode filterMode(int gltfFilter, osg::Texture::FilterMode absent)
{
    switch (gltfFilter)
    {
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
        return osg::Texture::NEAREST;
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
        return osg::Texture::LINEAR;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
        return osg::Texture::NEAREST_MIPMAP_NEAREST;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
        return osg::Texture::LINEAR_MIPMAP_NEAREST;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
        return osg::Texture::NEAREST_MIPMAP_LINEAR;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
        return osg::Texture::LINEAR_MIPMAP_LINEAR;
    default:
        return absent;
    }
}

osg::Vec4 vec4(const std::vector<double>& values, const osg::Vec4& absent)
{
    if (values.size() < 3)
        return absent;
    return osg::Vec4(float(values[0]), float(values[1]), float(values[2]), values.size() > 3 ? float(values[3]) : 1.0f);
}
} // namespace

MaterialBuilder::MaterialBuilder(const tinygltf::Model& model, std::string fileName, const osgDB::Options* options)
    : _model(model), _fileName(std::move(fileName)), _options(options)
{
}

osg::Vec4 MaterialBuilder::baseColorFactor(int materialIndex) const
{
    if (materialIndex < 0)
        return osg::Vec4(1, 1, 1, 1);
    return vec4(_model.materials[std::size_t(materialIndex)].pbrMetallicRoughness.baseColorFactor, osg::Vec4(1, 1, 1, 1));
}

osg::ref_ptr<osg::StateSet> MaterialBuilder::stateSet(int materialIndex, bool vertexColors)
{
    if (materialIndex != -1) // -1: no material, glTF's default
        checkReference("a primitive", "material", materialIndex, _model.materials.size());
    osg::ref_ptr<osg::StateSet>& cached = _stateSets[{materialIndex, vertexColors}];
    if (cached)
        return cached;
    static const tinygltf::Material defaultMaterial;
    const tinygltf::Material& source = materialIndex < 0 ? defaultMaterial : _model.materials[std::size_t(materialIndex)];

    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    osg::ref_ptr<osg::Material> material = new osg::Material;
    material->setName(materialIndex < 0 ? "gltf default material" : source.name);
    const osg::Vec4 base = baseColorFactor(materialIndex);
    material->setDiffuse(osg::Material::FRONT_AND_BACK, base);
    material->setAmbient(osg::Material::FRONT_AND_BACK, base);
    material->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, base.a()));
    material->setEmission(osg::Material::FRONT_AND_BACK, vec4(source.emissiveFactor, osg::Vec4(0, 0, 0, 1)));
    if (vertexColors)
        material->setColorMode(osg::Material::AMBIENT_AND_DIFFUSE);
    state->setAttributeAndModes(material.get());

    if (source.alphaMode == "BLEND")
    {
        state->setAttributeAndModes(new osg::BlendFunc(osg::BlendFunc::SRC_ALPHA, osg::BlendFunc::ONE_MINUS_SRC_ALPHA));
        state->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
    }
    else if (source.alphaMode == "MASK")
        state->setAttributeAndModes(new osg::AlphaFunc(osg::AlphaFunc::GEQUAL, float(source.alphaCutoff)));

    if (source.doubleSided)
    {
        state->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
        osg::ref_ptr<osg::LightModel> twoSided = new osg::LightModel;
        twoSided->setTwoSided(true);
        state->setAttributeAndModes(twoSided.get());
    }
    else
        state->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK));

    const tinygltf::TextureInfo& baseTexture = source.pbrMetallicRoughness.baseColorTexture;
    if (baseTexture.index >= 0)
    {
        if (baseTexture.texCoord != 0)
            OSG_WARN << "gltf: " << _fileName << ": material " << materialIndex << " maps its base colour with TEXCOORD_"
                     << baseTexture.texCoord << "; only TEXCOORD_0 is read" << std::endl;
        if (osg::ref_ptr<osg::Texture2D> baseColor = texture(baseTexture.index))
            state->setTextureAttributeAndModes(0, baseColor.get());
    }
    cached = state;
    return cached;
}

osg::ref_ptr<osg::Texture2D> MaterialBuilder::texture(int textureIndex)
{
    checkReference("a material", "texture", textureIndex, _model.textures.size());
    auto found = _textures.find(textureIndex);
    if (found != _textures.end())
        return found->second;
    const tinygltf::Texture& source = _model.textures[std::size_t(textureIndex)];
    osg::ref_ptr<osg::Texture2D> texture;
    if (source.source >= 0)
    {
        if (osg::ref_ptr<osg::Image> picture = image(source.source))
        {
            texture = new osg::Texture2D(picture.get());
            texture->setName(source.name);
            tinygltf::Sampler sampler;
            if (source.sampler >= 0)
            {
                checkReference("texture " + std::to_string(textureIndex), "sampler", source.sampler,
                               _model.samplers.size());
                sampler = _model.samplers[std::size_t(source.sampler)];
            }
            texture->setWrap(osg::Texture::WRAP_S, wrapMode(sampler.wrapS));
            texture->setWrap(osg::Texture::WRAP_T, wrapMode(sampler.wrapT));
            texture->setFilter(osg::Texture::MIN_FILTER, filterMode(sampler.minFilter, osg::Texture::LINEAR_MIPMAP_LINEAR));
            texture->setFilter(osg::Texture::MAG_FILTER, filterMode(sampler.magFilter, osg::Texture::LINEAR));
        }
    }
    _textures[textureIndex] = texture;
    return texture;
}

osg::ref_ptr<osg::Image> MaterialBuilder::image(int imageIndex)
{
    checkReference("a texture", "image", imageIndex, _model.images.size());
    auto found = _images.find(imageIndex);
    if (found != _images.end())
        return found->second;
    const tinygltf::Image& source = _model.images[std::size_t(imageIndex)];
    // note: the loader keeps encoded bytes (as_is); images in buffer views are read here, checked.
    ByteRange bytes{source.image.data(), source.image.size()};
    if (source.bufferView >= 0)
        bytes = bufferViewBytes(_model, source.bufferView);
    std::string problem = "its file was not found or is empty";
    osg::ref_ptr<osg::Image> decoded;
    if (bytes.size > 0)
        decoded = decodeImage(bytes.data, bytes.size, source.mimeType, source.uri, _options, problem);
    if (!decoded)
        OSG_WARN << "gltf: " << _fileName << ": image " << imageIndex
                 << (source.uri.empty() || source.uri.rfind("data:", 0) == 0 ? "" : " '" + source.uri + "'")
                 << " is left out: " << problem << std::endl;
    _images[imageIndex] = decoded;
    return decoded;
}
} // namespace osgVis::gltfplugin
