#!/usr/bin/env bash
# The main job: install, build, then solve every bundled example and print a table
# (name, status, branches, DOF, median solve time in µs); the collision examples add how many
# branches have a collision-free pose.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
build="${BUILD_DIR:-build}"
"$build/cli/relpos" table data/examples data/scenarios
"$build/cli/relpos" table data/plugins --plugin "$build/plugins/relpos-symmetric.so" \
  --plugin "$build/plugins/relpos-helical.so"
"$build/cli/relpos" table data/collision --collision --repeat 20
