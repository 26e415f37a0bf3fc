#!/bin/bash
# How consistent could the EKF's sigma be if it were linearized at the truth (the limit of
# first-estimate Jacobians)? Per seed of the paper preset: the EKF's final error and reported sigma
# (`giocal calibrate`), and the sigma of the same filter held on the truth (`giocal observability`,
# positions for double differences). Prints the RMS over seeds of error / sigma for both sigmas.
# usage: bench/linearization_bound.sh [first_seed] [seeds]   (default 301 20; about 1 min)
set -euo pipefail
first=${1:-301}
n=${2:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
giocal=$root/build/apps/giocal
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for ((s = first; s < first + n; s++)); do
  d=$work/paper-$s
  "$giocal" simulate --config "$root/config/sim/paper.yaml" --out "$d" --seed "$s" >/dev/null
  "$giocal" observability --data "$d" --out "$d/obs" >/dev/null
  "$giocal" calibrate --data "$d" --estimator ekf --out "$d/ekf" --quiet >/dev/null
  echo "$d"
done >"$work/runs.txt"
python3 - "$work/runs.txt" <<'P'
import json, math, sys
names = ["p_b_m.x", "p_b_m.y", "roll of q_b_m", "pitch of q_b_m", "yaw of q_b_m", "s_v", "s_w"]
def err_sd(s):
    e, sd = s["error"], s["sd"]
    return ([e["p_b_m"][0], e["p_b_m"][1]] + e["rpy_b_m_deg"] + [e["s_v"], e["s_w"]],
            [sd["p_b_m"][0], sd["p_b_m"][1]] + sd["rpy_b_m_deg"] + [sd["s_v"], sd["s_w"]])
ekf_r, bound_r, ratio = [[] for _ in names], [[] for _ in names], [[] for _ in names]
for d in open(sys.argv[1]).read().split():
    s = json.load(open(d + "/ekf/summary.json"))
    o = json.load(open(d + "/obs/observability.json"))["expected_sigma"]
    err, sd = err_sd(s)
    for k, name in enumerate(names):
        ekf_r[k].append((err[k] / sd[k]) ** 2)
        bound_r[k].append((err[k] / o[name]) ** 2)
        ratio[k].append(o[name] / sd[k])
rms = lambda v: math.sqrt(sum(v) / len(v))
print(f"{'state':16s} {'err/sd EKF':>11s} {'err/sd truth-linearized':>24s} {'sd ratio':>9s}")
for k, name in enumerate(names):
    print(f"{name:16s} {rms(ekf_r[k]):11.2f} {rms(bound_r[k]):24.2f} {sum(ratio[k]) / len(ratio[k]):9.2f}")
print(f"{len(ekf_r[0])} seeds; sd ratio: mean truth-linearized sigma / the EKF's reported sigma")
P
