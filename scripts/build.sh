#!/usr/bin/env bash
# Configures and builds relpos. Environment: BUILD_DIR (default build), BUILD_TYPE (Release),
# SANITIZE (e.g. address,undefined), WERROR (ON/OFF).
set -euo pipefail
cd "$(dirname "$0")/.."
"$(dirname "$0")/install_deps.sh"
BUILD_DIR=${BUILD_DIR:-build}
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" \
  -DRELPOS_SANITIZE="${SANITIZE:-}" -DRELPOS_WERROR="${WERROR:-OFF}" >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
