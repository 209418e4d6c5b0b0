#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Issue 19's acceptance table: per OpenArena 0.8.8 deathmatch map, from DIR/MAP-backoff-off.json
and DIR/MAP-backoff-on.json (osgvisbench reports), what exact and the frustum draw, octree's and
mask's occlusion efficacy, median cull ms and fps against plain OSG without and with do no harm,
q3-pvs-approx's false-invisible count and efficacy, and the slowest mode with do no harm on.
Usage: level-acceptance-table.py DIR"""
import json,sys,glob,os
maps=["aggressor","am_galmevish2","am_lavaarena","am_spacecont","am_underworks2","czest1dm","mlca1","oa_koth1","oa_koth2","oa_minia","oa_shouse","pul1duel-oa","pxlfan","sleekgrinder","slimefac"]
if len(sys.argv) != 2:
    sys.exit(__doc__)
d=sys.argv[1]
print("%-15s %7s %6s %6s | %-26s | %-26s | %-18s | %s" % ("map","tris","exact","frust","octree oe cull fps off/on","mask oe cull fps off/on","q3-pvs-approx fi oe","lowest mode, back-off on"))
for m in maps:
    try:
        a=json.load(open(f"{d}/{m}-backoff-off.json")); b=json.load(open(f"{d}/{m}-backoff-on.json"))
    except Exception as e:
        continue
    A=a["modes"]; B=b["modes"]
    def cell(mode):
        x=A[mode]; y=B[mode]
        return "%.2f %5.2f %.2fx/%.2fx" % (x["occlusion_efficacy"], x["cull_ms_median"], x["speedup_vs_osg"], y["speedup_vs_osg"])
    q=A["frustum+q3-pvs-approx"]
    low=min(((k,v["speedup_vs_osg"]) for k,v in B.items() if k not in ("osg","exact","frustum+q3-pvs-approx")), key=lambda t:t[1])
    print("%-15s %7d %5.1f%% %5.1f%% | %-26s | %-26s | fi=%-4d oe=%.2f      | %s %.2fx" % (m, a["triangles"], 100*A["exact"]["drawn_fraction"], 100*A["frustum"]["drawn_fraction"], cell("octree"), cell("mask"), q["false_invisible"], q["occlusion_efficacy"], low[0], low[1]))
