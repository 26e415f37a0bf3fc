#!/usr/bin/python3
"""giocal report: a self-contained HTML page with PNG figures of a giocal run's outputs.

Usage: giocal_report.py <run dir> <out dir> [<dataset dir>]
The run dir is what `giocal calibrate`, `compare`, `deadreckon` or `validate` wrote (or a Monte
Carlo --box-csv file). Figures: calibration convergence with its +-3 sigma band (both estimators for
compare; the truth when known), the horizontal trajectory, dead-reckoning error over time and
distance, NEES over time with its chi-square band (truth known), the validation's windows (the
calibration's and the guess's dead-reckoning error in each, with the verdict), Monte Carlo box
plots. Tables:
the run's summary.json, every number as the file has it. Called by `giocal report`; needs Debian's
python3-matplotlib.
"""
import csv
import html
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PARAMS = [("s_v", "V scale", 1.0, ""), ("s_w", "W scale", 1.0, ""), ("px", "p_b_m x", 1.0, "m"),
          ("py", "p_b_m y", 1.0, "m"), ("pz", "p_b_m z", 1.0, "m"), ("roll", "roll", 1.0, "deg"),
          ("pitch", "pitch", 1.0, "deg"), ("yaw", "yaw", 1.0, "deg")]
# chi-square 95 % two-sided bounds for 7 degrees of freedom (NEES of the observable states)
CHI2_7 = (1.69, 16.01)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in (rows[0].keys() if rows else [])}


def read_yaml_numbers(path):
    """The few truth_calib.yaml values the report needs (no YAML library in Debian's python3)."""
    out = {}
    with open(path) as f:
        for line in f:
            key, _, value = line.partition(":")
            key, value = key.strip(), value.split("#")[0].strip()
            if value.startswith("["):
                out[key] = [float(v) for v in value.strip("[]").split(",")]
            else:
                try:
                    out[key] = float(value)
                except ValueError:
                    pass
    return out


def truth_of(dataset):
    if not dataset or not os.path.exists(os.path.join(dataset, "truth_calib.yaml")):
        return None
    y = read_yaml_numbers(os.path.join(dataset, "truth_calib.yaml"))
    if "rpy_b_m_deg" not in y:
        return None
    return {"s_v": y["s_v"], "s_w": y["s_w"], "px": y["p_b_m"][0], "py": y["p_b_m"][1],
            "pz": y["p_b_m"][2], "roll": y["rpy_b_m_deg"][0], "pitch": y["rpy_b_m_deg"][1],
            "yaw": y["rpy_b_m_deg"][2]}


