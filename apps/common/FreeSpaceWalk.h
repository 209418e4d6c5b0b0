// SPDX-License-Identifier: MIT
#pragma once
// A walk through a model's free space, for models that come without one: eyes at a person's height
// above surfaces one could stand on, never inside solid geometry, each looking along the freest
// horizontal directions. How eyes are chosen (docs/walk-format.md, "Automatic walks"):
//  1. Candidate floor points: random points on upward-facing triangles (normal within 35 degrees
//     of +z), area-weighted, seeded.
//  2. Eye height from the model's own scale: where a candidate has a ceiling (the ray up meets
//     something), 0.55 × the median of those clearances (a 3 m room gives 1.65); with
//     ceilings above fewer than a quarter of the candidates, 1.7 units (metres, as glTF's unit)
//     unless that is more than a tenth of the model's horizontal size.
//  3. A candidate becomes an eye 1 eye height above its floor point if the ceiling is at least
//     1.25 eye heights up (and there is a ceiling at all, in a model whose eye height came from its
//     ceilings: an indoor model is walked indoors, not on its roof), the eye is clearly outside solid
//     geometry (at most a quarter of 64 rays first meet a back face, RayHit::backFace; insideSolid,
//     more than half, is the definition) and no wall is nearer than a quarter eye height in any of 16
//     horizontal directions.
//  4. Stations spread by farthest-point sampling over the eyes, visited in nearest-neighbour order;
//     each gives up to `gazesPerStation` keys looking along the horizontal directions (of 16) that
//     run farthest before meeting geometry, at least 60 degrees apart and at least one eye height
//     free (the freest one always); or, with randomGaze, random gazes from jittered eyes.
#include "RayScene.h"

#include <osgVis/core/scene/Walk.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace osgVis::apps
{
struct FreeSpaceWalkOptions
{
    unsigned stations = 40;        // eyes the walk visits
    unsigned gazesPerStation = 3;  // keys per eye, one per free direction
    unsigned candidates = 4000;    // floor points tried
    double secondsPerKey = 0.5;    // walk time between keys
    std::uint32_t seed = 1;
    double fovYDegrees = 60.0;
    unsigned width = 1280, height = 1024;
    // Instead of step 4's free directions: gazes uniform on the sphere from eyes jittered by up to a
    // fifth of the eye height (views nobody tuned, for contract checks).
    bool randomGaze = false;
};

struct FreeSpaceWalkReport
{
    unsigned candidates = 0;        // floor points tried
    unsigned withCeiling = 0;       // of those, with something above
    unsigned lowCeiling = 0;        // rejected: less than 1.25 eye heights of room above
    unsigned openSky = 0;           // rejected: nothing above, in a model walked indoors
    unsigned insideSolid = 0;       // rejected: eye inside solid geometry
    unsigned doubtful = 0;          // rejected: a quarter to a half of the rays meet a back face
    unsigned nearWall = 0;          // rejected: a wall nearer than a quarter eye height
    unsigned eyes = 0;              // accepted
    unsigned stations = 0;          // eyes the walk visits
    double eyeHeight = 0.0;         // world units
    std::string eyeHeightRule;      // how eyeHeight was found, for the user
};

struct FreeSpaceWalkError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

// Throws FreeSpaceWalkError when the model has no upward surface or no candidate passes.
core::Walk makeFreeSpaceWalk(const RayScene& rays, const FreeSpaceWalkOptions& options = {},
                             FreeSpaceWalkReport* report = nullptr);
} // namespace osgVis::apps
