#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Prints the include graph between the folders of osgvis/core, read from the compiler's own
# dependency output (c++ -MM on every source and header), and checks the layers of
# docs/architecture.md: a folder may include only folders of lower layers, so there is no arrow
# upwards, none inside a layer, and none between two method folders. Exits 1 on any violation.
#
#   scripts/core-include-graph.sh [--root DIR]   (DIR: a tree laid out like osgvis/core; default ours)
#
# The arrows printed are the direct includes (the transitive reduction of -MM's closure at file
# level); the check runs on the whole closure, so an include reached only indirectly counts too.
# CXX chooses the compiler (default c++).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)/osgvis/core
if [ "${1:-}" = "--root" ]; then
    root=$(cd "$2" && pwd)
elif [ $# -gt 0 ]; then
    sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
fi
cxx=${CXX:-c++}

# Layer of each folder: an arrow A -> B is allowed only when B's layer is lower than A's.
# The C header osgVis/visapi.h belongs to capi/ (its accessors); plugin/ (modules behind the C
# callbacks) is a method; visapi/ (the renderer side of the C interface) sits on the registry.
layers='geometry:0 scene:1 spatial:2 occluders:2 pvs:3 module:3 capi:3
frustum:4 octree:4 cellportal:4 mask:4 multifocal:4 cdt:4 plugin:4 api:5 async:6 session:7 visapi:8'

# Folder of a path under the core ("-" for the forwarding headers at the old flat paths).
folder_of() {
    case "$1" in
        "$root"/include/osgVis/visapi.h) echo capi ;;
        "$root"/include/osgVis/core/*/*) local rest=${1#"$root"/include/osgVis/core/}; echo "${rest%%/*}" ;;
        "$root"/src/*/*) local rest=${1#"$root"/src/}; echo "${rest%%/*}" ;;
        *) echo "-" ;;
    esac
}

deps=$(mktemp)
trap '[ -n "${KEEP_DEPS:-}" ] && cp "$deps" "$KEEP_DEPS"; rm -f "$deps"' EXIT
files=$( (find "$root/src" "$root/include/osgVis/core" -mindepth 2 \( -name '*.cpp' -o -name '*.h' \); [ -f "$root/include/osgVis/visapi.h" ] && echo "$root/include/osgVis/visapi.h") | sort)
[ -n "$files" ] || { echo "core-include-graph: no sources under $root" >&2; exit 2; }
for file in $files; do
    # One line per file: the file, then every non-system header it reaches, as absolute paths.
    out=$("$cxx" -std=c++17 -x c++ -MM -I"$root/include" "$file" 2>&1) ||
        { echo "core-include-graph: $cxx -MM failed on $file:" >&2; echo "$out" >&2; exit 2; }
    echo "$file $file" >> "$deps"
    set -- $(printf '%s' "$out" | tr -d '\\') # target, the file itself, then its headers
    shift
    for dep in "$@"; do echo "$file $(realpath -m "$dep")"; done >> "$deps"
done

# file -> folder for every file and dependency seen.
awk -v root="$root" -v layers="$layers" '
function folder(p,   rest) {
    if (p == root "/include/osgVis/visapi.h") return "capi"
    if (index(p, root "/include/osgVis/core/") == 1) { rest = substr(p, length(root "/include/osgVis/core/") + 1) }
    else if (index(p, root "/src/") == 1) { rest = substr(p, length(root "/src/") + 1) }
    else return "-"
    if (index(rest, "/") == 0) return "-"
    return substr(rest, 1, index(rest, "/") - 1)
}
BEGIN {
    n = split(layers, entries, /[ \n]+/)
    for (i = 1; i <= n; ++i) { split(entries[i], kv, ":"); level[kv[1]] = kv[2] + 0; order[++folders] = kv[1] }
}
{ present[folder($1)] = 1 }
$1 != $2 { closure[$1, $2] = 1; reach[$1] = reach[$1] " " $2; seen[$1] = 1 }
END {
    bad = 0
    for (key in closure) {
        split(key, fd, SUBSEP); a = folder(fd[1]); b = folder(fd[2])
        if (a == "-" || a == b) continue
        if (b == "-") { printf "VIOLATION: %s reaches %s, outside the core'"'"'s folders (a forwarding header? use the folder path)\n", fd[1], fd[2]; bad = 1; continue }
        if (!(a in level) || !(b in level)) { printf "VIOLATION: folder %s or %s has no layer (add it to this script and docs/architecture.md)\n", a, b; bad = 1; continue }
        if (level[b] >= level[a]) {
            why = level[b] == level[a] ? (level[a] == 4 ? "between two methods" : "inside one layer") : "upwards"
            printf "VIOLATION: %s -> %s (%s): %s reaches %s\n", a, b, why, fd[1], fd[2]; bad = 1
        }
    }
    # Direct includes: a dependency not reached through another dependency of the same file.
    for (key in closure) {
        split(key, fd, SUBSEP); f = fd[1]; d = fd[2]; direct = 1
        m = split(reach[f], others, " ")
        for (j = 1; j <= m && direct; ++j)
            if (others[j] != d && ((others[j], d) in closure)) direct = 0
        if (!direct) continue
        a = folder(f); b = folder(d)
        if (a == b || a == "-") continue
        edge[a, b] = 1; count[a, b]++
    }
    print "osgvis/core include graph (from c++ -MM): A -> B (n) says n files of A include a header of B"
    print "(an include already reached through another included header is left out of the picture)"
    for (i = folders; i >= 1; --i) {
        a = order[i]; line = ""
        for (j = 1; j <= folders; ++j) { b = order[j]; if ((a, b) in edge) line = line (line ? ", " : "") b " (" count[a, b] ")" }
        if (!(a in present)) continue
        if (line) printf "  %-10s -> %s\n", a, line
        else printf "  %-10s    (includes no other folder)\n", a
    }
    print "layers, lowest first: geometry | scene | spatial, occluders | pvs, module, capi | frustum, octree, cellportal, mask, multifocal, cdt, plugin (methods) | api | async, visapi"
    if (bad) { print "include layers: VIOLATED (see above)"; exit 1 }
    print "include layers: ok (every include, direct or not, points to a lower layer; no arrow between methods)"
}' "$deps"
