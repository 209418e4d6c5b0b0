// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Vector types of the core. Geometry runs in double precision (robust plane tests); bulk triangle
/// storage is single precision to keep multi-million-triangle scenes small.
#include <glm/glm.hpp>

namespace osgVis::core
{
using Vec3 = glm::dvec3;
using Vec4 = glm::dvec4;
using Mat4 = glm::dmat4;
using Vec3f = glm::vec3;
} // namespace osgVis::core
