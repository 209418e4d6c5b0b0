// SPDX-License-Identifier: MIT
#pragma once

// The exact-visibility oracle: ID-buffer render of the real OSG graph (objects and triangles), CPU ray
// casting, and the sampled visibility from a box of viewpoints.
#include <osgVis/oracle/CubeFaceViews.h>
#include <osgVis/oracle/IdBufferOracle.h>
#include <osgVis/oracle/OracleObject.h>
#include <osgVis/oracle/RayCast.h>
#include <osgVis/oracle/TriangleIdOracle.h>
#include <osgVis/oracle/VolumeEyes.h>
#include <osgVis/oracle/VolumeOracle.h>
