#!/bin/bash
# SPDX-License-Identifier: MIT
# usage: run.sh BIN_DIR OUT_DIR  (issue 46: per-view digests before/after)
B=$1; O=$2; mkdir -p $O; cd $O
M=osg,frustum,octree,mask,exact
S="--size 640x512"
set -x
$B/osgvisbench --generate city --triangles 100000 --seed 1 --views 60 $S --modes $M --json city100k.json > city.log 2>&1
$B/osgvisbench --generate office --triangles 100000 --seed 1 --views 40 $S --modes $M --json office100k.json > office.log 2>&1
$B/osgvisgen --kind floor --triangles 100000 --seed 1 -o floor.osgb > floor.log 2>&1 && $B/osgvispvs floor.osgb -o floor.pvs >> floor.log 2>&1
$B/osgvisbench --scene floor.pvs --modes osg,frustum,cellportal,exact --views 40 $S --json floor.json >> floor.log 2>&1
$B/osgvisbench --scene /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb --views 40 $S --modes $M --json engine.json > engine.log 2>&1
for m in am_underworks2 oa_koth2; do
  $B/osgvisbench --scene ~/.cache/osgvis/levels/maps/$m.bsp --views 40 $S --modes $M --json $m.json > $m.log 2>&1
done
$B/osgvisbench --generate city --triangles 100000 --seed 1 --size 640x512 --views 60 --modes osg,frustum+octree --threading SingleThreaded,DrawThreadPerContext --json threading.json > threading.log 2>&1
echo done > DONE
