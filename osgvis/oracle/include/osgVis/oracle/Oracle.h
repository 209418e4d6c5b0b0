// SPDX-License-Identifier: MIT
#pragma once

// The exact-visibility oracle: ID-buffer render of the real OSG graph, and CPU ray casting.
#include <osgVis/oracle/IdBufferOracle.h>
#include <osgVis/oracle/OracleObject.h>
#include <osgVis/oracle/RayCast.h>
