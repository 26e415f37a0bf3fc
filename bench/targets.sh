#!/usr/bin/env bash
# The accuracy targets of issue 20 (item 5) in one table, run as independent shards under GNU
# parallel: on the paper preset, the EKF and the factor graph (default window) against the full
# batch (a window covering the whole drive) for efficiency, their err/sigma for consistency, and
# X, Y, roll, W scale against the paper's row; on the field preset, NEES7 of both estimators, with
# the gyro's tilt against the accelerometer estimated (calibration.estimate_gyro_tilt: the
# preset's IMU has misaligned triads).
# Usage: bench/targets.sh [seeds 100] [first 301] [field seeds 8] [field first 301] [shards 4]
# (about 25 minutes for the defaults on two cores). The shards' result files stay in
# $GIOCAL_TARGETS_OUT (default: a temporary folder, removed) for a later --merge.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mc="$root/build/bench/giocal_monte_carlo"
seeds="${1:-100}" first="${2:-301}" field_seeds="${3:-8}" field_first="${4:-301}" n="${5:-4}"
command -v parallel > /dev/null || { echo "targets.sh: needs GNU parallel (Debian parallel)"; exit 1; }
out="${GIOCAL_TARGETS_OUT:-}"
if [ -z "$out" ]; then out="$(mktemp -d /tmp/giocal_targets.XXXXXX)"; trap 'rm -rf "$out"' EXIT; fi
mkdir -p "$out"
printf 'fgo:\n  window: 1000\n' > "$out/batch.yaml"
printf 'calibration:\n  estimate_gyro_tilt: 1\n' > "$out/tilt.yaml"
jobs="$out/jobs.txt"
: > "$jobs"
for k in $(seq 1 "$n"); do
  common="--seeds $seeds --first $first --shard $k/$n"
  echo "$mc $common --estimator fgo --config $out/batch.yaml --label fgo-batch --results $out/paper_batch_$k.csv" >> "$jobs"
  echo "$mc $common --estimator fgo --results $out/paper_fgo_$k.csv" >> "$jobs"
  echo "$mc $common --estimator ekf --results $out/paper_ekf_$k.csv" >> "$jobs"
  field="--preset $root/config/sim/field.yaml --seeds $field_seeds --first $field_first --shard $k/$n"
  field="$field --config $out/tilt.yaml"
  echo "$mc $field --estimator fgo --results $out/field_fgo_$k.csv" >> "$jobs"
  echo "$mc $field --estimator ekf --results $out/field_ekf_$k.csv" >> "$jobs"
done
start=$(date +%s)
# Each shard's own table goes to its log.
parallel --will-cite --halt now,fail=1 --joblog "$out/joblog.txt" "{} > /dev/null" :::: "$jobs"
echo "shards done in $(( $(date +%s) - start )) s of wall time on $(nproc) cores (joblog: per-shard times)"
echo "=== paper preset ($seeds seeds from $first)"
# The guess's rows are in every estimator's shards; keep one copy.
for f in "$out"/paper_fgo_*.csv "$out"/paper_batch_*.csv; do
  grep -v ',guess,' "$f" > "$f.noguess"
done
"$mc" --merge "$out"/paper_ekf_*.csv "$out"/paper_fgo_*.csv.noguess \
  "$out"/paper_batch_*.csv.noguess --batch fgo-batch
echo "=== field preset ($field_seeds seeds from $field_first): NEES7 target near 7"
for f in "$out"/field_fgo_*.csv; do grep -v ',guess,' "$f" > "$f.noguess"; done
"$mc" --merge "$out"/field_ekf_*.csv "$out"/field_fgo_*.csv.noguess
