#!/usr/bin/env bash
# giocal report on a calibrate, a compare and a deadreckon run of a simulated drive: every figure
# exists and is not trivial, every number of the page's tables equals summary.json's, the page
# renders in headless Chromium to a screenshot that is not blank, and a folder without outputs is
# refused with a message. Usage: test_report.sh <giocal binary> <source dir>
set -euo pipefail
giocal="$1"
src="$2"
work="$(mktemp -d /tmp/giocal_report_test.XXXXXX)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$giocal" simulate --config "$src/config/sim/paper.yaml" --out "$work/data" --seed 7 > /dev/null
"$giocal" compare --data "$work/data" --out "$work/cmp" --quiet > /dev/null
"$giocal" deadreckon --data "$work/data" --calibration "$work/cmp/ekf/summary.json" --start 60 \
  --duration 80 --out "$work/dr" --quiet > /dev/null
# Scenes as the simulator writes them for presets with gnss.scenes: shaded in the GNSS figure.
awk -F, 'NR == 2 { printf "t_start,t_end,type\n%.3f,%.3f,open_sky\n%.3f,%.3f,more_trees\n", \
  $1, $1 + 60, $1 + 60, $1 + 150 }' "$work/data/truth.csv" > "$work/data/scenes.csv"
# An odometer-delay state's file as a run with calibration.estimate_odometer_delay writes it.
awk -F, 'NR == 1 { print "t,t_d_odo,sd_t_d_odo"; next } \
  { printf "%s,%.5f,%.5f\n", $1, 0.05 * (1 - exp(-NR / 20)), 0.05 / sqrt(NR) }' \
  "$work/cmp/ekf/calibration.csv" > "$work/cmp/ekf/odometer_delay.csv"
"$giocal" report --run "$work/cmp" --data "$work/data" --out "$work/rep" > /dev/null
grep -q "scenes shaded: open_sky, more_trees" "$work/rep/index.html" || fail "scenes not named"
"$giocal" report --run "$work/dr" --data "$work/data" --out "$work/rep_dr" > /dev/null

# A calibration validated at its end, and `validate` on it: the windows drawn with the verdict.
"$giocal" calibrate --data "$work/data" --out "$work/cal" --quiet > /dev/null
"$giocal" validate --data "$work/data" --run "$work/cal" --outage 30 --windows 3 --out "$work/val" \
  --quiet > /dev/null
"$giocal" report --run "$work/cal" --data "$work/data" --out "$work/rep_cal" > /dev/null
"$giocal" report --run "$work/val" --out "$work/rep_val" > /dev/null
for run in cal val; do
  verdict=$(/usr/bin/python3 -c "import json, sys; s = json.load(open(sys.argv[1])); \
print(s.get('validation', s)['verdict'])" "$work/$run/summary.json")
  grep -q "Validation: [a-z]* $verdict" "$work/rep_$run/index.html" \
    || fail "rep_$run: the validation's verdict ($verdict) not on the page"
done

# A run from positions only (the LC scheme, the real Husky's fixes): no satellites, no PDOP.
"$giocal" import --bag "$src/data/real/husky-robot-localization/test1.bag" --out "$work/husky" \
  > /dev/null
printf 'calibration:\n  lc:\n    use_height: 0\n' > "$work/lc.yaml"
"$giocal" calibrate --data "$work/husky" --gnss lc --pos "$work/husky/gnss.pos" --config \
  "$work/lc.yaml" --out "$work/lc" --quiet > /dev/null
"$giocal" report --run "$work/lc" --data "$work/husky" --out "$work/rep_lc" > /dev/null \
  || fail "report of an LC run from positions only"

for f in rep/convergence.png rep/nees.png rep/gnss.png rep/trajectory.png rep/odometer_delay.png \
         rep_dr/dr_error.png rep_cal/validation.png rep_val/validation.png \
         rep_dr/trajectory.png rep_lc/gnss.png rep_lc/convergence.png; do
  [ -f "$work/$f" ] || fail "$f missing"
  [ "$(stat -c %s "$work/$f")" -gt 10000 ] || fail "$f is $(stat -c %s "$work/$f") bytes"
done
[ ! -e "$work/rep/.giocal-partial."* ] 2>/dev/null || fail "staging folder left behind"

