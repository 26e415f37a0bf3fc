#!/usr/bin/env python3
"""Splits an EKF run's heading error into the IMU heading and the extrinsic yaw, every <step> s.

Usage: python3 bench/heading_split.py <dataset dir> [<calibrate output dir>, default <dataset>/ekf]
                                      [<step s>, default 10]
Needs truth.csv and truth_calib.yaml in the dataset (simulated data). Prints the IMU heading error
(trajectory.csv against truth.csv) beside the extrinsic yaw error and its 1-sigma
(calibration.csv); they cancel when the vehicle heading is right and only the split is wrong.
"""
import csv
import math
import re
import sys


def yaw_deg(w, x, y, z):
    return math.degrees(math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)))


def rows(path):
    with open(path) as f:
        yield from csv.DictReader(f)


def main():
    data = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else data + "/ekf"
    step = float(sys.argv[3]) if len(sys.argv) > 3 else 10.0
    true_yaw = float(re.search(r"rpy_b_m_deg:\s*\[[^,]+,[^,]+,([^\]]+)\]",
                               open(data + "/truth_calib.yaml").read()).group(1))
    quat = ("qw", "qx", "qy", "qz")
    truth = {round(float(r["t"]), 2): yaw_deg(*(float(r[k]) for k in quat))
             for r in rows(data + "/truth.csv")}
    calib = {round(float(r["t"]), 2): (float(r["yaw"]), float(r["sd_yaw"]))
             for r in rows(out + "/calibration.csv")}
    print("   t s  IMU heading err deg  extrinsic yaw err deg  its sigma")
    t0 = None
    for r in rows(out + "/trajectory.csv"):
        t = round(float(r["t"]), 2)
        t0 = t if t0 is None else t0
        if (t - t0) % step != 0 or t not in truth or t not in calib:
            continue
        e = (yaw_deg(*(float(r[k]) for k in quat)) - truth[t] + 180) % 360 - 180
        print("%6.0f  %19.3f  %21.3f  %9.2f" % (t - t0, e, calib[t][0] - true_yaw, calib[t][1]))


if __name__ == "__main__":
    main()
