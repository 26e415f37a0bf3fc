#!/usr/bin/env bash
# Builds the libFuzzer harnesses with clang into build-fuzz/ (ASan + UBSan, -DGIOCAL_FUZZ=ON) and
# runs each for <seconds> (default 60) from a seed corpus of giocal's own files (data/, config/ and
# a simulated dataset); prints per harness the executions, and the crashes, timeouts (5 s) and
# out-of-memory (2 GB) it found; their inputs are kept in <out> (default /tmp/giocal_fuzz). With
# <runs>, each harness stops after that many executions (or <seconds>, whichever comes first).
# GIOCAL_FUZZ_HARNESSES="fuzz_ubx ..." picks harnesses.
# Usage: fuzz/run.sh [seconds] [out] [runs]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
secs="${1:-60}"
out="${2:-/tmp/giocal_fuzz}"
runs="${3:--1}"
bash "$root/scripts/setup.sh" > /dev/null  # packages and the normal build (for the seed dataset)
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="${missing:-} $p"
done
if [ -n "${missing:-}" ]; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $missing > /dev/null
fi
CC=clang CXX=clang++ cmake -S "$root" -B "$root/build-fuzz" -DGIOCAL_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
all_harnesses=(fuzz_rinex_obs fuzz_rinex_nav fuzz_csv_logs fuzz_yaml fuzz_ubx fuzz_ros_message)
read -r -a harnesses <<< "${GIOCAL_FUZZ_HARNESSES:-${all_harnesses[*]}}"
cmake --build "$root/build-fuzz" -j "$(nproc)" --target "${harnesses[@]}" > /dev/null

# Seed corpora.
rm -rf "$out" && mkdir -p "$out"
sim="$out/sim"
"$root/build/apps/giocal" simulate --config "$root/config/sim/paper.yaml" --out "$sim" > /dev/null
for h in "${all_harnesses[@]}"; do mkdir -p "$out/$h/corpus"; done  # every seed set is made
k=0
for f in "$root"/data/real/*/*.obs "$root"/data/real/*/*o "$sim/rover.obs"; do
  [ -f "$f" ] && head -c 60000 "$f" > "$out/fuzz_rinex_obs/corpus/seed$((k++))"
done
for f in "$root"/data/real/*/*.nav "$root"/data/real/*/*n "$sim/nav.rnx"; do
  [ -f "$f" ] && head -c 60000 "$f" > "$out/fuzz_rinex_nav/corpus/seed$((k++))"
done
i=0
for f in imu.csv odom.csv truth.csv; do
  { printf "\\x$(printf %02x $i)"; head -40 "$sim/$f"; } > "$out/fuzz_csv_logs/corpus/$f"
  i=$((i + 1))
done
{ printf '\x03'; head -40 "$root/data/real/mosaic-static-nagoya/rover_rtk.pos"; } \
  > "$out/fuzz_csv_logs/corpus/pos"
printf '\x04t_start,t_end,type\n1403252430,1403252750,open_sky\n1403252750,1403253060,few_trees\n' \
  > "$out/fuzz_csv_logs/corpus/scenes"
# i2Nav text: IMU increments with an odometer speed, GNSS positions, reference navigation.
printf '\x05456300.000 1e-5 -2e-5 3e-6 0.001 -0.002 -0.049 1.5\n456300.005 1.1e-5 -2e-5 3e-6 0.001 -0.002 -0.049 1.51\n456300.010 1e-5 -2e-5 3e-6 0.001 -0.002 -0.049 1.52\n' \
  > "$out/fuzz_csv_logs/corpus/i2nav_imu"
printf '\x06456300.000 30.4447873701 114.4718632047 20.899 0.005 0.004 0.01\n456301.000 30.4447874 114.4718633 20.9 0.005 0.004 0.01\n' \
  > "$out/fuzz_csv_logs/corpus/i2nav_pos"
printf '\x072218 456300.000 30.4447873701 114.4718632047 20.899 0.0 0.0 0.0 0.854 -2.034 185.702\n2218 456300.005 30.4447873701 114.4718632047 20.899 0.01 0.0 0.0 0.854 -2.034 185.702\n' \
  > "$out/fuzz_csv_logs/corpus/i2nav_nav"
# The real F9P log in pieces of 20 kB (a whole log is slow per execution), and its first piece
# followed by a cycle of BeiDou D2 pages 1-10 of a GEO satellite (the log has none).
if [ -d "$out/fuzz_ubx" ]; then
  split -b 20000 -a 3 "$root/data/real/ublox-f9p-walk/gnss_1730.ubx" "$out/fuzz_ubx/corpus/seed"
  python3 - "$root/data/real/ublox-f9p-walk/gnss_1730.ubx" "$out/fuzz_ubx/corpus/geo_d2" <<'PY'
import random, struct, sys
rng = random.Random(3)
def frame(cls, mid, payload):
    body = bytes([cls, mid]) + struct.pack("<H", len(payload)) + payload
    a = b = 0
    for x in body:
        a = (a + x) & 255
        b = (b + a) & 255
    return b"\xb5\x62" + body + bytes([a, b])
log, out, k = open(sys.argv[1], "rb").read(), b"", 0
while len(out) < 15000:  # whole UBX frames of the log's start
    k = log.index(b"\xb5\x62", k)
    n = 8 + struct.unpack("<H", log[k + 4:k + 6])[0]
    out, k = out + log[k:k + n], k + n
