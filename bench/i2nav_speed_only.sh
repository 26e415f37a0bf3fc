#!/usr/bin/env bash
# A speed-only odometer through the i2Nav text import: the field preset simulated (seed), its
# IMU written as a forward-right-down IMU's increments with the odometer's speed as an 8th column,
# giocal rtk's solution as the i2Nav GNSS position file, the truth as a .nav file; then
# `giocal import --i2nav-imu`, and `calibrate --gnss lc` with both estimators. Prints each
# estimator's errors against the truth (rotated into the FRD axes) with its sigmas, beside the
# same drive calibrated from its full odometer (speed and yaw rate) by the same LC scheme. The
# imported dataset.yaml gets the simulated IMU's noise (as a user edits it for theirs).
# Usage: bench/i2nav_speed_only.sh [seed...]   (default 81; about 2 minutes per seed)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
giocal="$root/build/apps/giocal"
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(81)
work="$(mktemp -d /tmp/giocal_i2nav.XXXXXX)"
trap 'rm -rf "$work"' EXIT
printf "%-5s %-18s %9s %9s %9s %9s %9s %9s\n" seed run "s_v err" "sd" "|p_xy| err" "sd" \
  "yaw(m) err" "sd deg"
for seed in "${seeds[@]}"; do
  sim="$work/sim$seed"
  "$giocal" simulate --config "$root/config/sim/field.yaml" --seed "$seed" --out "$sim" > /dev/null
  "$giocal" rtk --rover "$sim/rover.obs" --base "$sim/base.obs" --nav "$sim/nav.rnx" \
    --out "$sim/rtk.pos" > /dev/null
  /usr/bin/python3 - "$sim" "$work/i2nav$seed" <<'PY'
import sys, os, numpy as np, yaml, math
sim, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
R = np.array([[0, 1, 0], [1, 0, 0], [0, 0, -1.0]])  # FRD axes from the simulator's
imu = np.loadtxt(f"{sim}/imu.csv", delimiter=",", skiprows=1)
odo = np.loadtxt(f"{sim}/odom.csv", delimiter=",", skiprows=1)
W = 604800.0
sow0 = imu[0, 0] % W
dt = np.median(np.diff(imu[:, 0]))
k = np.arange(len(imu))
speed = np.interp(imu[:, 0], odo[:, 0], odo[:, 1])
rows = np.column_stack([sow0 + (k + 0.5) * dt, (imu[:, 1:4] @ R.T) * dt, (imu[:, 4:7] @ R.T) * dt, speed])
np.savetxt(f"{out}/imu.txt", rows, fmt=["%.9f"] + ["%.15g"] * 7)
with open(f"{out}/gnss.txt", "w") as f:
    for line in open(f"{sim}/rtk.pos"):
        if line.startswith("%"):
            continue
        v = line.split()
        y, mo, d = map(int, v[0].split("/")); hh, mm = map(int, v[1].split(":")[:2]); ss = float(v[1].split(":")[2])
        import datetime
        t = (datetime.datetime(y, mo, d, hh, mm) - datetime.datetime(1980, 1, 6)).total_seconds() + ss
        f.write("%.3f %s %s %s %s %s %s\n" % (t % W, v[2], v[3], v[4], v[7], v[8], v[9]))
tr = np.loadtxt(f"{sim}/truth.csv", delimiter=",", skiprows=1)[::40]
def quat_to_R(w, x, y, z):
    return np.array([[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)], [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)], [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]])
Rne = np.array([[0, 1, 0], [1, 0, 0], [0, 0, -1.0]])
with open(f"{out}/truth.nav", "w") as f:
    for r in tr:
        Rb = Rne @ quat_to_R(*r[7:11]) @ R.T
        yaw, pitch, roll = math.atan2(Rb[1, 0], Rb[0, 0]), -math.asin(Rb[2, 0]), math.atan2(Rb[2, 1], Rb[2, 2])
        f.write("%d %.9f %.10f %.10f %.4f %.6f %.6f %.6f %.8f %.8f %.8f\n" % (
            r[0] // W, r[0] % W, r[1], r[2], r[3], r[5], r[4], -r[6], *np.degrees([roll, pitch, yaw])))
c = yaml.safe_load(open(f"{sim}/truth_calib.yaml"))
lever = R @ np.array(c["p_b_g"], dtype=float)
open(f"{out}/lever", "w").write(",".join("%.6f" % x for x in lever))
PY
  "$giocal" import --i2nav-imu "$work/i2nav$seed/imu.txt" --i2nav-pos "$work/i2nav$seed/gnss.txt" \
    --i2nav-nav "$work/i2nav$seed/truth.nav" --lever-arm "$(cat "$work/i2nav$seed/lever")" \
    --out "$work/data$seed" --quiet > /dev/null
  # As a user would: the IMU's own noise (the import writes i2Nav's ICM20602 figures).
  /usr/bin/python3 - "$sim/dataset.yaml" "$work/data$seed/dataset.yaml" <<'PY'
import sys, yaml
sim, out = yaml.safe_load(open(sys.argv[1])), yaml.safe_load(open(sys.argv[2]))
out["imu"] = sim["imu"]
yaml.safe_dump(out, open(sys.argv[2], "w"))
PY
  for est in ekf fgo; do
    "$giocal" calibrate --data "$work/data$seed" --estimator $est --gnss lc \
      --pos "$work/data$seed/gnss.pos" --out "$work/speed_$est$seed" --quiet > /dev/null
    "$giocal" calibrate --data "$sim" --estimator $est --gnss lc --pos "$sim/rtk.pos" \
      --out "$work/full_$est$seed" --quiet > /dev/null
  done
  /usr/bin/python3 - "$work" "$seed" "$sim" <<'PY'
import sys, json, math, yaml, numpy as np
work, seed, sim = sys.argv[1], sys.argv[2], sys.argv[3]
R = np.array([[0, 1, 0], [1, 0, 0], [0, 0, -1.0]])
c = yaml.safe_load(open(f"{sim}/truth_calib.yaml"))
def quat_to_R(w, x, y, z):
    return np.array([[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)], [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)], [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]])
def row(name, path, rot):
    s = json.load(open(path))
    f, sd = s["final"], s["sd"]
    p_true = rot @ np.array(c["p_b_m"], dtype=float)
    q = c["q_b_m"]
    R_true = rot @ quat_to_R(q["w"], q["x"], q["y"], q["z"]) if isinstance(q, dict) else rot @ quat_to_R(*q)
    # About the vehicle's up axis (m's z), whatever the IMU axes: q_b_m = q_true Exp(theta).
    dR = R_true.T @ quat_to_R(*f["q_b_m"])
    e_yaw = math.degrees(math.atan2(dR[1, 0] - dR[0, 1], dR[0, 0] + dR[1, 1]))
    e_p = math.hypot(*(np.array(f["p_b_m"][:2]) - p_true[:2]))
    print("%-5s %-18s %9.5f %9.5f %9.4f %9.4f %9.3f %9.3f" % (seed, name, f["s_v"] - c["s_v"], sd["s_v"],
          e_p, math.hypot(*sd["p_b_m"][:2]), e_yaw, sd["rpy_b_m_deg"][2]))
for est in ("ekf", "fgo"):
    row(f"{est} speed only", f"{work}/speed_{est}{seed}/summary.json", R)
    row(f"{est} speed+yaw", f"{work}/full_{est}{seed}/summary.json", np.eye(3))
PY
done
