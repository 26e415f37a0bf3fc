#!/usr/bin/env python3
"""Fits the GNSS noise model on real double-difference residuals (bench/gnss_residuals.cc's CSV).

For each file and kind (phase, code) it prints the RMS residual per elevation bin of the row's
satellite, the ratio of the residuals to the sigma giocal assumes today (chi2/dof of
2 (f(el_sat) + f(el_ref)) with f(el) = s0^2 (1 + 1/sin el), s0 from --phase / --code), and a fit of
the undifferenced variance f(el) = a^2 + b^2 / sin^2(el) (RTKLIB's form) by least squares on the
squared residuals, trimmed at 5 sigma twice.
It also prints how each DD series (satellite, reference, band) is correlated with itself 1, 5, 10
and 30 s later (the correlation of its deviations from its mean, pooled over the series): white
noise gives 0, multipath that changes slowly gives values near 1.
Usage: bench/gnss_noise_fit.py [--phase 0.003] [--code 0.3] [--first-s T] name=residuals.csv ...
       (--first-s: only the first T seconds of each file, e.g. a simulated drive's open sky)
       bench/gnss_noise_fit.py --cmc [--code 0.3] name=cmc.csv ...   (a receiver alone: code
       minus carrier per arc, a line per arc taken out; RMS by elevation and by C/N0, the same fit)
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


def cmc_rows(path):
    """Code-minus-carrier residuals: per satellite and band, arcs cut at a loss of lock, a gap over
    1.5 s or a jump over 5 m; a straight line in time fitted out of each arc of 20 or more."""
    arcs, last = {}, {}
    out = []
    for d in load(path):
        key = (d["sat"], d["band"])
        t, v = float(d["t"]), float(d["cmc_m"])
        prev = last.get(key)
        if prev is None or int(d["lli"]) & 1 or t - prev[0] > 1.5 or abs(v - prev[1]) > 5.0:
            arcs.setdefault(key, []).append([])
        arcs[key][-1].append((t, v, float(d["el_deg"]), float(d["cn0"])))
        last[key] = (t, v)
    for arc_list in arcs.values():
        for arc in arc_list:
            if len(arc) < 20:
                continue
            n = len(arc)
            mt = sum(a[0] for a in arc) / n
            mv = sum(a[1] for a in arc) / n
            stt = sum((a[0] - mt) ** 2 for a in arc)
            slope = sum((a[0] - mt) * (a[1] - mv) for a in arc) / stt if stt > 0 else 0.0
            k = math.sqrt(n / (n - 2.0))  # two parameters fitted out
            for t, v, el, cn0 in arc:
                out.append(((v - mv - slope * (t - mt)) * k, math.radians(el), cn0))
    return out


def cmc_main(files, s0):
    bins = [10, 15, 20, 30, 45, 60, 90]
    for name, path in files:
        rows = [r for r in cmc_rows(path) if r[1] > math.radians(10)]
        if not rows:
            continue
        chi = [r * r / current_var(s0, math.degrees(el)) for r, el, _ in rows]
        line = f"{name:8s} code-minus-carrier rows {len(rows):6d}  chi2/dof at s0={s0:g}: "
        line += f"{sum(chi) / len(chi):6.2f}   RMS per el bin:"
        for lo, hi in zip(bins[:-1], bins[1:]):
            sel = [r for r, el, _ in rows if lo <= math.degrees(el) < hi]
            if sel:
                line += f" {lo}-{hi}: {math.sqrt(sum(r * r for r in sel) / len(sel)):.2f} m"
        line += "   per C/N0:"
        for lo, hi in ((0, 30), (30, 35), (35, 40), (40, 45), (45, 60)):
            sel = [r for r, _, c in rows if lo <= c < hi]
            if len(sel) > 20:
                line += f" {lo}-{hi}: {math.sqrt(sum(r * r for r in sel) / len(sel)):.2f} m"
        # undifferenced: r^2 = a^2 + b^2 / sin^2(el), least squares
        xs = [1.0 / math.sin(el) ** 2 for _, el, _ in rows]
        ys = [r * r for r, _, _ in rows]
        n = len(xs)
        mx, my = sum(xs) / n, sum(ys) / n
        sxx = sum((x - mx) ** 2 for x in xs)
        b2 = max(sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx, 0.0) if sxx else 0.0
        a2 = max(my - b2 * mx, 0.0)
        line += f"   fit a {math.sqrt(a2):.3f} m, b {math.sqrt(b2):.3f} m"
        print(line)


def lag_correlations(data, kind, lags=(1, 5, 10, 30)):
    """Pooled correlation of each DD series' deviations from its mean, `lag` seconds apart."""
    series = {}
    for d in data:
        if d["kind"] == kind:
            key = (d["sat"], d["ref"], d["band"])
            series.setdefault(key, {})[round(float(d["t"]))] = float(d["residual_m"])
    out = []
    for lag in lags:
        cov = var = 0.0
        n_cov = n_var = 0
        for s in series.values():
            if len(s) < lag + 10:
                continue
            m = sum(s.values()) / len(s)
            var += sum((v - m) ** 2 for v in s.values())
            n_var += len(s)
            for t, v in s.items():
                if t + lag in s:
                    cov += (v - m) * (s[t + lag] - m)
                    n_cov += 1
        out.append((lag, cov / n_cov / (var / n_var) if n_cov and var > 0 else float("nan")))
    return out


def main():
    s0 = {"phase": 0.003, "code": 0.3}
    first_s = math.inf
    files = []
    cmc = False
    args = sys.argv[1:]
    while args:
        a = args.pop(0)
        if a == "--cmc":
            cmc = True
        elif a in ("--phase", "--code"):
            s0[a[2:]] = float(args.pop(0))
        elif a == "--first-s":
            first_s = float(args.pop(0))
        else:
            name, path = a.split("=", 1)
            files.append((name, path))
    if cmc:
        cmc_main(files, s0["code"])
        return
    bins = [10, 15, 20, 30, 45, 60, 90]
    for name, path in files:
        data = load(path)
        if data:
            t0 = float(data[0]["t"])
            data = [d for d in data if float(d["t"]) - t0 < first_s]
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
            line += "   correlated " + ", ".join(
                f"{lag} s {c:.2f}" for lag, c in lag_correlations(data, kind))
            print(line)


if __name__ == "__main__":
    main()
