#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every source, header, script and CMake file of osgVis carries "SPDX-License-Identifier: MIT" in
# its first three lines (after a shebang or an editor mode line). Lists the files that do not and
# exits 1 when there is one. Reads git's file list, or every file below the tree outside git.
#   scripts/check-spdx.sh [DIR]   (default: this repository)
set -euo pipefail
top=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$top"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    list() { git ls-files --cached --others --exclude-standard; }
else
    list() { find . -type f -not -path './build*' -not -path './.git/*' | sed 's|^\./||'; }
fi
checked=0 missing=0
while IFS= read -r file; do
    name=${file##*/}
    case "$file" in
        *.cpp | *.h | *.c | *.sh | *.cmake | *.cmake.in | *.pc.in | */CMakeLists.txt | CMakeLists.txt | .ci/run) ;;
        osgvis/osg/include/osgVis/*) [[ "$name" == *.* ]] && continue ;; # OSG-style extension-less headers
        *) continue ;;
    esac
    [ -f "$file" ] || continue
    checked=$((checked + 1))
    if ! head -n 3 "$file" | grep -q 'SPDX-License-Identifier: MIT'; then
        echo "no SPDX line: $file"
        missing=$((missing + 1))
    fi
done < <(list)
echo "spdx: $checked files checked, $missing without 'SPDX-License-Identifier: MIT'"
[ "$missing" -eq 0 ]
