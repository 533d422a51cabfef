#!/usr/bin/env bash
# The main job: install, build, then solve every bundled example and print a table
# (name, status, branches, DOF, median solve time in µs).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
"${BUILD_DIR:-build}/cli/relpos" table data/examples
