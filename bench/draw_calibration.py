#!/usr/bin/env python3
"""A calibration a consistent estimator could have given: the truth plus an error drawn from a
run's own sigmas at one time.

Usage: python3 bench/draw_calibration.py <run dir> <dataset dir> <seconds|end> <out dir> <seed>
Takes the row of <run dir>/calibration.csv at <seconds> after the run's first rover epoch (or its
last row), and writes to <out dir> a calibration.csv with one row at that time whose values are the
dataset's truth_calib.yaml plus independent normal errors of that row's sigmas (sigmas kept), a
gyro_tilt.csv likewise when the run has one and the truth states the tilt, and a summary.json with
the run's first rover epoch, so that `deadreckon --calibration <out dir>/calibration.csv@<seconds>`
reads it as it reads the run. Dead-reckoning with it shows what the run's sigma alone costs, apart
from any error the run makes beyond its sigma. Correlations between the states are not drawn
(calibration.csv holds sigmas only).
"""
import csv
import json
import os
import random
import sys


def truth(path):
    t = {}
    for line in open(path):
        if ":" in line and not line.startswith("#"):
            k, v = line.split(":", 1)
            t[k.strip()] = json.loads(v)
    return t


def row_at(path, t):
    rows = list(csv.reader(open(path)))
    header, body = rows[0], [[float(x) for x in r] for r in rows[1:] if r]
    chosen = [r for r in body if t is None or r[0] <= t + 1e-9]
    if not chosen:
        sys.exit(f"draw_calibration.py: {path}: no row at or before t={t}")
    return header, chosen[-1]


def main():
    if len(sys.argv) != 6:
        sys.exit("usage: draw_calibration.py <run dir> <dataset dir> <seconds|end> <out dir> <seed>")
    run, data, when, out, seed = sys.argv[1:6]
    rng = random.Random(int(seed))
    t0 = json.load(open(os.path.join(run, "summary.json")))["t_first_rover_epoch"]
    t = None if when == "end" else t0 + float(when)
    tr = truth(os.path.join(data, "truth_calib.yaml"))
    header, r = row_at(os.path.join(run, "calibration.csv"), t)
    mean = [tr["s_v"], tr["s_w"]] + tr["p_b_m"] + tr["rpy_b_m_deg"]
    sd = r[9:17]
    row = [r[0]] + [m + rng.gauss(0.0, s) for m, s in zip(mean, sd)] + sd
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "calibration.csv"), "w") as f:
        f.write(",".join(header) + "\n" + ",".join(repr(x) for x in row) + "\n")
    tilt = os.path.join(run, "gyro_tilt.csv")
    if os.path.exists(os.path.join(out, "gyro_tilt.csv")):
        os.remove(os.path.join(out, "gyro_tilt.csv"))  # an earlier draw's
    if os.path.exists(tilt) and "gyro_tilt_deg" in tr:
        th, tt = row_at(tilt, r[0])
        g = [tt[0]] + [m + rng.gauss(0.0, s) for m, s in zip(tr["gyro_tilt_deg"], tt[3:5])] + tt[3:5]
        with open(os.path.join(out, "gyro_tilt.csv"), "w") as f:
            f.write(",".join(th) + "\n" + ",".join(repr(x) for x in g) + "\n")
    json.dump({"t_first_rover_epoch": t0}, open(os.path.join(out, "summary.json"), "w"))


if __name__ == "__main__":
    main()
