#!/usr/bin/env python3
"""Seed-by-seed comparison of two estimators' absolute calibration errors from Monte Carlo output.

Usage: python3 bench/paired_errors.py <run A.txt> <estimator A> <run B.txt> <estimator B>
The files are what build/bench/giocal_monte_carlo prints (one row per seed and estimator). For the
seeds both runs hold, prints the mean over seeds of |error A| - |error B| per state with its
standard error: negative means A is more accurate. Pairing by seed removes the spread that the
seeds' different initial guesses put into each mean, so a difference of a few tenths of a degree
becomes visible where the two means alone could not show it.
"""
import math
import sys

STATES = ["X m", "Y m", "roll deg", "pitch deg", "yaw deg", "V scale", "W scale"]


def per_seed(path, estimator):
    errors = {}
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) >= 9 and fields[0].isdigit() and fields[1] == estimator:
                errors[int(fields[0])] = [float(x) for x in fields[2:9]]
    return errors


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    a = per_seed(sys.argv[1], sys.argv[2])
    b = per_seed(sys.argv[3], sys.argv[4])
    seeds = sorted(set(a) & set(b))
    if len(seeds) < 2:
        sys.exit("fewer than two seeds in common: nothing to compare")
    print(f"{len(seeds)} seeds: |{sys.argv[2]} error| - |{sys.argv[4]} error|, "
          "mean +- standard error")
    for i, name in enumerate(STATES):
        d = [abs(a[s][i]) - abs(b[s][i]) for s in seeds]
        mean = sum(d) / len(d)
        sd = math.sqrt(sum((x - mean) ** 2 for x in d) / (len(d) - 1))
        print(f"  {name:10s} {mean:+.3g} +- {sd / math.sqrt(len(d)):.2g}")


if __name__ == "__main__":
    main()
