#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Compares the per-view records of two osgvisbench JSON reports (docs/benchmark.md, "per_view"):
for every mode both ran, and every synchronous row of the threading table, whether each view drew
the same set (digest), the same object and triangle counts, and the same false-invisible count.

    scripts/compare-per-view.py BEFORE.json AFTER.json

Exits 1 when a synchronous pass differs in any view. Asynchronous rows are reported but not
judged: which region answer the cull thread finds ready depends on the worker's timing, so two
runs of the same build differ there.
"""
import json
import sys


def load(path):
    with open(path) as f:
        return json.load(f)


def compare(name, a, b):
    """One line per pass; returns True when every view agrees."""
    views = len(a["view_digest"])
    if views != len(b["view_digest"]):
        print(f"  {name}: {views} views before, {len(b['view_digest'])} after")
        return False
    differ = [v for v in range(views) if a["view_digest"][v] != b["view_digest"][v]]
    counts = sum(a[k] != b[k] for k in ("view_objects", "view_triangles", "view_false_invisible"))
    missed = sum(b["view_false_invisible"])
    print(f"  {name:<44} {views:>5} views  sets differ in {len(differ):>4}  "
          f"count columns differ: {counts}  false-invisible after: {missed}")
    return not differ and counts == 0


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip())
        return 2
    before, after = load(argv[1]), load(argv[2])
    print(f"{before['scene']}: {argv[1]} vs {argv[2]}")
    same = True
    for mode, record in before.get("per_view", {}).items():
        if mode in after.get("per_view", {}):
            same &= compare(mode, record, after["per_view"][mode])
    rows_after = {(r["mode"], r["threading"], r["async"]): r for r in after.get("threading_per_view", [])}
    for row in before.get("threading_per_view", []):
        key = (row["mode"], row["threading"], row["async"])
        if key not in rows_after:
            continue
        name = f"{row['mode']} {row['threading']} async {'on' if row['async'] else 'off'}"
        if row["async"]:
            print("  (not judged: async)", end="")
            compare(name, row, rows_after[key])
        else:
            same &= compare(name, row, rows_after[key])
    print("identical" if same else "DIFFERENT")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
