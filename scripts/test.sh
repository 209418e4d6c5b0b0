#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start #2: installs dependencies, builds, and runs the whole test suite (under Xvfb when
# there is no display). Extra arguments go to ctest, e.g. `scripts/test.sh -L core`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${OSGVIS_BUILD_DIR:-$root/build}
bash "$root/scripts/deps.sh"
OSGVIS_BUILD_DIR=$build bash "$root/scripts/build.sh"
cd "$build"
bash "$root/scripts/with-display.sh" ctest --output-on-failure -j"$(nproc)" "$@"
