"""The figures of `giocal report` (report/giocal_report.py assembles the page): calibration
convergence, delay, trajectory, dead-reckoning error, validation windows, GNSS sky and epochs,
NEES and Monte Carlo box plots, each written as a PNG."""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PARAMS = [("s_v", "V scale", 1.0, ""), ("s_w", "W scale", 1.0, ""), ("px", "p_b_m x", 1.0, "m"),
          ("py", "p_b_m y", 1.0, "m"), ("pz", "p_b_m z", 1.0, "m"), ("roll", "roll", 1.0, "deg"),
          ("pitch", "pitch", 1.0, "deg"), ("yaw", "yaw", 1.0, "deg")]
# chi-square 95 % two-sided bounds for 7 degrees of freedom (NEES of the observable states)
CHI2_7 = (1.69, 16.01)


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