def convergence_figure(runs, truth, out):
    fig, axes = plt.subplots(4, 2, figsize=(11, 11), sharex=True)
    for ax, (key, label, _, unit) in zip(axes.flat, PARAMS):
        for name, cal in runs:
            t0 = cal["t"][0]
            t = [x - t0 for x in cal["t"]]
            v, sd = cal[key], cal["sd_" + key]
            line, = ax.plot(t, v, label=name)
            ax.fill_between(t, [a - 3 * s for a, s in zip(v, sd)], [a + 3 * s for a, s in zip(v, sd)],
                            color=line.get_color(), alpha=0.2)
        if truth:
            ax.axhline(truth[key], color="k", linestyle="--", label="truth")
        ax.set_ylabel(f"{label} [{unit}]" if unit else label)
        ax.grid(True, alpha=0.3)
    axes.flat[0].legend(loc="best", fontsize=8)
    for ax in axes[-1]:
        ax.set_xlabel("time since the first GNSS epoch [s]")
    fig.suptitle("Calibration with its ±3σ band")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def delay_figure(delays, out):
    """The odometer delay state (calibration.estimate_odometer_delay) with its +-3 sigma band."""
    fig, ax = plt.subplots(figsize=(11, 3.5))
    for name, d in delays:
        t0 = d["t"][0]
        t = [x - t0 for x in d["t"]]
        v = [1e3 * x for x in d["t_d_odo"]]
        sd = [1e3 * x for x in d["sd_t_d_odo"]]
        line, = ax.plot(t, v, label=name)
        ax.fill_between(t, [a - 3 * s for a, s in zip(v, sd)], [a + 3 * s for a, s in zip(v, sd)],
                        color=line.get_color(), alpha=0.2)
    ax.set_ylabel("odometer delay [ms]")
    ax.set_xlabel("time since the first GNSS epoch [s]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def enu(traj):
    lat0, lon0 = math.radians(traj["lat"][0]), math.radians(traj["lon"][0])
    r = 6378137.0
    e = [(math.radians(lo) - lon0) * r * math.cos(lat0) for lo in traj["lon"]]
    n = [(math.radians(la) - lat0) * r for la in traj["lat"]]
    return e, n, lat0, lon0


def trajectory_figure(tracks, out):
    fig, ax = plt.subplots(figsize=(8, 8))
    ref = None
    for name, traj in tracks:
        if ref is None:
            _, _, lat0, lon0 = enu(traj)
            ref = (lat0, lon0)
        r = 6378137.0
        e = [(math.radians(lo) - ref[1]) * r * math.cos(ref[0]) for lo in traj["lon"]]
        n = [(math.radians(la) - ref[0]) * r for la in traj["lat"]]
        ax.plot(e, n, label=name)
    ax.set_xlabel("east [m]")
    ax.set_ylabel("north [m]")
    ax.axis("equal")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best")
    ax.set_title("Horizontal trajectory")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def dr_error_figure(err, out):
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
    a.plot(err["elapsed_s"], err["horizontal_m"])
    a.set_xlabel("time in the outage [s]")
    b.plot(err["distance_m"], err["horizontal_m"])
    b.set_xlabel("distance driven [m]")
    for ax in (a, b):
        ax.set_ylabel("horizontal error [m]")
        ax.grid(True, alpha=0.3)
    fig.suptitle("Dead-reckoning error")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def validation_figure(entries, out):
    """entries: (name, validation dict with a list of windows, verdict, ratio, confidence)."""
    fig, axes = plt.subplots(1, len(entries), figsize=(5.5 * len(entries), 4), squeeze=False)
    for ax, (name, windows, verdict, ratio, confidence) in zip(axes[0], entries):
        x = list(range(len(windows)))
        ax.bar([i - 0.2 for i in x], [w["calibrated_m"] for w in windows], 0.4,
               label="calibration")
        ax.bar([i + 0.2 for i in x], [w["guess_m"] for w in windows], 0.4, label="initial guess")
        ax.set_xticks(x)
        ax.set_xticklabels([f"+{w['start_s']:.0f} s\n{w['distance_m']:.0f} m" for w in windows],
                           fontsize=8)
        ax.set_ylabel("horizontal MAX error in the window [m]")
        ax.set_title(f"{name}: {verdict} (ratio {ratio:.2f}, confidence {confidence:.2f})",
                     fontsize=10)
        ax.grid(True, axis="y", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Validation: dead reckoning through GNSS outage windows")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def validation_entry(name, v):
    """A figure entry from a summary's validation (calibrate's "validation" or validate's own)."""
    windows = v.get("per_window", v.get("windows"))
    if not isinstance(windows, list) or not windows or "verdict" not in v:
        return None
    return (name, windows, v["verdict"], v.get("ratio", 0.0), v.get("confidence", 0.0))


def read_scenes(dataset):
    """A simulated dataset's scenes.csv as (t_start, t_end, type) in GPS seconds, else []."""
    path = os.path.join(dataset, "scenes.csv") if dataset else None
    if not path or not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return [(float(r["t_start"]), float(r["t_end"]), r["type"]) for r in csv.DictReader(f)]


SCENE_COLOURS = {"open_sky": "#ffffff", "few_trees": "#d9f0d3", "more_trees": "#a6dba0",
                 "building": "#d0d0e0"}


def gnss_figure(skies, out, scenes=()):
    """Satellites, PDOP and what became of each epoch (fixed, used, not used) over time, with the
    dataset's scenes shaded as in the paper's satellite figure."""
    fig, (a, b) = plt.subplots(2, 1, figsize=(11, 6), sharex=True)
    t_first = skies[0][1]["t"][0]
    for t_start, t_end, kind in scenes:
        for ax in (a, b):
            ax.axvspan(t_start - t_first, t_end - t_first, color=SCENE_COLOURS.get(kind, "#eeeeee"),
                       alpha=0.6, lw=0)
        a.text(0.5 * (t_start + t_end) - t_first, 0.3, kind.replace("_", " "), ha="center",
               fontsize=8)
    positions_only = not any(p > 0 for _, g in skies for p in g["pdop"])  # NaN compares false
    for name, g in skies:
        t0 = t_first  # one time axis for every run and the scenes
        t = [x - t0 for x in g["t"]]
        a.step(t, g["satellites"], where="post", label=f"{name}: satellites")
        b.plot(t, g["pdop"], label=f"{name}: PDOP")
        top = max(g["satellites"] + [1]) + 1
        for flag, colour, what in ((lambda u, f: f, "g", "fixed"),
                                   (lambda u, f: u and not f, "orange",
                                    "position used" if positions_only else "float"),
                                   (lambda u, f: not u, "r", "not used")):
            pick = [x for x, u, f in zip(t, g["used"], g["fixed"]) if flag(u, f)]
            if pick:
                a.plot(pick, [top] * len(pick), "|", color=colour, label=f"{name}: {what}")
    a.set_ylabel("satellites above the mask")
    a.set_ylim(bottom=0)
    if not positions_only:
        b.set_ylabel("PDOP (log scale)")
        b.set_yscale("log")  # a few epochs with 3-4 satellites reach hundreds
    else:  # the LC scheme from a position file: no satellites, no PDOP
        b.set_ylabel("PDOP")
        b.text(0.5, 0.5, "no raw GNSS in the run (positions only): no satellites, no PDOP",
               transform=b.transAxes, ha="center", va="center")
    b.set_xlabel("time since the first GNSS epoch [s]")
    for ax in (a, b):
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
    fig.suptitle("GNSS: satellites, fix status and PDOP")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def nees_figure(runs, truth, out):
    fig, ax = plt.subplots(figsize=(11, 4))
    keys = [p[0] for p in PARAMS if p[0] != "pz"]
    for name, cal in runs:
        t0 = cal["t"][0]
        nees = [sum(((cal[k][i] - truth[k]) / cal["sd_" + k][i]) ** 2 for k in keys)
                for i in range(len(cal["t"]))]
        ax.semilogy([x - t0 for x in cal["t"]], nees, label=name)
    ax.axhspan(*CHI2_7, color="g", alpha=0.15, label="χ²(7) 95 %")
    ax.set_xlabel("time since the first GNSS epoch [s]")
    ax.set_ylabel("NEES (diagonal sigmas)")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def box_figure(rows, out):
    """A Monte Carlo --box-csv (seed, estimator, scheme, t_s, err_<q>, sd_<q>): per quantity, box
    plots of |error| and of sigma per estimator, scheme and time (the paper's box-plot figure)."""
    quantities = [c[4:] for c in rows[0].keys() if c.startswith("err_")]
    times = sorted({r["t_s"] for r in rows}, key=float)
    groups = sorted({(r["estimator"], r["scheme"]) for r in rows})
    fig, axes = plt.subplots(len(quantities), 2, figsize=(12, 2.4 * len(quantities)), squeeze=False)
    for row, q in zip(axes, quantities):
        for ax, col, what in ((row[0], "err_" + q, "|error|"), (row[1], "sd_" + q, "sigma")):
            data, labels = [], []
            for est, scheme in groups:
                for t in times:
                    data.append([abs(float(r[col])) for r in rows
                                 if r["estimator"] == est and r["scheme"] == scheme and r["t_s"] == t])
                    labels.append(f"{est} {scheme} {t}s")
            ax.boxplot(data)
            ax.set_xticks(range(1, len(labels) + 1))
            ax.set_xticklabels(labels, rotation=45, ha="right", fontsize=6)
            ax.set_ylabel(f"{q} {what}", fontsize=8)
            ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def flat(prefix, value, rows):
    if isinstance(value, dict):
        for k, v in value.items():
            flat(f"{prefix}.{k}" if prefix else k, v, rows)
    elif isinstance(value, list) and value and all(isinstance(v, (int, float)) for v in value) \
            and len(value) <= 8:
        for i, v in enumerate(value):
            rows.append((f"{prefix}[{i}]", v))
    elif isinstance(value, list) and value and isinstance(value[0], list):
        rows.append((prefix, f"{len(value)}x{len(value[0])} matrix"))
    else:
        rows.append((prefix, value))


def table(summary, title):
    rows = []
    flat("", summary, rows)
    cells = "".join(
        f'<tr><td>{html.escape(k)}</td><td data-key="{html.escape(k)}">{html.escape(repr(v) if isinstance(v, float) else str(v))}</td></tr>'
        for k, v in rows)
    return f"<h2>{html.escape(title)}</h2><table>{cells}</table>"


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    run, out = argv[1], argv[2]
    dataset = argv[3] if len(argv) > 3 and argv[3] else None
    figures, tables = [], []
    truth = truth_of(dataset)
    if os.path.isfile(run):  # a Monte Carlo --box-csv
        with open(run, newline="") as f:
            rows = list(csv.DictReader(f))
        if not rows or "t_s" not in rows[0]:
            print(f"giocal report: {run}: not a Monte Carlo --box-csv file", file=sys.stderr)
            return 1
        box_figure(rows, os.path.join(out, "box.png"))
        figures.append(("box.png", "Monte Carlo errors and sigmas (|error| and sigma per time)"))
    else:
        calibrate_dirs = [(n, os.path.join(run, n)) for n in ("ekf", "fgo")
                          if os.path.exists(os.path.join(run, n, "calibration.csv"))]
        if os.path.exists(os.path.join(run, "calibration.csv")):
            calibrate_dirs = [("run", run)]
        runs = [(n, read_csv(os.path.join(d, "calibration.csv"))) for n, d in calibrate_dirs]
        validations = []
        for n, d in calibrate_dirs:
            with open(os.path.join(d, "summary.json")) as f:
                summary = json.load(f)
            tables.append(table(summary, f"{summary.get('estimator', n)}: summary.json"))
            entry = validation_entry(summary.get("estimator", n), summary.get("validation", {}))
            if entry:
                validations.append(entry)
        summary_path = os.path.join(run, "summary.json")
        if not calibrate_dirs and os.path.exists(summary_path):  # a validate folder
            with open(summary_path) as f:
                summary = json.load(f)
            entry = validation_entry("validate", summary)
            if entry:
                validations.append(entry)
                tables.append(table(summary, "validate: summary.json"))
        if validations:
            validation_figure(validations, os.path.join(out, "validation.png"))
            figures.append(("validation.png", "Validation: " + "; ".join(
                f"{n} {v}" for n, _, v, _, _ in validations)))
        if runs:
            convergence_figure(runs, truth, os.path.join(out, "convergence.png"))
            figures.append(("convergence.png", "Calibration convergence (±3σ)"))
            if truth:
                nees_figure(runs, truth, os.path.join(out, "nees.png"))
                figures.append(("nees.png", "NEES over time"))
        delays = [(n, read_csv(os.path.join(d, "odometer_delay.csv"))) for n, d in calibrate_dirs
                  if os.path.exists(os.path.join(d, "odometer_delay.csv"))]
        delays = [(n, d) for n, d in delays if d.get("t")]
        if delays:
            delay_figure(delays, os.path.join(out, "odometer_delay.png"))
            figures.append(("odometer_delay.png", "Odometer delay state (±3σ)"))
        skies = [(n, read_csv(os.path.join(d, "gnss.csv"))) for n, d in calibrate_dirs
                 if os.path.exists(os.path.join(d, "gnss.csv"))]
        skies = [(n, g) for n, g in skies if g.get("t")]
        if skies:
            scenes = read_scenes(dataset)
            gnss_figure(skies, os.path.join(out, "gnss.png"), scenes)
            figures.append(("gnss.png", "Satellites, fix status and PDOP" + (
                " (scenes shaded: " + ", ".join(k for _, _, k in scenes) + ")" if scenes else "")))
        tracks = [(n, read_csv(os.path.join(d, "trajectory.csv"))) for n, d in calibrate_dirs
                  if os.path.exists(os.path.join(d, "trajectory.csv"))]
        if os.path.exists(os.path.join(run, "error.csv")):  # deadreckon
            with open(os.path.join(run, "summary.json")) as f:
                summary = json.load(f)
            tables.append(table(summary, "deadreckon: summary.json"))
            dr_error_figure(read_csv(os.path.join(run, "error.csv")), os.path.join(out, "dr_error.png"))
            figures.append(("dr_error.png", "Dead-reckoning horizontal error"))
            tracks = [("dead reckoning", read_csv(os.path.join(run, "trajectory.csv")))]
            ref = summary.get("reference")
            if ref and os.path.exists(ref):
                tracks.insert(0, ("reference", read_csv(ref)))
        if dataset and os.path.exists(os.path.join(dataset, "truth.csv")) and not any(
                n == "reference" for n, _ in tracks):
            tracks.insert(0, ("truth", read_csv(os.path.join(dataset, "truth.csv"))))
        if tracks:
            trajectory_figure(tracks, os.path.join(out, "trajectory.png"))
            figures.append(("trajectory.png", "Horizontal trajectory"))
    if not figures:
        print(f"giocal report: {run}: no calibrate, compare, deadreckon or validate outputs found",
              file=sys.stderr)
        return 1
    body = "".join(f'<figure><img src="{f}" alt="{html.escape(c)}"><figcaption>{html.escape(c)}'
                   f"</figcaption></figure>" for f, c in figures)
    page = ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>giocal report</title><style>"
            "body{font-family:sans-serif;margin:2em;max-width:1200px}img{max-width:100%}"
            "table{border-collapse:collapse}td{border:1px solid #ccc;padding:2px 6px;"
            "font-size:13px}</style></head><body>"
            f"<h1>giocal report: {html.escape(os.path.abspath(run))}</h1>" + body +
            "".join(tables) + "</body></html>\n")
    with open(os.path.join(out, "index.html"), "w") as f:
        f.write(page)
    print(f"giocal report: {len(figures)} figures, {len(tables)} tables")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
