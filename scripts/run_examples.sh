#!/usr/bin/env bash
# The main job: install, build, then solve every bundled example and print a table
# (name, status, branches, DOF, median solve time in µs); the collision examples add how many
# branches have a collision-free pose; then batches over the examples and 10,000 generated specs.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
build="${BUILD_DIR:-build}"
"$build/cli/relpos" table data/examples data/scenarios
"$build/cli/relpos" table data/plugins --plugin "$build/plugins/relpos-symmetric.so" \
  --plugin "$build/plugins/relpos-helical.so"
"$build/cli/relpos" table data/collision --collision --repeat 20
# Batch: every bundled example, then 10,000 generated grasp and weld specs; results as JSONL in
# the build folder, the summary on stderr.
"$build/cli/relpos" batch data/examples -o "$build/examples-results.jsonl"
"$build/bench/relpos_generate_specs" 10000 7 > "$build/generated-specs.jsonl"
"$build/cli/relpos" batch "$build/generated-specs.jsonl" -o "$build/generated-results.jsonl"
