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
import os
import sys

from figures import (box_figure, convergence_figure, delay_figure, dr_error_figure,  # noqa
                     gnss_figure, nees_figure, trajectory_figure, validation_figure)


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
