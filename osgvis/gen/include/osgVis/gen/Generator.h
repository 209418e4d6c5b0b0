// SPDX-License-Identifier: MIT
#pragma once
// Seeded test scenes and their walks: the office floor, the city, the field of tetrahedra and the
// forest of the papers' benchmarks, scaled by a triangle budget, plus a set of small adversarial scenes that every
// culling mode must pass. The same options give byte-identical geometry on every machine.
// Presets (layout, tessellation, walk speed, projection) are frozen: see docs/scenes.md.
#include <osgVis/core/scene/Walk.h>
#include <osgVis/gen/Forest.h>

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
    Floor,  // one office storey of fixed size, ~2 300 objects, corridor walk (cell-portal paper's floor)
    Forest  // closed-surface trees in one of three layouts (multifocal z-buffer paper), Forest.h
};

struct GenerateOptions
{
    SceneKind kind = SceneKind::Office;
    std::uint64_t triangles = 100000; // generated count lands within ±10% of this (2k … 50M)
    std::uint32_t seed = 1;
    ForestLayout forestLayout = ForestLayout::Dense; // Forest only: how many trees, and where
};

struct GeneratedScene
{
    osg::ref_ptr<osg::Group> root; // Z up, metres
    core::Walk walk;               // one fixed projection whose far plane contains the whole scene
};

// Throws std::invalid_argument for a triangle budget outside [minTriangles, maxTriangles], or below
// minTrianglesFor(kind, forestLayout).
GeneratedScene generate(const GenerateOptions& options);

constexpr std::uint64_t minTriangles = 1000;
constexpr std::uint64_t maxTriangles = 50000000;

// The budget osgvisgen uses when none is given: 300 000 for Floor (the paper's floor has ~250k
// polygons), for Forest 12 000 a tree (12 000, 72 000, 385 000: the paper's scenes), otherwise
// 100 000 (GenerateOptions' default). `layout` matters for Forest only.
std::uint64_t defaultTriangles(SceneKind kind, ForestLayout layout = ForestLayout::Dense);
// Smallest budget the kind can meet: Floor's and Forest's fixed layouts have a fixed coarsest meshing.
std::uint64_t minTrianglesFor(SceneKind kind, ForestLayout layout = ForestLayout::Dense);

// "office" | "city" | "tetra" | "floor" | "forest"; throws std::invalid_argument naming the known kinds.
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
