#!/usr/bin/env bash
# The main job: installs, builds, then runs the most complete thing the project has.
set -euo pipefail
cd "$(dirname "$0")/.."
./deploy/install-deps.sh
./deploy/build.sh
build_dir=${OCEAN_BUILD_DIR:-build}

echo "== ocean: one tick of the default scene =="
"$build_dir"/server/sim/ocean-simdump --summary
echo "== ocean-bench sim =="
"$build_dir"/tests/bench/ocean-bench sim --size 256 --json
