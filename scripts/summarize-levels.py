#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""One line per level from osgvisbench JSON reports: the level's size, what exact and the frustum
draw, and per mode its false-invisible count, occlusion efficacy, drawn fraction, median cull ms
and frame rate against plain OSG. Usage: summarize-levels.py REPORT.json... (a level per file)."""
import json
import os
import sys

MODES = ["octree", "octree-paper", "mask", "frustum+q3-pvs-approx", "exact"]


def row(path):
    report = json.load(open(path))
    modes = report["modes"]
    name = os.path.basename(path).rsplit(".", 1)[0]
    head = "%-26s %5d %7d %4d  exact %5.1f%%  frustum %5.1f%%" % (
        name, report["objects"], report["triangles"], report["views"],
        100 * modes["exact"]["drawn_fraction"], 100 * modes["frustum"]["drawn_fraction"])
    cells = []
    for mode in MODES:
        if mode not in modes:
            continue
        m = modes[mode]
        eff = m.get("occlusion_efficacy")
        cells.append("%s fi=%d oe=%s drawn=%.1f%% cull=%.2f %.2fx" % (
            mode, m["false_invisible"], "%.2f" % eff if eff is not None else "-",
            100 * m["drawn_fraction"], m["cull_ms_median"], m["speedup_vs_osg"]))
    return head + "\n    " + "\n    ".join(cells)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for path in sys.argv[1:]:
        print(row(path))
