#!/usr/bin/env bash
# The Monte Carlo split into shards run by GNU parallel and merged prints the same summary as one
# run over the same seeds; the full-batch targets; merge errors naming the file and line.
# Usage: test_monte_carlo_shards.sh <giocal_monte_carlo>
set -euo pipefail
mc="$1"
work="$(mktemp -d /tmp/giocal_shards.XXXXXX)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
summary() { sed -n '/^Mean absolute/,$p' "$1" | grep -v 'timing\|peak memory'; }

"$mc" --seeds 3 --first 901 --estimator ekf --results "$work/all.csv" > "$work/all.txt"
parallel --will-cite --halt now,fail=1 "$mc" --seeds 3 --first 901 --estimator ekf --shard {}/2 \
  --results "$work/shard{}.csv" ">" /dev/null ::: 1 2
[ "$(grep -c '^90[0-9],ekf,' "$work/shard1.csv")" = 2 ] || fail "shard 1/2 should hold seeds 901, 903"
[ "$(grep -c '^90[0-9],ekf,' "$work/shard2.csv")" = 1 ] || fail "shard 2/2 should hold seed 902"
"$mc" --merge "$work/shard2.csv" "$work/shard1.csv" > "$work/merged.txt"
diff <(summary "$work/all.txt") <(summary "$work/merged.txt") || fail "merged summary differs"
grep -q "over 3 seeds" "$work/merged.txt" || fail "merged summary does not count 3 seeds"

# The accuracy targets against a 'full batch': the same rows under another name give ratio 1.
sed 's/,ekf,/,batch,/' "$work/all.csv" | grep -v ',guess,' > "$work/batch.csv"
"$mc" --merge "$work/all.csv" "$work/batch.csv" --batch batch > "$work/targets.txt"
grep -E '^ekf MAE / batch +1\.00   +1\.00   +1\.00 ' "$work/targets.txt" > /dev/null ||
  { cat "$work/targets.txt"; fail "ekf against itself as the batch should be 1.00"; }

# Shards of another run, or the same shard twice, are refused with the file and line.
sed '1s/paper.yaml/field.yaml/' "$work/shard2.csv" > "$work/other.csv"
if "$mc" --merge "$work/shard1.csv" "$work/other.csv" > /dev/null 2> "$work/err.txt"; then
  fail "merging shards of different runs succeeded"
fi
grep -q "other.csv:1: computed from another run" "$work/err.txt" || { cat "$work/err.txt"; fail "message"; }
if "$mc" --merge "$work/shard1.csv" "$work/shard1.csv" > /dev/null 2> "$work/err.txt"; then
  fail "merging a shard twice succeeded"
fi
grep -q "shard1.csv:3: seed 901 of guess found twice" "$work/err.txt" || { cat "$work/err.txt"; fail "message"; }
echo "shards: ok"
