#!/usr/bin/env python3
"""Compares two weightings of double-difference rows on real residuals: by elevation (giocal's
model, undifferenced variance s0^2 (1 + 1/sin el)) and by C/N0 (a^2 + b^2 10^(-C/N0 / 10)), each
fitted by maximum likelihood (Gaussian, coordinate search on the log of its parameters) to the
rows of bench/gnss_residuals.cc's CSV (phase and code apart; rows beyond 5 robust sigma left
out). Prints the negative log-likelihood per row of each model: the lower one describes the
residuals better. Rows without a C/N0 at both receivers are skipped (the GSI pair has none).
Usage: bench/gnss_weight_compare.py residuals.csv ...
"""
import csv
import math
import sys


def rows(path, kind):
    out = []
    for r in csv.DictReader(open(path)):
        if r["kind"] != kind:
            continue
        cn0 = [float(r[k]) for k in ("cn0_sat_rover", "cn0_sat_base", "cn0_ref_rover",
                                     "cn0_ref_base")]
        if any(math.isnan(c) for c in cn0):
            continue
        out.append((float(r["residual_m"]), float(r["el_sat_deg"]), float(r["el_ref_deg"]), cn0))
    return out


def elevation_factor(el_deg):
    s = max(math.sin(math.radians(el_deg)), 0.05)
    return 1.0 + 1.0 / s


def nll(r2, features, theta):
    total = 0.0
    for a, f in zip(r2, features):
        v = sum(t * x for t, x in zip(theta, f)) + 1e-30
        total += math.log(v) + a / v
    return 0.5 * total / len(r2)


def golden(fun, lo, hi, iterations=30):
    g = (math.sqrt(5.0) - 1.0) / 2.0
    a, b = lo, hi
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = fun(c), fun(d)
    for _ in range(iterations):
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = fun(c)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = fun(d)
    return (a + b) / 2.0


def fit(r2, features):
    k = len(features[0])
    mean = sum(r2) / len(r2)
    log_theta = [math.log(mean / (sum(f[j] for f in features) / len(features)) / k)
                 for j in range(k)]
    for _ in range(8 if k > 1 else 1):
        for j in range(k):
            def at(x):
                theta = [math.exp(v) for v in log_theta]
                theta[j] = math.exp(x)
                return nll(r2, features, theta)
            log_theta[j] = golden(at, log_theta[j] - 12.0, log_theta[j] + 6.0)
    theta = [math.exp(v) for v in log_theta]
    return nll(r2, features, theta), theta


def main(paths):
    for path in paths:
        for kind in ("phase", "code"):
            d = rows(path, kind)
            if not d:
                print(f"{path} {kind}: no rows with C/N0 at both receivers")
                continue
            med = sorted(abs(x[0]) for x in d)[len(d) // 2]
            d = [x for x in d if abs(x[0]) < 5.0 * 1.4826 * med]
            r2 = [x[0] ** 2 for x in d]
            elevation = [[2.0 * (elevation_factor(x[1]) + elevation_factor(x[2]))] for x in d]
            cn0 = [[4.0, 1e4 * sum(10.0 ** (-c / 10.0) for c in x[3])] for x in d]
            e, _ = fit(r2, elevation)
            c, theta = fit(r2, cn0)
            print(f"{path} {kind}: {len(d)} rows, NLL per row: elevation {e:.4f}, C/N0 {c:.4f} "
                  f"(a {math.sqrt(theta[0]) * 1000:.1f} mm, b {math.sqrt(theta[1]) * 1000:.1f} mm "
                  f"at 40 dB-Hz) -> {'C/N0' if c < e else 'elevation'} fits better")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        print(__doc__)
        sys.exit(2)
    main(sys.argv[1:])
