#!/usr/bin/env bash
# One receiver against RTK: for each seed and preset, the same drive simulated with a base and
# as a rover alone (--no-base: broadcast orbit and clock errors, drifting atmosphere, receiver
# clock steps, half-cycle slips); the estimator calibrates the first with RTK (TC-AR), the second
# with --gnss single. Prints per preset and state the mean |error| of each scheme and their
# ratio, the mean |error|/sigma, the ratio of the mean stated sigmas (single over RTK: what the
# schemes hold, apart from their luck), the mean NEES7, and the speed.
# Usage: [PRESETS="paper field"] [ESTIMATOR=ekf|fgo] bench/single_receiver.sh [seed...]
#          (a preset is a name in config/sim/ or a path to a .yaml, e.g. the one
#          `PRESET_OUT=<file> bench/real_like_gnss.sh` writes)
#          (default seeds 6001-6010; about 15 s per seed and preset)
#        CONFIG=<yaml> adds a calibrate --config to every run.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
giocal="${GIOCAL_BIN:-$root/build/apps/giocal}"
est="${ESTIMATOR:-ekf}"
seeds=("${@:-6001 6002 6003 6004 6005 6006 6007 6008 6009 6010}")
read -r -a seeds <<< "${seeds[*]}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
config=()
[ -n "${CONFIG:-}" ] && config=(--config "$CONFIG")
for source in ${PRESETS:-paper field}; do
  preset="$(basename "$source" .yaml)"
  [ -f "$source" ] || source="$root/config/sim/$preset.yaml"
  sed "s|\.\./\.\./data/|$root/data/|" "$source" > "$work/$preset.yaml"
  for seed in "${seeds[@]}"; do
    d="$work/$preset-$seed"
    "$giocal" simulate --config "$work/$preset.yaml" --seed "$seed" --out "$d-base" > /dev/null
    "$giocal" simulate --config "$work/$preset.yaml" --seed "$seed" --no-base --out "$d-alone" \
      > /dev/null
    "$giocal" calibrate --data "$d-base" --estimator "$est" --quiet "${config[@]}" --out "$d-rtk" \
      > /dev/null 2>&1 || true
    "$giocal" calibrate --data "$d-alone" --estimator "$est" --quiet "${config[@]}" \
      --out "$d-single" > /dev/null 2>&1 || true
  done
done
python3 - "$work" "$est" "${seeds[@]}" <<'PY'
import json, os, sys
work, est, seeds = sys.argv[1], sys.argv[2], sys.argv[3:]
states = [("s_v", lambda v: v["s_v"]), ("s_w", lambda v: v["s_w"]),
          ("p_b_m.x", lambda v: v["p_b_m"][0]), ("p_b_m.y", lambda v: v["p_b_m"][1]),
          ("roll", lambda v: v["rpy_b_m_deg"][0]), ("pitch", lambda v: v["rpy_b_m_deg"][1]),
          ("yaw", lambda v: v["rpy_b_m_deg"][2])]
for source in os.environ.get("PRESETS", "paper field").split():
    preset = os.path.basename(source).removesuffix(".yaml")
    runs = {"rtk": [], "single": []}
    for seed in seeds:
        for scheme in runs:
            f = os.path.join(work, f"{preset}-{seed}-{scheme}", "summary.json")
            runs[scheme].append(json.load(open(f)) if os.path.exists(f) else None)
    ok = {k: sum(1 for s in v if s and s["status"] == "ok") for k, v in runs.items()}
    print(f"{preset} preset, {est}, seeds {seeds[0]}-{seeds[-1]}: runs ok: RTK {ok['rtk']}, "
          f"single {ok['single']} of {len(seeds)}")
    print(f"  {'state':8} {'RTK |err|':>11} {'single |err|':>13} {'ratio':>6} "
          f"{'RTK err/sd':>11} {'single err/sd':>14} {'sd ratio':>9}")
    for name, get in states:
        row = {}
        for scheme, summaries in runs.items():
            pairs = [(abs(get(s["error"])), abs(get(s["error"])) / get(s["sd"]), get(s["sd"]))
                     for s in summaries if s and s["status"] == "ok"]
            row[scheme] = [sum(p[k] for p in pairs) / len(pairs) for k in range(3)]
        print(f"  {name:8} {row['rtk'][0]:11.5f} {row['single'][0]:13.5f} "
              f"{row['single'][0] / row['rtk'][0]:6.2f} {row['rtk'][1]:11.2f} {row['single'][1]:14.2f} "
              f"{row['single'][2] / row['rtk'][2]:9.2f}")
    for scheme, summaries in runs.items():
        good = [s for s in summaries if s and s["status"] == "ok"]
        nees = sum(s["error"]["nees7"] for s in good) / len(good)
        speed = sum(s["real_time_factor"] for s in good) / len(good)
        print(f"  {scheme}: mean NEES7 {nees:.1f}, mean speed {speed:.0f}x real time")
PY
