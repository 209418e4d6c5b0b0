#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# ThreadSanitizer build of the threaded tests: region queries and AsyncVisibility (core, the
# worker thread), the octree's parallel traversal (TBB) and every OSG threading model with two
# views sync and async (adapter, under a display). Builds into ${OSGVIS_TSAN_BUILD_DIR:-build-tsan};
# a TSan report fails the test. Suppressions (uninstrumented Mesa/libstdc++ only): share/tsan.supp.
# `scripts/tsan.sh core` builds and runs only the core tests (what CI runs: no GL, no Mesa threads).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${OSGVIS_TSAN_BUILD_DIR:-$root/build-tsan}
targets=(osgvis_core_region_tests osgvis_core_octree_tests osgvis_osg_threading)
tests='^(RegionQueries|AsyncVisibility|OctreeModule|ThreadingModels)\.'
if [ "${1:-}" = core ]; then
    targets=(osgvis_core_region_tests osgvis_core_octree_tests)
    tests='^(RegionQueries|AsyncVisibility|OctreeModule)\.'
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOSGVIS_TSAN=ON
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}"
cd "$build"
bash "$root/scripts/with-display.sh" ctest --output-on-failure -j"$(nproc)" -R "$tests"
