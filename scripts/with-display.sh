#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs a command with an X display: the caller's if there is one, else a private Xvfb (Mesa
# llvmpipe gives OpenGL 4.5 there).
set -euo pipefail
if [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1; then
    exec "$@"
fi
exec xvfb-run -a -s "-screen 0 1920x1080x24 +extension GLX" "$@"
