#!/usr/bin/env bash
# Install, build, and run every test (GoogleTest suites under ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_deps.sh --tests
./scripts/build.sh
ctest --test-dir "${BUILD_DIR:-build}" -j"$(nproc)" --output-on-failure
