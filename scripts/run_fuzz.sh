#!/usr/bin/env bash
# Builds the libFuzzer target (tests/fuzz/spec_fuzzer.cpp: spec reader, solver and result writer
# under ASan and UBSan) with clang in a build directory of its own, makes its seed corpus from
# data/, and fuzzes for a bounded time. Exit non-zero on any crash, leak, timeout (an input
# slower than a second) or broken invariant; the input that did it is kept and its path printed.
# Usage: scripts/run_fuzz.sh [SECONDS] (default 60). Environment: BUILD_DIR (build-fuzz), WERROR,
# UNITY (ON/OFF, default OFF: as scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
"$(dirname "$0")/install_deps.sh"
# clang and libFuzzer, as install_deps.sh installs the rest.
missing=()
for p in clang-14 libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi

BUILD_DIR=${BUILD_DIR:-build-fuzz}
CC=clang-14 CXX=clang++-14 cmake -S . -B "$BUILD_DIR" -DRELPOS_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRELPOS_WERROR="${WERROR:-OFF}" \
  -DCMAKE_UNITY_BUILD="${UNITY:-OFF}" >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)" --target relpos_spec_fuzzer
cmake --build "$BUILD_DIR" --target relpos_fuzz_corpus

# New inputs found go to fuzz-corpus (kept between runs); fuzz-seeds is remade from data/.
corpus="$BUILD_DIR/fuzz-corpus" artifacts="$BUILD_DIR/fuzz-artifacts"
mkdir -p "$corpus" "$artifacts"
log="$BUILD_DIR/fuzz.log"
echo "fuzzing for ${seconds} s (log: $log)"
status=0
ASAN_OPTIONS=detect_leaks=1 \
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "$BUILD_DIR/tests/fuzz/relpos_spec_fuzzer" -max_total_time="$seconds" -timeout=1 \
  -rss_limit_mb=2048 -max_len=16384 -dict=tests/fuzz/spec.dict -print_final_stats=1 \
  -artifact_prefix="$artifacts/" "$corpus" "$BUILD_DIR/fuzz-seeds" >"$log" 2>&1 || status=$?
if [ "$status" -ne 0 ]; then
  tail -n 80 "$log"
  echo "run_fuzz.sh: the fuzzer failed (exit $status); the input:" >&2
  grep -E "Test unit written to|artifact_prefix" "$log" >&2 || true
  exit 1
fi
grep -E "^stat::(number_of_executed_units|peak_rss_mb)|^Done" "$log" || true
echo "run_fuzz.sh: no failure in ${seconds} s"
