#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Seeds for osgvis_q3solids_fuzzer (tests/fuzz/README.md): a small hand-made IBSP 46 level (an axial
# box with a caulked side, a brush with a diagonal side, a water brush, a door, spawn points), and,
# for each .bsp named, a cut-down copy of that real level: its first brushes of the world, the
# planes and sides they use, every shader, the worldspawn and spawn-point entities, no other lump.
# Small seeds keep the fuzzer fast. Usage: q3solids_seeds.py OUT_DIR [level.bsp ...]
import os
import re
import struct
import sys

LUMPS = 17
SOLID, WATER, TRANSLUCENT, NODRAW = 0x1, 0x20, 0x20000000, 0x80


def ibsp(lumps):
    """The file: header then the lumps in order, every absent lump empty."""
    blobs = [lumps.get(i, b"") for i in range(LUMPS)]
    out, offset = [b"IBSP", struct.pack("<i", 46)], 8 + 8 * LUMPS
    for blob in blobs:
        out.append(struct.pack("<ii", offset, len(blob)))
        offset += len(blob)
    return b"".join(out + blobs)


def shader(name, surface, contents):
    return name.encode().ljust(64, b"\0")[:64] + struct.pack("<ii", surface, contents)


def synthetic():
    planes, sides, brushes = [], [], []

    def brush(shader_index, faces):
        brushes.append(struct.pack("<3i", len(sides), len(faces), shader_index))
        for normal, dist, side_shader in faces:
            planes.append(struct.pack("<4f", *normal, dist))
            sides.append(struct.pack("<2i", len(planes) - 1, side_shader))

    def box(shader_index, lo, hi, side_shaders):
        axes = [(1, 0, 0), (0, 1, 0), (0, 0, 1)]
        faces = []
        for a in range(3):
            faces.append((tuple(-v for v in axes[a]), -lo[a], side_shaders[2 * a]))
            faces.append((axes[a], hi[a], side_shaders[2 * a + 1]))
        brush(shader_index, faces)

    box(0, (0, 16, -8), (64, 48, 8), (0, 0, 1, 0, 0, 0))
    r = 0.5 ** 0.5
    brush(0, [((-1, 0, 0), -200, 0), ((1, 0, 0), 264, 0), ((0, -1, 0), 0, 0), ((0, 1, 0), 64, 0),
              ((0, 0, -1), 0, 0), ((0, 0, 1), 64, 0), ((r, 0, r), 300 * r, 0)])
    box(2, (0, 0, 0), (16, 16, 16), (2,) * 6)
    box(0, (500, 0, 0), (532, 32, 32), (0,) * 6)
    models = struct.pack("<6f4i", -512, -512, -512, 1024, 1024, 1024, 0, 0, 0, 3)
    models += struct.pack("<6f4i", 500, 0, 0, 532, 32, 32, 0, 0, 3, 1)
    entities = (b'{\n"classname" "worldspawn"\n}\n{\n"classname" "info_player_deathmatch"\n'
                b'"origin" "32 -64 24"\n}\n{\n"origin" "10 20 30"\n"classname" "team_CTF_redspawn"\n}\n\0')
    shaders = (shader("textures/base_wall/concrete", 0, SOLID) + shader("textures/common/caulk", NODRAW, SOLID)
               + shader("textures/liquids/calm", 0, WATER | TRANSLUCENT))
    return ibsp({0: entities, 1: shaders, 2: b"".join(planes), 7: models, 8: b"".join(brushes),
                 9: b"".join(sides)})


def cut_down(path, keep_brushes=24):
    data = open(path, "rb").read()
    lumps = [struct.unpack_from("<ii", data, 8 + 8 * i) for i in range(LUMPS)]

    def records(index, size):
        offset, length = lumps[index]
        return [data[offset + k * size: offset + (k + 1) * size] for k in range(length // size)]

    planes, brushes, sides = records(2, 16), records(8, 12), records(9, 8)
    world = struct.unpack("<6f4i", records(7, 40)[0])
    first, count = world[8], min(world[9], keep_brushes)
    plane_map, new_planes, new_sides, new_brushes = {}, [], [], []
    for b in range(first, first + count):
        first_side, side_count, brush_shader = struct.unpack("<3i", brushes[b])
        new_brushes.append(struct.pack("<3i", len(new_sides), side_count, brush_shader))
        for s in range(first_side, first_side + side_count):
            plane, side_shader = struct.unpack("<2i", sides[s])
            if plane not in plane_map:
                plane_map[plane] = len(new_planes)
                new_planes.append(planes[plane])
            new_sides.append(struct.pack("<2i", plane_map[plane], side_shader))
    models = struct.pack("<6f4i", *world[:6], 0, 0, 0, count)
    offset, length = lumps[0]
    text = data[offset: offset + length].split(b"\0")[0].decode("latin-1")
    keep = [e for e in re.findall(r"\{[^{}]*\}", text)
            if re.search(r'"classname"\s+"(worldspawn|info_player_\w+|team_CTF_\w+)"', e)][:6]
    entities = ("\n".join(keep) + "\n").encode("latin-1") + b"\0"
    return ibsp({0: entities, 1: b"".join(records(1, 72)), 2: b"".join(new_planes), 7: models,
                 8: b"".join(new_brushes), 9: b"".join(new_sides)})


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__ if __doc__ else "usage: q3solids_seeds.py OUT_DIR [level.bsp ...]")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "synthetic.bsp"), "wb") as f:
        f.write(synthetic())
    for path in sys.argv[2:]:
        with open(os.path.join(out, "cut-" + os.path.basename(path)), "wb") as f:
            f.write(cut_down(path))


if __name__ == "__main__":
    main()
