#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# usage: check-installed-tree.sh BUILD_DIR CONSUMER_SOURCE WORK_DIR
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for f in include/osgVis/VisibilityGroup include/osgVis/core/module/VisibilityModule.h include/osgVis/visapi.h \
         lib/osgvis-modules/osgvis_module_cfrustum.so \
         lib/cmake/osgVis/osgVisConfig.cmake lib/pkgconfig/osgVis.pc; do
    [ -e "$prefix/$f" ] || { echo "installed tree lacks $f" >&2; exit 1; }
done
ls "$prefix"/lib/libosgVis.so* "$prefix"/lib/libosgVisCore.so* >/dev/null
plugins=$(echo "$prefix"/lib/osgPlugins-*)
for p in osgdb_pvs osgdb_gltf osgdb_serializers_osgvis; do
    [ -e "$plugins/$p.so" ] || { echo "installed tree lacks $plugins/$p.so" >&2; exit 1; }
done

# The README's first C++ block, as a user would paste it.
awk '/^```cpp$/ {on=1; next} /^```$/ && on {exit} on' "$src/../../../README.md" >"$work/readme_example.cpp"
grep -q "osgVis::VisibilityGroup" "$work/readme_example.cpp"

echo "== find_package(osgVis)"
cmake -S "$src" -B "$work/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" \
    -DREADME_EXAMPLE="$work/readme_example.cpp" >"$work/configure.log"
cmake --build "$work/cmake-build" >"$work/build.log" 2>&1 || { cat "$work/build.log" >&2; exit 1; }
out=$("$work/cmake-build/osgvis_consumer")
echo "$out"
grep -q "consumer ok" <<<"$out"

echo "== no flat core header paths (the forwarding headers of osgVis 0.1 are gone)"
flat=$(find "$prefix/include/osgVis/core" -maxdepth 1 -name '*.h')
[ -z "$flat" ] || { echo "headers left directly under include/osgVis/core: $flat" >&2; exit 1; }

[ -x "$work/cmake-build/readme_example" ] || { echo "the README example did not build" >&2; exit 1; }

echo "== pkg-config osgVis (the .pc finds its prefix from where it lies)"
flags=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs osgVis)
c++ -std=c++17 "$src/main.cpp" -o "$work/pc_consumer" $flags -Wl,-rpath,"$prefix/lib"
out=$("$work/pc_consumer")
echo "$out"
grep -q "consumer ok" <<<"$out"

echo "== a C99 program on the C interface (visapi.h), its plugin mode found beside the installed library"
cc -std=c99 -pedantic -Wall -Wextra -Werror "$src/visapi_consumer.c" -o "$work/visapi_consumer" -I"$prefix/include" \
    -L"$prefix/lib" -losgVisCore -Wl,-rpath,"$prefix/lib"
out=$(env -u OSGVIS_MODULE_PATH "$work/visapi_consumer")
echo "$out"
grep -q "visapi consumer ok (1 visible)" <<<"$out"

echo "== stock osgconv with the installed plugins"
if command -v osgconv >/dev/null; then
    export OSG_LIBRARY_PATH="$prefix/lib" LD_LIBRARY_PATH=
    osgconv "$src/../../../data/osgvis-demo.osgt" "$work/demo.osgb" >"$work/osgconv.log" 2>&1
    osgconv "$work/demo.osgb" "$work/demo-again.osgt" >>"$work/osgconv.log" 2>&1
    grep -q "osgVis::VisibilityGroup" "$work/demo-again.osgt"
    model=/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb
    if [ -e "$model" ]; then
        osgconv "$model" "$work/box.osgt" >>"$work/osgconv.log" 2>&1
        grep -q "osg::Geometry" "$work/box.osgt"
    fi
    echo "osgconv ok"
fi
