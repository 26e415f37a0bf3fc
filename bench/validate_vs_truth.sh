#!/usr/bin/env bash
# Does `validate`'s verdict (no truth: the dataset's own RTK fixes as the reference) agree with
# what the truth says? For each seed: the field preset simulated, `calibrate` (which validates at
# its end), then each of its validation windows dead-reckoned again with `deadreckon` against
# truth.csv, with the calibration as it stood when the window began and with the guess; the
# truth's verdict follows validate's rule (mean ratio below 0.9 and most windows better: better;
# above 1.1 and most worse: worse; else no better). Prints both verdicts per seed and the count
# that agree. GUESS=truth starts each drive from its true calibration instead (dataset.yaml's
# initial_calibration replaced, its sigmas kept). On the field preset both verdicts still say
# "better" (seeds 7101-7102: validate's ratio 0.11 and 0.17, the truth's 0.19 and 0.50): its gyro
# triad is tilted against the accelerometers, which the true q_b_m leaves out and the estimate
# absorbs, and the guess keeps its sigmas (0.5 m, 5 deg), which the dead reckoning holds as
# consider: exact values stated that loosely still dead-reckon worse (the odometer is
# de-weighted). GUESS=known also states them tightly (s_v, s_w 1e-3, p_b_m 1 cm, 0.1 deg), and
# ALIGNED=1 simulates the IMU without its misalignment (misalignment_deg: 0): together, a guess
# as good as a calibration can be, the "no better" side. NO_BASE=1 simulates a rover alone:
# calibrate and validate take the single-receiver scheme (validate against the rover's own
# track, errors from each window's start).
# Usage: [GUESS=truth|known] [ALIGNED=1] [NO_BASE=1] bench/validate_vs_truth.sh
#        [first seed, default 7101] [seeds, default 10] [ekf|fgo]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
first="${1:-7101}"
count="${2:-10}"
estimator="${3:-ekf}"
giocal="${GIOCAL:-$root/build/apps/giocal}"
[ -x "$giocal" ] || { echo "build first: bash scripts/setup.sh"; exit 1; }
work="$(mktemp -d /tmp/giocal_validate_truth.XXXXXX)"
trap 'rm -rf "$work"' EXIT
preset="$root/config/sim/field.yaml"
if [ "${ALIGNED:-}" = 1 ]; then
  sed -e 's/^  misalignment_deg: .*/  misalignment_deg: 0.0/' \
    -e "s|\.\./\.\./data/|$root/data/|" "$preset" > "$work/field_aligned.yaml"
  preset="$work/field_aligned.yaml"
fi
agree=0
total=0
for seed in $(seq "$first" $((first + count - 1))); do
  d="$work/data$seed"
  run="$work/cal$seed"
  "$giocal" simulate --config "$preset" --out "$d" --seed "$seed" \
    ${NO_BASE:+--no-base} > /dev/null
  if [ "${GUESS:-}" = truth ] || [ "${GUESS:-}" = known ]; then
    /usr/bin/python3 - "$d" "$GUESS" <<'PY'
import re, sys
d, mode = sys.argv[1], sys.argv[2]
tight = {"s_v": "0.001", "s_w": "0.001", "p_b_m": "[0.01, 0.01, 0.01]",
         "rpy_b_m_deg": "[0.1, 0.1, 0.1]"}
truth = {}
for line in open(f"{d}/truth_calib.yaml"):
    m = re.match(r"(s_v|s_w|p_b_m|q_b_m|rpy_b_m_deg): (.*)", line)
    if m:
        truth[m.group(1)] = m.group(2)
out, inside = [], False
for line in open(f"{d}/dataset.yaml"):
    if line.startswith("initial_calibration:"):
        inside = True
    elif inside and not line.startswith(" "):
        inside = False
    m = re.match(r"(  )(s_v|s_w|p_b_m|q_b_m|rpy_b_m_deg): ", line)
    if inside and m:
        line = f"  {m.group(2)}: {truth[m.group(2)]}\n"
    m = re.match(r"    (s_v|s_w|p_b_m|rpy_b_m_deg): ", line)
    if inside and m and mode == "known":
        line = f"    {m.group(1)}: {tight[m.group(1)]}\n"
    out.append(line)
open(f"{d}/dataset.yaml", "w").write("".join(out))
PY
  fi
  code=0
  "$giocal" calibrate --data "$d" --estimator "$estimator" --out "$run" --quiet > /dev/null \
    || code=$?
  [ "$code" -eq 0 ] || [ "$code" -eq 3 ] || { echo "seed $seed: calibrate exited $code"; exit 1; }
  # Each window: start and length from the run's validation, dead-reckoned against the truth.
  windows=$(/usr/bin/python3 -c "import json, sys
v = json.load(open(sys.argv[1])).get('validation', {})
for w in v.get('per_window', []): print(w['start_s'], w['duration_s'])" "$run/summary.json")
  [ -n "$windows" ] || { echo "seed $seed: no validation windows"; continue; }
  rows=""
  while read -r start duration; do
    for source in "$run/calibration.csv@$start" guess; do
      out="$work/dr$seed"
      rm -rf "$out"
      "$giocal" deadreckon --data "$d" --calibration "$source" --start "$start" \
        --duration "$duration" --out "$out" --quiet > /dev/null
      rows+="$(/usr/bin/python3 -c "import json, sys
print(json.load(open(sys.argv[1]))['horizontal_max_m'])" "$out/summary.json") "
    done
    rows+=$'\n'
  done <<< "$windows"
  /usr/bin/python3 - "$seed" "$run/summary.json" "$rows" <<'PY' | tee -a "$work/verdicts.txt"
import json, sys
seed, summary, rows = sys.argv[1], sys.argv[2], sys.argv[3]
v = json.load(open(summary))["validation"]
pairs = [tuple(map(float, r.split())) for r in rows.strip().splitlines()]
cal = sum(p[0] for p in pairs) / len(pairs)
guess = sum(p[1] for p in pairs) / len(pairs)
ratio = cal / guess if guess > 0 else 1.0
better = sum(1 for c, g in pairs if c < g)
n = len(pairs)
truth = ("better" if ratio < 0.9 and 2 * better > n else
         "worse" if ratio > 1.1 and 2 * (n - better) > n else "no better")
print(f"seed {seed}: validate {v['verdict']:9s} (ratio {v['ratio']:.2f}, {v['better_windows']} of "
      f"{v['windows']} better)   truth {truth:9s} (ratio {ratio:.2f}, {cal:.2f} / {guess:.2f} m, "
      f"{better} of {n} better)   "
      f"{'agree' if truth == v['verdict'] else 'DISAGREE'}")
PY
  total=$((total + 1))
  tail -1 "$work/verdicts.txt" | grep -q " agree$" && agree=$((agree + 1))
done
echo "$estimator: validate's verdict agrees with the truth's on $agree of $total seeds"
