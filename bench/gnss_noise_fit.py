#!/usr/bin/env python3
"""Fits the GNSS noise model on real double-difference residuals (bench/gnss_residuals.cc's CSV).

For each file and kind (phase, code) it prints the RMS residual per elevation bin of the row's
satellite, the ratio of the residuals to the sigma giocal assumes today (chi2/dof of
2 (f(el_sat) + f(el_ref)) with f(el) = s0^2 (1 + 1/sin el), s0 from --phase / --code), and a fit of
the undifferenced variance f(el) = a^2 + b^2 / sin^2(el) (RTKLIB's form) by least squares on the
squared residuals, trimmed at 5 sigma twice.
Usage: bench/gnss_noise_fit.py [--phase 0.003] [--code 0.3] name=residuals.csv ...
"""
import csv
import math
import sys


def load(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def current_var(s0, el_deg):
    s = max(math.sin(math.radians(el_deg)), 0.05)
    return s0 * s0 * (1.0 + 1.0 / s)


def fit(rows):
    """Least squares of r^2 = 2 (2 a^2 + b^2 (1/sin^2 es + 1/sin^2 er)) for (a^2, b^2) >= 0."""
    keep = rows
    a2 = b2 = 0.0
    for _ in range(3):
        sxx = sxy = syy = sx = sy = 0.0
        n = 0
        for r, es, er in keep:
            x = 2.0 * (1.0 / math.sin(es) ** 2 + 1.0 / math.sin(er) ** 2)
            y = r * r
            # regress y = 4 a2 + x b2
            sxx += x * x
            sx += x
            sy += y
            sxy += x * y
            n += 1
        if n < 3:
            return None
        det = n * sxx - sx * sx
        b2 = max((n * sxy - sx * sy) / det, 0.0)
        a2 = max((sy - b2 * sx) / (4.0 * n), 0.0)
        var = lambda es, er: 2.0 * (2.0 * a2 + b2 * (1 / math.sin(es) ** 2 + 1 / math.sin(er) ** 2))
        keep = [(r, es, er) for r, es, er in rows if r * r < 25.0 * var(es, er)]
    return math.sqrt(a2), math.sqrt(b2), len(rows) - len(keep)


def main():
    s0 = {"phase": 0.003, "code": 0.3}
    files = []
    args = sys.argv[1:]
    while args:
        a = args.pop(0)
        if a in ("--phase", "--code"):
            s0[a[2:]] = float(args.pop(0))
        else:
            name, path = a.split("=", 1)
            files.append((name, path))
    bins = [10, 15, 20, 30, 45, 60, 90]
    for name, path in files:
        data = load(path)
        baseline = float(data[0]["baseline_m"]) if data else 0.0
        for kind in ("phase", "code"):
            rows = [(float(d["residual_m"]), math.radians(float(d["el_sat_deg"])),
                     math.radians(float(d["el_ref_deg"]))) for d in data if d["kind"] == kind]
            if not rows:
                continue
            chi = [r * r / (2 * (current_var(s0[kind], math.degrees(es)) +
                                 current_var(s0[kind], math.degrees(er)))) for r, es, er in rows]
            line = f"{name:8s} {baseline / 1000:6.2f} km {kind:5s} rows {len(rows):6d}  "
            line += f"chi2/dof at s0={s0[kind]:g}: {sum(chi) / len(chi):7.2f}   RMS per el bin:"
            for lo, hi in zip(bins[:-1], bins[1:]):
                sel = [r for r, es, _ in rows if lo <= math.degrees(es) < hi]
                if sel:
                    rms = math.sqrt(sum(r * r for r in sel) / len(sel))
                    line += f" {lo}-{hi}: {rms * 1000:7.1f} mm ({len(sel)})"
            f = fit(rows)
            if f:
                line += f"   fit a {f[0] * 1000:.2f} mm, b {f[1] * 1000:.2f} mm ({f[2]} trimmed)"
            print(line)


if __name__ == "__main__":
    main()
