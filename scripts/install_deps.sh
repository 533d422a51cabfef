#!/usr/bin/env bash
# Installs the Debian packages relpos builds with. Does nothing when they are all present, so the
# README commands can call it every time. --tests: also what the tests need beyond the build
# (Chromium, which the viewer's test drives).
set -euo pipefail
pkgs=(cmake g++ make ccache libeigen3-dev nlohmann-json3-dev libgtest-dev libgmock-dev
      libbenchmark-dev libboost-dev libfcl-dev libcgal-dev python3
      libslvs1-dev libnlopt-dev libsimdjson-dev libfmt-dev pybind11-dev python3-dev python3-numpy)
# The viewer's script is bundled with npm at build time (viewer/CMakeLists.txt); a machine with
# Node.js from elsewhere keeps its own.
if ! command -v npm >/dev/null; then pkgs+=(nodejs npm); fi
if [ "${1:-}" = "--tests" ]; then pkgs+=(chromium); fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
echo "installing: ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
