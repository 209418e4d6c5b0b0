// SPDX-License-Identifier: MIT
#include "GltfMeshes.h"

#include <osgVis/gltf/GltfAccessors.h>
#include <osgVis/gltf/GltfError.h>

#include <osg/Geometry>
#include <osg/ValueObject>
#include <osgUtil/SmoothingVisitor>

#include <algorithm>
#include <cmath>

namespace osgVis::gltfplugin
{
using gltf::checkReference;
using gltf::FloatElements;
using gltf::GltfError;
using gltf::readFloatAccessor;
using gltf::readIndexAccessor;

namespace
{
const std::vector<int> floatOnly{TINYGLTF_COMPONENT_TYPE_FLOAT};
const std::vector<int> floatOrNormalized{TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};

GLenum primitiveMode(int gltfMode, const std::string& where)
{
    switch (gltfMode)
    {
    case TINYGLTF_MODE_POINTS:
        return GL_POINTS;
    case TINYGLTF_MODE_LINE:
        return GL_LINES;
    case TINYGLTF_MODE_LINE_LOOP:
        return GL_LINE_LOOP;
    case TINYGLTF_MODE_LINE_STRIP:
        return GL_LINE_STRIP;
    case TINYGLTF_MODE_TRIANGLES:
        return GL_TRIANGLES;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
        return GL_TRIANGLE_STRIP;
    case TINYGLTF_MODE_TRIANGLE_FAN:
        return GL_TRIANGLE_FAN;
    default:
        throw GltfError(where + " has unknown mode " + std::to_string(gltfMode));
    }
}

int attribute(const tinygltf::Primitive& primitive, const char* name)
{
    auto found = primitive.attributes.find(name);
    return found == primitive.attributes.end() ? -1 : found->second;
}

// A per-vertex attribute read and checked to have one element per vertex.
FloatElements readVertexAttribute(const tinygltf::Model& model, int accessor, const std::vector<int>& types,
                                  const std::vector<int>& componentTypes, const char* usage, std::size_t vertexCount,
                                  const std::string& where)
{
    FloatElements elements = readFloatAccessor(model, accessor, types, componentTypes, usage);
    if (elements.count != vertexCount)
        throw GltfError(where + ": " + usage + " has " + std::to_string(elements.count) + " elements but POSITION has " +
                        std::to_string(vertexCount));
    return elements;
}

osg::ref_ptr<osg::Vec3Array> toVec3Array(const FloatElements& elements)
{
    osg::ref_ptr<osg::Vec3Array> array = new osg::Vec3Array(unsigned(elements.count));
    for (std::size_t i = 0; i < elements.count; ++i)
        (*array)[unsigned(i)].set(elements.values[3 * i], elements.values[3 * i + 1], elements.values[3 * i + 2]);
    return array;
}

bool allFinite(const FloatElements& elements)
{
    return std::all_of(elements.values.begin(), elements.values.end(), [](float v) { return std::isfinite(v); });
}

osg::ref_ptr<osg::Geometry> buildPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                           const std::string& where, MaterialBuilder& materials)
{
    if (primitive.extensions.count("KHR_draco_mesh_compression"))
        throw GltfError(where + " is Draco-compressed (KHR_draco_mesh_compression), which is not supported");
    const GLenum mode = primitiveMode(primitive.mode, where);
    const int positionAccessor = attribute(primitive, "POSITION");
    if (positionAccessor < 0)
        throw GltfError(where + " has no POSITION attribute");
    const FloatElements positions =
        readFloatAccessor(model, positionAccessor, {TINYGLTF_TYPE_VEC3}, floatOnly, "POSITION");
    const std::size_t vertexCount = positions.count;

    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setName(where);
    geometry->setVertexArray(toVec3Array(positions).get());
    geometry->setStateSet(materials.stateSet(primitive.material, attribute(primitive, "COLOR_0") >= 0).get());

    const int normalAccessor = attribute(primitive, "NORMAL");
    if (normalAccessor >= 0)
    {
        const FloatElements normals =
            readVertexAttribute(model, normalAccessor, {TINYGLTF_TYPE_VEC3}, floatOnly, "NORMAL", vertexCount, where);
        geometry->setNormalArray(toVec3Array(normals).get(), osg::Array::BIND_PER_VERTEX);
    }
    const int texcoordAccessor = attribute(primitive, "TEXCOORD_0");
    if (texcoordAccessor >= 0)
    {
        const FloatElements texcoords = readVertexAttribute(model, texcoordAccessor, {TINYGLTF_TYPE_VEC2},
                                                            floatOrNormalized, "TEXCOORD_0", vertexCount, where);
        osg::ref_ptr<osg::Vec2Array> array = new osg::Vec2Array(unsigned(vertexCount));
        // glTF's texture origin is the top-left corner, OSG's (OpenGL's) the bottom-left.
        for (std::size_t i = 0; i < vertexCount; ++i)
            (*array)[unsigned(i)].set(texcoords.values[2 * i], 1.0f - texcoords.values[2 * i + 1]);
        geometry->setTexCoordArray(0, array.get(), osg::Array::BIND_PER_VERTEX);
    }
    const int colorAccessor = attribute(primitive, "COLOR_0");
    if (colorAccessor >= 0)
    {
        const FloatElements colors = readVertexAttribute(model, colorAccessor, {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
                                                         floatOrNormalized, "COLOR_0", vertexCount, where);
        const osg::Vec4 factor = materials.baseColorFactor(primitive.material);
        osg::ref_ptr<osg::Vec4Array> array = new osg::Vec4Array(unsigned(vertexCount));
        const std::size_t n = std::size_t(colors.components);
        for (std::size_t i = 0; i < vertexCount; ++i)
        {
            const float* c = &colors.values[i * n];
            const osg::Vec4 color(c[0], c[1], c[2], n == 4 ? c[3] : 1.0f);
            (*array)[unsigned(i)] = osg::componentMultiply(color, factor);
        }
        geometry->setColorArray(array.get(), osg::Array::BIND_PER_VERTEX);
    }

    if (primitive.indices >= 0)
    {
        const std::vector<std::uint32_t> indices = readIndexAccessor(model, primitive.indices, vertexCount);
        osg::ref_ptr<osg::DrawElementsUInt> elements = new osg::DrawElementsUInt(mode, indices.begin(), indices.end());
        geometry->addPrimitiveSet(elements.get());
    }
    else if (vertexCount > 0)
        geometry->addPrimitiveSet(new osg::DrawArrays(mode, 0, GLsizei(vertexCount)));
    const bool surface = mode == GL_TRIANGLES || mode == GL_TRIANGLE_STRIP || mode == GL_TRIANGLE_FAN;
    if (normalAccessor < 0)
    {
        if (surface && allFinite(positions))
            osgUtil::SmoothingVisitor::smooth(*geometry);
        else if (surface)
        {
            // note: the smoother keys vertices by position in an ordered set; NaN breaks its ordering
            // and crashes it (found by fuzzing). Such a mesh gets one normal.
            osg::ref_ptr<osg::Vec3Array> up = new osg::Vec3Array;
            up->push_back(osg::Vec3(0, 0, 1));
            geometry->setNormalArray(up.get(), osg::Array::BIND_OVERALL);
        }
        else
        {
            // Points and lines without normals have nothing to light; show their base colour as it is.
            osg::ref_ptr<osg::StateSet> unlit = new osg::StateSet(*geometry->getStateSet(), osg::CopyOp::SHALLOW_COPY);
            unlit->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
            geometry->setStateSet(unlit.get());
            if (colorAccessor < 0)
            {
                osg::ref_ptr<osg::Vec4Array> baseColor = new osg::Vec4Array;
                baseColor->push_back(materials.baseColorFactor(primitive.material));
                geometry->setColorArray(baseColor.get(), osg::Array::BIND_OVERALL);
            }
        }
    }
    return geometry;
}
} // namespace

osg::ref_ptr<osg::Geode> buildMesh(const tinygltf::Model& model, int meshIndex, MaterialBuilder& materials)
{
    checkReference("a node", "mesh", meshIndex, model.meshes.size());
    const tinygltf::Mesh& mesh = model.meshes[std::size_t(meshIndex)];
    if (mesh.primitives.empty())
        throw GltfError("mesh " + std::to_string(meshIndex) + " has no primitives (glTF requires at least one)");
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->setName(mesh.name.empty() ? "mesh" + std::to_string(meshIndex) : mesh.name);
    for (std::size_t i = 0; i < mesh.primitives.size(); ++i)
    {
        osg::ref_ptr<osg::Geometry> geometry =
            buildPrimitive(model, mesh.primitives[i], geode->getName() + "#" + std::to_string(i), materials);
        geometry->setUserValue(GltfPrimitiveKey, int(i));
        geode->addDrawable(geometry.get());
    }
    return geode;
}
} // namespace osgVis::gltfplugin