# The numbers of the tables against summary.json (ekf's, fgo's, deadreckon's).
/usr/bin/python3 - "$work" <<'PY'
import html.parser, json, math, sys
work = sys.argv[1]

class Cells(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.tables, self.key = [], None
    def handle_starttag(self, tag, attrs):
        if tag == "table":
            self.tables.append({})
        a = dict(attrs)
        self.key = a.get("data-key") if tag == "td" else None
    def handle_data(self, data):
        if self.key is not None:
            self.tables[-1][self.key] = data
            self.key = None

def flat(prefix, v, out):
    if isinstance(v, dict):
        for k, x in v.items():
            flat(f"{prefix}.{k}" if prefix else k, x, out)
    elif isinstance(v, list) and v and all(isinstance(x, (int, float)) for x in v) and len(v) <= 8:
        for i, x in enumerate(v):
            out[f"{prefix}[{i}]"] = x
    elif not isinstance(v, list):
        out[prefix] = v

checked = 0
for page, summaries in (("rep", ["cmp/ekf", "cmp/fgo"]), ("rep_dr", ["dr"])):
    p = Cells()
    p.feed(open(f"{work}/{page}/index.html").read())
    assert len(p.tables) == len(summaries), (page, len(p.tables))
    for table, run in zip(p.tables, summaries):
        expected = {}
        flat("", json.load(open(f"{work}/{run}/summary.json")), expected)
        for key, value in expected.items():
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                continue
            assert key in table, f"{run}: {key} not in the page"
            got = float(table[key])
            assert got == value or math.isclose(got, value, rel_tol=1e-12), (run, key, got, value)
            checked += 1
assert checked > 100, checked
# The run's options in effect, defaults included (no --config was given).
p = Cells()
p.feed(open(f"{work}/rep/index.html").read())
for key, value in (("options.fgo.window", 30), ("options.calibration.ambiguity_resolution", 1)):
    assert key in p.tables[1] and float(p.tables[1][key]) == value, (key, p.tables[1].get(key))
print(f"report tables: {checked} numbers equal summary.json's")
PY

# Headless Chromium renders the page; the screenshot is not blank.
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1200,1600 \
  --screenshot="$work/shot.png" "file://$work/rep/index.html" > /dev/null 2>&1 \
  || fail "chromium could not render the page"
/usr/bin/python3 - "$work/shot.png" <<'PY'
import sys
import matplotlib.image as mpimg
img = mpimg.imread(sys.argv[1])
std = float(img[..., :3].std())
assert img.shape[0] >= 1000 and std > 0.05, (img.shape, std)
print(f"screenshot {img.shape[1]}x{img.shape[0]}, pixel standard deviation {std:.3f}")
PY

# A Monte Carlo --box-csv: box plots of errors and sigmas.
/usr/bin/python3 - "$work/box.csv" <<'PY'
import random, sys
random.seed(1)
with open(sys.argv[1], "w") as f:
    f.write("seed,estimator,scheme,t_s,err_s_v,sd_s_v,err_yaw,sd_yaw\n")
    for seed in range(10):
        for scheme in ("TC", "TC-LE-OL"):
            for t in (0, 60, 120):
                f.write(f"{seed},ekf,{scheme},{t},{random.gauss(0, 1e-3)},{1e-3},"
                        f"{random.gauss(0, 0.5)},{0.5}\n")
PY
"$giocal" report --run "$work/box.csv" --out "$work/rep_box" > /dev/null
[ "$(stat -c %s "$work/rep_box/box.png")" -gt 10000 ] || fail "box.png too small"

mkdir -p "$work/empty"
if "$giocal" report --run "$work/empty" --out "$work/rep_empty" > "$work/msg" 2>&1; then
  fail "a folder without outputs was accepted"
fi
grep -q "no calibrate, compare, deadreckon or validate outputs found" "$work/msg" || fail "$(cat "$work/msg")"
[ ! -e "$work/rep_empty/index.html" ] || fail "a failed report left index.html"
if "$giocal" report --run "$work/cmp" --out "$work/rep" > "$work/msg" 2>&1; then
  fail "an earlier report was overwritten without --overwrite"
fi
echo "report: ok"
