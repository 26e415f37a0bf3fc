#!/usr/bin/env bash
# Runs `giocal rtk` and RTKLIB's rnx2rtkp (Debian package rtklib) on the same files with comparable
# settings (kinematic, L1+L2, 15 deg mask, the same constellations, ratio 3) in one run, and prints
# the throughput of both and their ratio, plus fix rates and the mean distance between the fixed
# solutions. Usage: bench/rtk_vs_rtklib.sh [repetitions]   (needs build/ from scripts/setup.sh)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
reps="${1:-5}"
giocal="$root/build/apps/giocal"
command -v rnx2rtkp >/dev/null || { echo "rnx2rtkp missing: apt-get install rtklib"; exit 1; }
[ -x "$giocal" ] || { echo "build first: bash scripts/setup.sh"; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
D="$root/data/real"

# name | rnx2rtkp navsys | rnx2rtkp args | giocal args
run_case() {
  local name="$1" navsys="$2" rtklib_args="$3" giocal_args="$4" epochs="$5"
  printf 'pos1-navsys=%s\npos2-arthres=3\n' "$navsys" > "$work/$name.conf"
  local t0 t1 tg tr
  t0=$(date +%s.%N)
  for _ in $(seq "$reps"); do
    eval "$giocal rtk $giocal_args --out $work/$name.giocal.pos --overwrite" > "$work/$name.giocal.log"
  done
  t1=$(date +%s.%N)
  tg=$(python3 -c "print(($t1 - $t0) / $reps)")
  t0=$(date +%s.%N)
  for _ in $(seq "$reps"); do
    eval "rnx2rtkp -k $work/$name.conf -t -p 2 -f 2 -m 15 $rtklib_args -o $work/$name.rtklib.pos" 2>/dev/null
  done
  t1=$(date +%s.%N)
  tr=$(python3 -c "print(($t1 - $t0) / $reps)")
  python3 - "$name" "$epochs" "$tg" "$tr" "$work/$name.giocal.pos" "$work/$name.rtklib.pos" <<'PY'
import math, sys
name, epochs, tg, tr, gpos, rpos = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), sys.argv[5], sys.argv[6]
def read(p):
    out = {}
    for line in open(p):
        if line.startswith('%') or not line.strip():
            continue
        f = line.split()
        out[f[0] + ' ' + f[1][:8]] = (float(f[2]), float(f[3]), float(f[4]), int(f[5]))
    return out
g, r = read(gpos), read(rpos)
gf = sum(1 for v in g.values() if v[3] == 1)
rf = sum(1 for v in r.values() if v[3] == 1)
d = []
for k, v in g.items():
    if k in r and v[3] == 1 and r[k][3] == 1:
        dn = (v[0] - r[k][0]) * 111320.0
        de = (v[1] - r[k][1]) * 111320.0 * math.cos(math.radians(v[0]))
        d.append(math.hypot(dn, de))
print(f"{name:22s} giocal {epochs / tg:8.1f} epochs/s ({gf}/{epochs} fixed)   "
      f"rnx2rtkp {epochs / tr:8.1f} epochs/s ({rf}/{epochs} fixed)   "
      f"throughput ratio giocal/rtklib {tr / tg:5.2f}   "
      f"mean horizontal difference of common fixed epochs {1000 * sum(d) / max(len(d), 1):.1f} mm")
PY
}

M="$D/mosaic-static-nagoya"
G="$D/gsi-static-0759-3040"
BASE_LLH="35.134707705 136.977577939 104.853"
BASE_XYZ="-3817681.1213,3562839.4311,3650159.1593"   # the same point in ECEF
echo "giocal rtk vs rnx2rtkp, mean of $reps runs each (wall time includes reading the files)"
run_case mosaic-GEJC 57 "-l $BASE_LLH $M/rover.obs $M/base.obs $M/base.nav" \
  "--rover $M/rover.obs --base $M/base.obs --nav $M/base.nav --base-pos $BASE_XYZ" 301
run_case gsi-GPS 1 "-r -3978241.958 3382840.234 3649900.853 $G/07590920.05o $G/30400920.05o $G/30400920.05n $G/07590920.05n" \
  "--rover $G/07590920.05o --base $G/30400920.05o --nav $G/30400920.05n --nav $G/07590920.05n --base-pos -3978241.958,3382840.234,3649900.853" 120
