// SPDX-License-Identifier: MIT
#pragma once
// Seeded test scenes and their walks: the office floor, the city and the field of tetrahedra of the
// papers' benchmarks, scaled by a triangle budget, plus a set of small adversarial scenes that every
// culling mode must pass. The same options give byte-identical geometry on every machine.
// Presets (layout, tessellation, walk speed, projection) are frozen: see docs/scenes.md.
#include <osgVis/core/scene/Walk.h>

#include <osg/Group>
#include <osg/ref_ptr>

#include <cstdint>
#include <string>
#include <vector>

namespace osgVis::gen
{
enum class SceneKind
{
    Office, // furnished office floors: rooms, corridors, doors (cell-portal paper)
    City,   // street grid with blocks of tall buildings (occlusion-mask paper)
    Tetra,  // randomly sized and oriented tetrahedra scattered on a plane (octree paper)
    Floor   // one office storey of fixed size, ~2 300 objects, corridor walk (cell-portal paper's floor)
};

struct GenerateOptions
{
    SceneKind kind = SceneKind::Office;
    std::uint64_t triangles = 100000; // generated count lands within ±10% of this (2k … 50M)
    std::uint32_t seed = 1;
};

struct GeneratedScene
{
    osg::ref_ptr<osg::Group> root; // Z up, metres
    core::Walk walk;               // one fixed projection whose far plane contains the whole scene
};

// Throws std::invalid_argument for a triangle budget outside [minTriangles, maxTriangles], or below
// minTrianglesFor(kind).
GeneratedScene generate(const GenerateOptions& options);

constexpr std::uint64_t minTriangles = 1000;
constexpr std::uint64_t maxTriangles = 50000000;

// The budget osgvisgen uses when none is given: 300 000 for Floor (the paper's floor has ~250k
// polygons), otherwise 100 000 (GenerateOptions' default).
std::uint64_t defaultTriangles(SceneKind kind);
// Smallest budget the kind can meet: Floor's fixed layout has a fixed coarsest meshing.
std::uint64_t minTrianglesFor(SceneKind kind);

// "office" | "city" | "tetra" | "floor"; throws std::invalid_argument naming the known kinds.
SceneKind parseSceneKind(const std::string& name);
const char* sceneKindName(SceneKind kind);
std::vector<std::string> sceneKindNames();

// Adversarial set: named small scenes with short walks, each built to trip one known way culling
// goes wrong (DESIGN.md). Names: thin-slit, frame-edges, off-centre, ortho, degenerate-occluders,
// eye-on-occluder-plane, geode-one-hidden, moving-occluder.
std::vector<std::string> adversarialSceneNames();
// Throws std::invalid_argument naming the known scenes.
GeneratedScene adversarialScene(const std::string& name);
} // namespace osgVis::gen
