#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The real set's table from osgvisbench JSON reports (scripts/levels.sh writes them): per model
its objects and triangles and exact's drawn %, and per mode osgVis's chain cull ms (median/p99),
OSG's whole cull traversal ms (median), occlusion efficacy, drawn %, fps against plain OSG and
false-invisible objects; then per model issue 44's checks.
Usage: levels-table.py REPORT.json... (one model per file)."""
import json
import os
import sys

# Modes that stand for no culling method: the baseline and the oracle's replay.
REFERENCE_MODES = ("osg", "exact")
CHAIN_MEDIAN_LIMIT = 1.0  # ms, the best mode
CHAIN_P99_LIMIT = 2.0     # ms, every conservative mode
EFFICACY_LIMIT = 0.7


def fmt(value, pattern):
    return "-" if value is None else pattern % value


def conservative(name):
    return "approx" not in name


def culling_modes(modes):
    return {n: m for n, m in modes.items() if n not in REFERENCE_MODES}


def best_mode(modes):
    """The fastest conservative culling mode (chain median) whose occlusion efficacy reaches the
    limit, else the one with the highest occlusion efficacy."""
    candidates = {n: m for n, m in culling_modes(modes).items()
                  if conservative(n) and m.get("occlusion_efficacy") is not None}
    if not candidates:
        return None
    good = {n: m for n, m in candidates.items() if m["occlusion_efficacy"] >= EFFICACY_LIMIT}
    if good:
        return min(good, key=lambda n: good[n].get("chain_ms_median") or 1e9)
    return max(candidates, key=lambda n: candidates[n]["occlusion_efficacy"])


def checks(modes):
    best = best_mode(modes)
    notes = []
    if best is None:
        return "no culling mode", False
    b = modes[best]
    ok_best = (b.get("chain_ms_median") or 1e9) <= CHAIN_MEDIAN_LIMIT and b["occlusion_efficacy"] >= EFFICACY_LIMIT
    slow = [n for n, m in culling_modes(modes).items()
            if conservative(n) and (m.get("chain_ms_p99") or 1e9) > CHAIN_P99_LIMIT]
    missing = [n for n, m in modes.items() if conservative(n) and m["false_invisible"] != 0]
    notes.append("best %s (%s ms, oe %.2f)%s" % (best, fmt(b.get("chain_ms_median"), "%.2f"),
                                                  b["occlusion_efficacy"], "" if ok_best else " FAIL"))
    notes.append("p99 > %g ms: %s" % (CHAIN_P99_LIMIT, ",".join(slow) if slow else "none"))
    notes.append("false-invisible: %s" % (",".join(missing) if missing else "none"))
    return "; ".join(notes), ok_best and not slow and not missing


def rows(path):
    report = json.load(open(path))
    modes = report["modes"]
    name = os.path.basename(path).rsplit(".", 1)[0]
    exact = modes.get("exact", {}).get("drawn_fraction")
    out = ["%-16s %6d %8d %4d views  exact drawn %s" % (
        name, report["objects"], report["triangles"], report["views"], fmt(exact and 100 * exact, "%.1f%%"))]
    for mode, m in modes.items():
        oe = m.get("occlusion_efficacy")
        out.append("    %-14s %13s %7s %6s %7s %7s %5d" % (
            mode, fmt(m.get("chain_ms_median"), "%.2f") + "/" + fmt(m.get("chain_ms_p99"), "%.2f"),
            fmt(m.get("cull_ms_median"), "%.2f"), fmt(oe, "%.2f"), fmt(100 * m["drawn_fraction"], "%.1f"),
            fmt(m.get("speedup_vs_osg"), "%.2fx"), m["false_invisible"]))
    verdict, passed = checks(modes)
    out.append("    -> %s: %s" % ("pass" if passed else "not yet", verdict))
    return out, passed


def main(paths):
    print("%-16s %6s %8s" % ("model", "objects", "triangles"))
    print("    %-14s %13s %7s %6s %7s %7s %5s" % ("mode", "chain ms m/p99", "cull ms", "oe", "drawn%",
                                                   "vs osg", "f-inv"))
    passed = 0
    for path in paths:
        lines, ok = rows(path)
        passed += ok
        print("\n".join(lines))
    print("%d of %d models pass (best mode's chain median <= %g ms with occlusion efficacy >= %g, every "
          "conservative mode's chain p99 <= %g ms, 0 false-invisible)" % (
              passed, len(paths), CHAIN_MEDIAN_LIMIT, EFFICACY_LIMIT, CHAIN_P99_LIMIT))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
