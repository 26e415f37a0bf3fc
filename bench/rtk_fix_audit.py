#!/usr/bin/env python3
"""Counts fixed and wrong-fixed epochs of RTK solutions against a simulated dataset's truth, per scene.

Usage: python3 bench/rtk_fix_audit.py <dataset dir> <preset.yaml> <label>=<file.pos>...
       python3 bench/rtk_fix_audit.py --sum < lines   (totals of lines printed by the above)
A fix is wrong when its horizontal distance from the true antenna (truth.csv's IMU origin plus
R_n_b p_b_g from dataset.yaml) exceeds 5 cm; vertically the simulated troposphere puts correct
fixes a few centimetres off (docs/design.md, "Wrong fixes are counted"), so height is left out.
Prints one line per scene and label: epochs, fixed, fix rate, wrong, wrong share, the wrong fixes
whose error is also beyond 3 times the solution's own horizontal sigma, and the worst error.
Scenes are the preset's gnss.scenes (seconds from the first epoch).
"""
import bisect
import csv
import datetime
import math
import re
import sys

import yaml

GPS_EPOCH = datetime.datetime(1980, 1, 6)
WRONG_M = 0.05


def gps_seconds(date, clock):
    t = datetime.datetime.strptime(date + " " + clock[:15], "%Y/%m/%d %H:%M:%S.%f")
    return (t - GPS_EPOCH).total_seconds()


def read_pos(path):
    out = []
    for line in open(path):
        if line.startswith("%") or not line.strip():
            continue
        f = line.split()
        out.append((gps_seconds(f[0], f[1]), float(f[2]), float(f[3]), int(f[5]),
                    math.hypot(float(f[7]), float(f[8]))))
    return out


def rotate(q, v):
    w, x, y, z = q
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    return [sum(r[i][j] * v[j] for j in range(3)) for i in range(3)]


class Truth:
    """The true antenna's latitude and longitude, interpolated linearly in time."""

    def __init__(self, data):
        spec = yaml.safe_load(open(data + "/dataset.yaml"))
        self.p_b_g = spec["gnss"]["p_b_g"]
        self.t, self.rows = [], []
        with open(data + "/truth.csv") as f:
            for r in csv.DictReader(f):
                self.t.append(float(r["t"]))
                self.rows.append(r)

    def antenna(self, t):
        i = bisect.bisect_left(self.t, t)
        if i >= len(self.t) or (i == 0 and self.t[0] != t):
            return None
        if self.t[i] != t:
            a, b = self.rows[i - 1], self.rows[i]
            w = (t - self.t[i - 1]) / (self.t[i] - self.t[i - 1])
            r = {k: float(a[k]) + w * (float(b[k]) - float(a[k])) for k in a}
        else:
            r = {k: float(v) for k, v in self.rows[i].items()}
        e, n, _ = rotate((r["qw"], r["qx"], r["qy"], r["qz"]), self.p_b_g)
        lat = math.radians(r["lat"])
        a, e2 = 6378137.0, 6.69437999014e-3
        s = 1 - e2 * math.sin(lat) ** 2
        rm, rn = a * (1 - e2) / s ** 1.5 + r["h"], a / math.sqrt(s) + r["h"]
        return r["lat"] + math.degrees(n / rm), r["lon"] + math.degrees(e / (rn * math.cos(lat)))


def horizontal_error(sol, ant):
    lat = math.radians(ant[0])
    dn = math.radians(sol[1] - ant[0]) * 6378137.0
    de = math.radians(sol[2] - ant[1]) * 6378137.0 * math.cos(lat)
    return math.hypot(dn, de)


def print_totals(lines):
    totals, order = {}, []
    for line in lines:
        m = re.search(r"(\S+)\s+(\S+)\s+epochs\s+(\d+) fixed\s+(\d+).*wrong\s+(\d+).*"
                      r"beyond3sd\s+(\d+) worst\s+(\S+)", line)
        if not m:
            continue
        key = m.group(1) + " " + m.group(2)
        if key not in totals:
            totals[key] = [0, 0, 0, 0, 0.0]
            order.append(key)
        t = totals[key]
        for i in range(4):
            t[i] += int(m.group(3 + i))
        t[4] = max(t[4], float(m.group(7)))
    for key in order:
        n, fixed, wrong, beyond, worst = totals[key]
        print(f"{key:20s} epochs {n:5d} fixed {fixed:5d} ({100.0 * fixed / max(n, 1):5.1f} %) "
              f"wrong {wrong:4d} ({100.0 * wrong / max(fixed, 1):5.2f} %) beyond3sd {beyond:4d} "
              f"worst {worst:8.3f} m")


def main():
    if sys.argv[1:] == ["--sum"]:
        print_totals(sys.stdin)
        return
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    data, preset = sys.argv[1], sys.argv[2]
    scenes = yaml.safe_load(open(preset))["gnss"].get("scenes", [])
    truth = Truth(data)
    t0 = truth.t[0]
    for spec in sys.argv[3:]:
        label, path = spec.split("=", 1)
        sols = read_pos(path)
        bins = [(s["type"], s["start"], s["end"]) for s in scenes] or [("all", 0, 1e18)]
        for name, start, end in bins:
            n = fixed = wrong = beyond = 0
            worst = 0.0
            for sol in sols:
                if not start <= sol[0] - t0 < end:
                    continue
                n += 1
                if sol[3] != 1:
                    continue
                ant = truth.antenna(sol[0])
                if ant is None:
                    continue
                fixed += 1
                err = horizontal_error(sol, ant)
                worst = max(worst, err)
                wrong += err > WRONG_M
                beyond += err > WRONG_M and err > 3.0 * sol[4]
            print(f"{label:8s} {name:11s} epochs {n:5d} fixed {fixed:5d} "
                  f"({100.0 * fixed / max(n, 1):5.1f} %) wrong {wrong:4d} "
                  f"({100.0 * wrong / max(fixed, 1):5.2f} %) beyond3sd {beyond:4d} "
                  f"worst {worst:8.3f} m")


if __name__ == "__main__":
    main()
