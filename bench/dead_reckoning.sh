#!/usr/bin/env bash
# The paper's field evaluation on the field preset: for each seed, calibrate on the field drive
# (config/sim/field.yaml) with each scheme (LC from giocal rtk's solution, TC-WAR, TC-AR) and
# estimator, take the calibration at the end of each
# of its four scenes (open sky, few trees, more trees, building), and dead-reckon a separate test
# drive of the same robot (bench/field_test_drive.yaml: another route, seed + 1000: new noise)
# through 1000 s without GNSS after 100 s with it. Prints horizontal MAX and RMSE per scene and
# scheme (mean over seeds), the initial guess, and the true calibration as the floor; and
# "draw": the truth plus an error drawn from TC-AR's own sigmas at that scene
# (bench/draw_calibration.py), what an estimator as precise as TC-AR claims would give.
# Usage: bench/dead_reckoning.sh [--gyro-tilt] [--single] [--shard k/n] [--results <file.csv>]
#          [seed...]
#          (--single: also the single-receiver scheme, --gnss single on the same calibration
#          drive simulated as a rover alone, simulate --no-base; "SINGLE" rows, and its MAX
#          against TC-AR's, target <= 1.2)
#          (--gyro-tilt: every calibration also estimates the gyro's tilt against the
#          accelerometer, calibration.estimate_gyro_tilt, and dead reckoning applies it)
#          (about 5 minutes per seed on an idle machine; --shard: only the k-th of every n seeds of
#          the list, one of n independent processes; --results: keep the per-seed rows)
#        bench/dead_reckoning.sh --merge <file.csv>...   (the table of several shards' rows)
# For example, with GNU parallel on two cores:
#   parallel bench/dead_reckoning.sh --shard {}/2 --results dr{}.csv 41 42 43 44 ::: 1 2
#   bench/dead_reckoning.sh --merge dr1.csv dr2.csv
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
giocal="${GIOCAL_BIN:-$root/build/apps/giocal}"  # GIOCAL_BIN: another build
shard=1 shards=1 keep="" merge=() tilt=0 single=0
while [ $# -gt 0 ]; do
  case "$1" in
    --gyro-tilt) tilt=1; shift ;;
    --single) single=1; shift ;;
    --shard) IFS=/ read -r shard shards <<< "$2"; shift 2 ;;
    --results) keep="$2"; shift 2 ;;
    --merge) shift; merge=("$@"); break ;;
    *) break ;;
  esac
done
if ! [[ "$shard" =~ ^[0-9]+$ && "$shards" =~ ^[0-9]+$ ]] || [ "$shard" -lt 1 ] || [ "$shard" -gt "$shards" ]; then
  echo "dead_reckoning.sh: --shard $shard/$shards: expected k/n with 1 <= k <= n" >&2; exit 2
fi
all=("${@:-31 32 33}")
read -r -a all <<< "${all[*]}"
seeds=()
for i in "${!all[@]}"; do
  [ $(( i % shards )) -eq $(( shard - 1 )) ] && seeds+=("${all[$i]}")
done
work="$(mktemp -d /tmp/giocal_dr.XXXXXX)"
trap 'rm -rf "$work"' EXIT
printf 'calibration:\n  ambiguity_resolution: 0\n  estimate_gyro_tilt: %s\n' "$tilt" > "$work/war.yaml"
printf 'calibration:\n  estimate_gyro_tilt: %s\n' "$tilt" > "$work/ar.yaml"
scene_ends=(320 630 940 end)
results="$work/results.csv"
echo "seed,scheme,scene,max,rmse" > "$results"
if [ "${#merge[@]}" -gt 0 ]; then
  for f in "${merge[@]}"; do
    [ "$(head -1 "$f")" = "seed,scheme,scene,max,rmse" ] ||
      { echo "dead_reckoning.sh: $f:1: not a results file of this bench" >&2; exit 1; }
    tail -n +2 "$f" >> "$results"
  done
  seeds=()
