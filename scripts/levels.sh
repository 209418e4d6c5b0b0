#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The real set, in one table: every deathmatch (ffa) map of Debian's openarena-088-data that OSG's
# bsp plugin loads and the Khronos 2CylinderEngine.glb (assimp-testmodels), each on its automatic
# walk, benchmarked mode by mode against the exact-visibility oracle (docs/benchmark.md, "The real
# set"). The oracle's exact sets are cached, so a second run renders no oracle.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

usage() {
    cat <<EOF
usage: scripts/levels.sh [--out DIR] [--cache DIR] [--modes LIST] [--size WxH] [--models A,B,...]
                         [--bench PATH] [--list] [-- EXTRA osgvisbench ARGUMENTS]

Runs osgvisbench over the real set and prints one table (scripts/levels-table.py): per model its
objects and triangles, and per mode the cull time osgVis's chain took (ms median/p99, one core),
OSG's whole cull traversal, occlusion efficacy, drawn %, exact's drawn % and false-invisible
objects, then the issue-44 acceptance checks per model.

  --out DIR      per-model JSON and text reports (default: build/levels)
  --cache DIR    extracted maps and the oracle cache (default: \${XDG_CACHE_HOME:-~/.cache}/osgvis/levels)
  --modes LIST   osgvisbench modes (default: osg,frustum,octree,mask,cdt,exact)
  --size WxH     view size (default: 1280x1024)
  --models LIST  only these (map names without .bsp, or 2CylinderEngine); default: all of them
  --bench PATH   the osgvisbench binary (default: build/bin/osgvisbench)
  --list         print the models of the set and exit
Needs openarena-088-data and assimp-testmodels (scripts/deps.sh installs both), and a display
or Xvfb. Every map is read by OSG's own bsp plugin; llvmpipe renders single-threaded
(LP_NUM_THREADS=1) so the cull timings share no core with it.
EOF
}

out=$root/build/levels
cache=${XDG_CACHE_HOME:-$HOME/.cache}/osgvis/levels
modes=osg,frustum,octree,mask,cdt,exact
size=1280x1024
models=
bench=$root/build/bin/osgvisbench
list=0
extra=()
while [ $# -gt 0 ]; do
    case $1 in
        --out) out=$2; shift 2 ;;
        --cache) cache=$2; shift 2 ;;
        --modes) modes=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        --models) models=$2; shift 2 ;;
        --bench) bench=$2; shift 2 ;;
        --list) list=1; shift ;;
        -h|--help) usage; exit 0 ;;
        --) shift; extra=("$@"); break ;;
        *) echo "levels.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done

pak=/usr/share/games/openarena/baseoa/pak6-patch088.pk3
engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
for need in "$pak" "$engine"; do
    if [ ! -f "$need" ]; then
        echo "levels.sh: $need is missing: install openarena-088-data and assimp-testmodels" >&2
        exit 1
    fi
done

# The ffa maps that arenas.txt names and the pak holds (the others live in packages OSG reads too,
# but the set is this one release's deathmatch maps).
mkdir -p "$cache/maps" "$out"
if [ ! -f "$cache/maps/ffa.txt" ]; then
    unzip -o -q "$pak" 'scripts/arenas.txt' 'maps/*.bsp' -d "$cache/pak"
    python3 - "$cache/pak/scripts/arenas.txt" "$cache/pak/maps" > "$cache/maps/ffa.txt.part" <<'EOF'
import os, re, sys
text = open(sys.argv[1], encoding="latin-1").read()
for block in re.findall(r"\{(.*?)\}", text, re.S):
    name, kinds = re.search(r'map\s+"([^"]+)"', block), re.search(r'type\s+"([^"]+)"', block)
    if name and kinds and "ffa" in kinds.group(1).split() and os.path.exists(os.path.join(sys.argv[2], name.group(1) + ".bsp")):
        print(name.group(1))
EOF
    sort -u "$cache/maps/ffa.txt.part" > "$cache/maps/ffa.txt" && rm "$cache/maps/ffa.txt.part"
    while read -r map; do cp "$cache/pak/maps/$map.bsp" "$cache/maps/"; done < "$cache/maps/ffa.txt"
fi
all=$(tr '\n' ' ' < "$cache/maps/ffa.txt")2CylinderEngine
if [ "$list" = 1 ]; then
    echo "$all" | tr ' ' '\n'
    exit 0
fi
if [ -n "$models" ]; then
    for m in ${models//,/ }; do
        case " $all " in *" $m "*) ;; *) echo "levels.sh: '$m' is not in the real set (see --list)" >&2; exit 2 ;; esac
    done
    all=${models//,/ }
fi
if [ ! -x "$bench" ]; then
    echo "levels.sh: $bench is not built (cmake --build build --target osgvisbench)" >&2
    exit 1
fi

start=$(date +%s)
count=$(echo "$all" | wc -w)
i=0
for m in $all; do
    i=$((i + 1))
    if [ "$m" = 2CylinderEngine ]; then scene=$engine; else scene=$cache/maps/$m.bsp; fi
    echo "levels.sh: [$i/$count] $m ($(($(date +%s) - start)) s so far)" >&2
    if ! LP_NUM_THREADS=1 bash "$root/scripts/with-display.sh" "$bench" --scene "$scene" --modes "$modes" \
        --size "$size" --oracle-cache "$cache/oracle" --json "$out/$m.json" "${extra[@]}" \
        > "$out/$m.txt" 2> "$out/$m.log"; then
        echo "levels.sh: $m failed; see $out/$m.log" >&2
        tail -5 "$out/$m.log" >&2
        exit 1
    fi
done
echo "levels.sh: $count models in $(($(date +%s) - start)) s" >&2
files=()
for m in $all; do files+=("$out/$m.json"); done
python3 "$root/scripts/levels-table.py" "${files[@]}"
