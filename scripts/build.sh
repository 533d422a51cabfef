#!/usr/bin/env bash
# Configures and builds relpos. Environment: BUILD_DIR (default build), BUILD_TYPE (Release),
# SANITIZE (e.g. address,undefined), WERROR (ON/OFF), OPT_FLAGS (the build type's compiler flags,
# e.g. "-O1 -g1 -DNDEBUG"; default CMake's), BENCH (ON/OFF: the Google Benchmark programs), UNITY
# (ON/OFF, default OFF: the libraries compiled as unity sources, a few files in one compiler run;
# faster from cold, as CI's sanitizer and fuzz builds are; slower to rebuild after an edit).
set -euo pipefail
cd "$(dirname "$0")/.."
"$(dirname "$0")/install_deps.sh"
BUILD_DIR=${BUILD_DIR:-build}
BUILD_TYPE=${BUILD_TYPE:-Release}
args=(-DCMAKE_BUILD_TYPE="$BUILD_TYPE" -DRELPOS_SANITIZE="${SANITIZE:-}"
      -DRELPOS_WERROR="${WERROR:-OFF}" -DRELPOS_BUILD_BENCH="${BENCH:-ON}"
      -DCMAKE_UNITY_BUILD="${UNITY:-OFF}")
if [ -n "${OPT_FLAGS:-}" ]; then args+=(-DCMAKE_CXX_FLAGS_"${BUILD_TYPE^^}"="$OPT_FLAGS"); fi
cmake -S . -B "$BUILD_DIR" "${args[@]}" >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