fi
dr() {  # dr <seed> <scheme> <scene> <calibration source>
  "$giocal" deadreckon --data "$work/test_$1" --calibration "$4" --start 100 --duration 1000 \
    --out "$work/dr" --overwrite > /dev/null
  python3 -c "import json,sys; s=json.load(open('$work/dr/summary.json')); \
print('$1,$2,$3,%.3f,%.3f' % (s['horizontal_max_m'], s['horizontal_rmse_m']))" >> "$results"
}
for seed in "${seeds[@]}"; do
  "$giocal" simulate --config "$root/config/sim/field.yaml" --out "$work/cal_$seed" \
    --seed "$seed" > /dev/null
  "$giocal" simulate --config "$root/bench/field_test_drive.yaml" --out "$work/test_$seed" \
    --seed "$((seed + 1000))" > /dev/null
  # The same calibration drive as a rover alone (the motion sensors draw alike): one receiver.
  [ "$single" = 1 ] && "$giocal" simulate --config "$root/config/sim/field.yaml" --no-base \
    --out "$work/alone_$seed" --seed "$seed" > /dev/null
  "$giocal" rtk --rover "$work/cal_$seed/rover.obs" --base "$work/cal_$seed/base.obs" \
    --nav "$work/cal_$seed/nav.rnx" --out "$work/cal_$seed.pos" > /dev/null
  # The truth and the guess do not depend on the scene: run once, listed under every scene.
  for scheme in truth guess; do
    dr "$seed" "$scheme" "${scene_ends[0]}" "$scheme:$work/cal_$seed"
    row=$(tail -1 "$results")
    for scene in "${scene_ends[@]:1}"; do
      echo "$row" | sed "s/,$scheme,${scene_ends[0]},/,$scheme,$scene,/" >> "$results"
    done
  done
  for est in ekf fgo; do
    for scheme in LC TC-WAR TC-AR; do
      config="--config $work/ar.yaml"
      [ "$scheme" = TC-WAR ] && config="--config $work/war.yaml"
      [ "$scheme" = LC ] && config="--gnss lc --pos $work/cal_$seed.pos --config $work/ar.yaml"
      # shellcheck disable=SC2086
      "$giocal" calibrate --data "$work/cal_$seed" --estimator "$est" $config \
        --out "$work/run" --overwrite > /dev/null
      for scene in "${scene_ends[@]}"; do
        if [ "$scene" = end ]; then source="$work/run/summary.json"
        else source="$work/run/calibration.csv@$scene"; fi
        dr "$seed" "$scheme-$est" "$scene" "$source"
        if [ "$scheme" = TC-AR ]; then
          # The truth with an error drawn from this run's sigmas: what its sigma alone costs.
          python3 "$root/bench/draw_calibration.py" "$work/run" "$work/cal_$seed" "$scene" \
            "$work/draw" "$seed"
          at="$scene"; [ "$scene" = end ] && at=100000
          dr "$seed" "draw-$est" "$scene" "$work/draw/calibration.csv@$at"
        fi
      done
    done
  done
  for est in ekf fgo; do
    [ "$single" = 1 ] || break
    "$giocal" calibrate --data "$work/alone_$seed" --estimator "$est" --config "$work/ar.yaml" \
      --out "$work/run" --overwrite > /dev/null
    for scene in "${scene_ends[@]}"; do
      if [ "$scene" = end ]; then source="$work/run/summary.json"
      else source="$work/run/calibration.csv@$scene"; fi
      dr "$seed" "SINGLE-$est" "$scene" "$source"
    done
  done
  echo "seed $seed done" >&2
done
if [ -n "$keep" ]; then cp "$results" "$keep.tmp" && mv "$keep.tmp" "$keep"; fi
python3 - "$results" <<'PY'
import csv, sys, collections
rows = list(csv.DictReader(open(sys.argv[1])))
seeds = sorted({r["seed"] for r in rows})
scenes = ["320", "630", "940", "end"]
names = {"320": "open sky", "630": "few trees", "940": "more trees", "end": "building"}
schemes = ["guess", "LC-ekf", "TC-WAR-ekf", "TC-AR-ekf", "LC-fgo", "TC-WAR-fgo", "TC-AR-fgo",
           "truth"]
v = collections.defaultdict(list)
for r in rows:
    v[(r["scheme"], r["scene"])].append((float(r["max"]), float(r["rmse"])))
schemes += [s for s in ["draw-ekf", "draw-fgo", "SINGLE-ekf", "SINGLE-fgo"]
            if any(k[0] == s for k in v)]
print("dead reckoning of the test drive, 1000 s without GNSS; horizontal MAX / RMSE [m], mean of "
      "seeds %s; calibration taken at the end of each scene of the calibration drive" % " ".join(seeds))
print("%-12s" % "scheme" + "".join("%22s" % names[s] for s in scenes))
for sc in schemes:
    cells = []
    for s in scenes:
        x = v[(sc, s)]
        cells.append("%22s" % ("%.2f / %.2f" % (sum(a for a, _ in x) / len(x), sum(b for _, b in x) / len(x))))
    print("%-12s" % sc + "".join(cells))
print("TC-AR MAX against the true calibration's (target <= 1.1), per scene:")
for est in ["ekf", "fgo"]:
    ratios = []
    for s in scenes:
        ar = sum(a for a, _ in v[("TC-AR-" + est, s)]) / len(seeds)
        tr = sum(a for a, _ in v[("truth", s)]) / len(seeds)
        ratios.append("%22.2f" % (ar / tr))
    print("%-12s" % ("TC-AR-" + est) + "".join(ratios))
for est in ["ekf", "fgo"]:  # the truth with errors of TC-AR's sigmas, when the rows have it
    if not any(k[0] == "draw-" + est for k in v):
        continue
    print("%-12s" % ("draw-" + est) + "".join(
        "%22.2f" % (sum(a for a, _ in v[("draw-" + est, s)]) / sum(a for a, _ in v[("truth", s)]))
        for s in scenes))
for est in ["ekf", "fgo"]:  # one receiver against RTK, when the rows have it
    if not any(k[0] == "SINGLE-" + est for k in v):
        continue
    print("%-12s" % ("SINGLE/AR-" + est) + "".join(
        "%22.2f" % (sum(a for a, _ in v[("SINGLE-" + est, s)]) /
                    sum(a for a, _ in v[("TC-AR-" + est, s)])) for s in scenes))
print("TC-AR better than LC and TC-WAR (MAX), per scene:")
for est in ["ekf", "fgo"]:
    cells = []
    for s in scenes:
        ar = sum(a for a, _ in v[("TC-AR-" + est, s)])
        lc = sum(a for a, _ in v[("LC-" + est, s)])
        war = sum(a for a, _ in v[("TC-WAR-" + est, s)])
        cells.append("%22s" % ("LC %s, WAR %s" % ("yes" if ar < lc else "no",
                                                  "yes" if ar < war else "no")))
    print("%-12s" % est + "".join(cells))
PY
