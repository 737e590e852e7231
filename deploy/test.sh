#!/usr/bin/env bash
# Installs what is needed from Debian, builds a Release tree with tests, runs every test
# through CTest. Exits non-zero on any failure. .ci/run calls exactly this.
set -euo pipefail
cd "$(dirname "$0")/.."
./deploy/install-deps.sh
./deploy/build.sh
build_dir=${OCEAN_BUILD_DIR:-build}
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" --timeout 600
