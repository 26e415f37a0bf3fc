#!/usr/bin/env python3
"""The slow part of the time-differenced phase rows against the true antenna, by elevation.

Reads the CSV of `giocal_gnss_residuals --rover R --nav N --truth truth.csv --p-b-g x,y,z` (one
row per TDCP row and epoch pair: t, sat, ref, band, el_sat_deg, el_ref_deg, residual_m, ...),
averages each row's residual (a 1 s pair's, so mm/s) over blocks of BLOCK seconds, and prints the
RMS of those means, over all rows and per bin of the row's lower elevation. A white error averages
away in a block; what is left is what lasts a minute: orbit and clock rates, the ionosphere's
change, and multipath that a static antenna keeps for minutes.
Usage: tdcp_slow_errors.py rows.csv [--systems G] [--mask 24] [--block 60] [--min-rows 30]
"""
import argparse
import csv
import math
from collections import defaultdict

BINS = [(0, 30), (30, 45), (45, 60), (60, 90)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("rows")
    ap.add_argument("--systems", default="", help="system letters to keep (all when empty)")
    ap.add_argument("--mask", type=float, default=0.0, help="both satellites above this [deg]")
    ap.add_argument("--block", type=float, default=60.0, help="block length [s]")
    ap.add_argument("--min-rows", type=int, default=30, help="a block's fewest rows")
    a = ap.parse_args()
    blocks = defaultdict(list)  # (sat, ref, band, block) -> [(residual, lower elevation)]
    with open(a.rows) as f:
        for r in csv.DictReader(f):
            if a.systems and (r["sat"][0] not in a.systems or r["ref"][0] not in a.systems):
                continue
            el = min(float(r["el_sat_deg"]), float(r["el_ref_deg"]))
            if el < a.mask:
                continue
            key = (r["sat"], r["ref"], r["band"], math.floor(float(r["t"]) / a.block))
            blocks[key].append((float(r["residual_m"]), el))
    means = []  # (block mean [mm per pair], mean lower elevation, white RMS [mm])
    for rows in blocks.values():
        if len(rows) < a.min_rows:
            continue
        m = sum(x for x, _ in rows) / len(rows)
        white = math.sqrt(sum((x - m) ** 2 for x, _ in rows) / (len(rows) - 1))
        means.append((1e3 * m, sum(e for _, e in rows) / len(rows), 1e3 * white))
    if not means:
        print("no block with enough rows")
        return 1

    def line(name, sel):
        if not sel:
            return
        rms = math.sqrt(sum(m * m for m, _, _ in sel) / len(sel))
        white = math.sqrt(sum(w * w for _, _, w in sel) / len(sel))
        print(f"{name:>10s} {len(sel):6d} {rms:9.3f} {white:9.3f}")

    print(f"{'lower el':>10s} {'blocks':>6s} {'slow':>9s} {'white':>9s}   (mm per 1 s pair)")
    line("all", means)
    for lo, hi in BINS:
        line(f"{lo}-{hi}", [x for x in means if lo <= x[1] < hi])
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
