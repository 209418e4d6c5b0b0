#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs a command with an X display: the caller's if there is one, else a private Xvfb (Mesa
# llvmpipe gives OpenGL 4.5 there).
#
# An X server resets when its last client leaves, and a client connecting in that moment is
# refused ("Failed to open display"): an app test that starts one GL process right after another
# failed so in CI. Our Xvfb runs with -noreset; on the caller's display an idle client (xev on the
# root window) stays connected while the command runs.
set -euo pipefail
if [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1; then
    xev -root >/dev/null 2>&1 &
    holder=$!
    trap 'kill "$holder" 2>/dev/null || true' EXIT
    "$@"
    exit $?
fi
exec xvfb-run -a -s "-screen 0 1920x1080x24 +extension GLX -noreset" "$@"
