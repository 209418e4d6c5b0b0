#!/usr/bin/env bash
# usage: check-installed-tree.sh BUILD_DIR CONSUMER_SOURCE WORK_DIR
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
for f in include/osgVis/VisibilityGroup include/osgVis/core/VisibilityModule.h \
         lib/cmake/osgVis/osgVisConfig.cmake lib/pkgconfig/osgVis.pc; do
    [ -e "$prefix/$f" ] || { echo "installed tree lacks $f" >&2; exit 1; }
done
ls "$prefix"/lib/libosgVis.so* "$prefix"/lib/libosgVisCore.so* >/dev/null

echo "== find_package(osgVis)"
cmake -S "$src" -B "$work/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" >"$work/configure.log"
cmake --build "$work/cmake-build" >"$work/build.log"
out=$("$work/cmake-build/osgvis_consumer")
echo "$out"
grep -q "consumer ok" <<<"$out"

echo "== pkg-config osgVis"
sed -i "s|^prefix=.*|prefix=$prefix|" "$prefix/lib/pkgconfig/osgVis.pc"
flags=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs osgVis)
c++ -std=c++17 "$src/main.cpp" -o "$work/pc_consumer" $flags -Wl,-rpath,"$prefix/lib"
out=$("$work/pc_consumer")
echo "$out"
grep -q "consumer ok" <<<"$out"
