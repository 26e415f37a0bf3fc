#!/usr/bin/env bash
# Ambiguity resolution in a degraded sky against RTKLIB (issue 23, item 5): simulates the field
# preset (GPS only, four scenes: open sky, few trees, more trees, a building) for the given seeds,
# runs `giocal rtk` and RTKLIB's rnx2rtkp (continuous AR, ratio 3, L1+L2, 15 deg mask, GPS; Debian
# package rtklib) on the same files, and prints per scene and seed the fix rate and the fixes more
# than 5 cm (horizontally) from the true antenna, then the totals over the seeds.
# Usage: [GIOCAL=<another giocal binary>] bench/rtk_under_trees.sh [first seed, default 501]
#        [seeds, default 4] [giocal config]   (PRESET=<a preset> in place of the field preset)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
first="${1:-501}"
count="${2:-4}"
config=()
[ -n "${3:-}" ] && config=(--config "$3")
giocal="${GIOCAL:-$root/build/apps/giocal}"
preset="${PRESET:-$root/config/sim/field.yaml}"
command -v rnx2rtkp >/dev/null || { echo "rnx2rtkp missing: apt-get install rtklib"; exit 1; }
[ -x "$giocal" ] || { echo "build first: bash scripts/setup.sh"; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
printf 'pos1-navsys=1\npos2-arthres=3\npos2-armode=continuous\n' > "$work/rtklib.conf"
for seed in $(seq "$first" $((first + count - 1))); do
  d="$work/field$seed"
  "$giocal" simulate --config "$preset" --out "$d" --seed "$seed" > /dev/null
  base=$(python3 -c "import yaml,sys; print(','.join(str(x) for x in yaml.safe_load(open(sys.argv[1]))['gnss']['base_position_ecef']))" "$d/dataset.yaml")
  "$giocal" rtk --rover "$d/rover.obs" --base "$d/base.obs" --nav "$d/nav.rnx" --base-pos "$base" \
    "${config[@]}" --out "$d/giocal.pos" > /dev/null
  rnx2rtkp -k "$work/rtklib.conf" -p 2 -f 2 -m 15 -r ${base//,/ } "$d/rover.obs" "$d/base.obs" \
    "$d/nav.rnx" -o "$d/rtklib.pos" 2> /dev/null
  python3 "$root/bench/rtk_fix_audit.py" "$d" "$preset" giocal="$d/giocal.pos" \
    rtklib="$d/rtklib.pos" | sed "s/^/seed $seed  /" | tee -a "$work/all.txt"
done
echo "totals over seeds $first-$((first + count - 1)):"
python3 "$root/bench/rtk_fix_audit.py" --sum < "$work/all.txt"