for page in range(1, 11):
    bits = rng.getrandbits(300)
    def put(pos, length, value):
        global bits
        shift = 300 - pos - length
        bits = (bits & ~(((1 << length) - 1) << shift)) | (value << shift)
    sow = 345600 + 3 * (page - 1)
    put(0, 11, 0x712); put(15, 3, 1); put(18, 8, sow >> 12); put(30, 12, sow & 0xFFF); put(42, 4, page)
    words = [(bits >> (30 * (9 - w))) & 0x3FFFFFFF for w in range(10)]
    out += frame(0x02, 0x13, bytes([3, 3, 1, 0, 10, 0, 2, 0]) + b"".join(struct.pack("<I", w) for w in words))
open(sys.argv[2], "wb").write(out)
PY
fi
# ROS messages: the first byte picks ROS 1 or CDR, then a definition, a NUL and message bytes.
if [ -d "$out/fuzz_ros_message" ]; then
  printf '\x00Header header\nfloat64[3] v\nstring s\nMSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n\0\x01\0\0\0\x10\0\0\0\x20\0\0\0\x03\0\0\0imu' \
    > "$out/fuzz_ros_message/corpus/header"
  printf '\x01int32 a\nfloat64[] b\n\0\0\x01\0\0\x05\0\0\0\x02\0\0\0' > "$out/fuzz_ros_message/corpus/cdr"
  # gnss_comm messages (flags 2): a GnssMeasMsg of one satellite, and a GnssEphemMsg.
  python3 - "$out/fuzz_ros_message/corpus" <<'PY'
import struct, sys
time = "MSG: gnss_comm/GnssTimeMsg\nuint32 week\nfloat64 tow\n"
obs = ("GnssObsMsg[] meas\nMSG: gnss_comm/GnssObsMsg\nGnssTimeMsg time\nuint32 sat\n"
       + "".join(f"{t}[] {n}\n" for t, n in [("float64", "freqs"), ("float64", "CN0"),
         ("uint8", "LLI"), ("uint8", "code"), ("float64", "psr"), ("float64", "psr_std"),
         ("float64", "cp"), ("float64", "cp_std"), ("float64", "dopp"), ("float64", "dopp_std"),
         ("uint8", "status")]) + time)
f64 = lambda *v: struct.pack("<I", len(v)) + b"".join(struct.pack("<d", x) for x in v)
u8 = lambda *v: struct.pack("<I", len(v)) + bytes(v)
meas = (struct.pack("<I", 1) + struct.pack("<Id", 2300, 345600.0) + struct.pack("<I", 5)
        + f64(1575.42e6) + f64(45.0) + u8(0) + u8(1) + f64(2.1e7) + f64(1.0) + f64(1.1e8)
        + f64(0.01) + f64(-1200.0) + f64(0.1) + u8(3))
names = ["A", "e", "i0", "omg", "OMG0", "M0", "delta_n", "OMG_dot", "i_dot", "cuc", "cus", "crc",
         "crs", "cic", "cis", "af0", "af1", "af2", "tgd0", "tgd1", "A_dot", "n_dot"]
ephem_def = ("uint32 sat\nGnssTimeMsg ttr\nGnssTimeMsg toe\nGnssTimeMsg toc\nfloat64 toe_tow\n"
             "uint32 week\nuint32 iode\nuint32 iodc\nuint32 health\nuint32 code\n"
             "float64 ura\n" + "".join(f"float64 {n}\n" for n in names) + time)
ephem = (struct.pack("<I", 65) + struct.pack("<Id", 2300, 345600.0) * 3 + struct.pack("<d", 345600.0)
         + struct.pack("<IIIIId", 2300, 10, 10, 0, 517, 3.12)
         + struct.pack("<d", 2.9600e7) + struct.pack("<d", 2e-4) + b"".join(
             struct.pack("<d", 0.1) for _ in names[2:]))
for name, definition, body in [("gnss_comm_meas", obs, meas), ("gnss_comm_ephem", ephem_def, ephem)]:
    open(f"{sys.argv[1]}/{name}", "wb").write(b"\x02" + definition.encode() + b"\0" + body)
PY
fi
{ printf '\x00'; cat "$sim/dataset.yaml"; } > "$out/fuzz_yaml/corpus/dataset"
{ printf '\x01'; cat "$root/config/giocal.yaml"; } > "$out/fuzz_yaml/corpus/config"
{ printf '\x02'; cat "$root/config/sim/field.yaml"; } > "$out/fuzz_yaml/corpus/preset"

printf "%-16s %12s %8s %9s %5s %6s\n" harness executions crashes timeouts oom leaks
status=0
for h in "${harnesses[@]}"; do
  ( cd "$out/$h" && "$root/build-fuzz/fuzz/$h" -max_total_time="$secs" -runs="$runs" -timeout=5 \
      -rss_limit_mb=2048 -artifact_prefix="$out/$h/" -print_final_stats=1 corpus \
      > log.txt 2>&1 ) || true
  executed=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$out/$h/log.txt" | grep -o '[0-9]*$' || echo 0)
  n() { find "$out/$h" -maxdepth 1 -name "$1-*" | wc -l; }
  printf "%-16s %12s %8s %9s %5s %6s\n" "$h" "${executed:-0}" "$(n crash)" "$(n timeout)" "$(n oom)" \
    "$(n leak)"
  [ "$(n crash)$(n timeout)$(n oom)$(n leak)" = "0000" ] || status=1
done
exit $status
