#!/usr/bin/env bash
# The libraries, the giocal command and the tests built with AddressSanitizer and
# UndefinedBehaviorSanitizer (-O1 -g1: line tables for the reports, half the compile time of
# -O2 -g; into build-sanitize/, without bench/ and examples/), then every test labelled `fast`
# (the `slow` ones run in Release only: under the sanitizers one took 641 s); fails on any report.
# CI runs it after scripts/test.sh.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh" > /dev/null  # the packages (and the normal build)
cmake -S "$root" -B "$root/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DGIOCAL_SANITIZE=ON \
  -DGIOCAL_BENCH=OFF -DGIOCAL_EXAMPLES=OFF > /dev/null
cmake --build "$root/build-sanitize" -j "$(nproc)"
cd "$root/build-sanitize"
# Leaks are reported too; halt_on_error makes a report fail the test that caused it.
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --output-on-failure -j "$(nproc)" --timeout 1500 -L fast
