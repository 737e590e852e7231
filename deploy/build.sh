#!/usr/bin/env bash
# Configures and builds a Release tree in $OCEAN_BUILD_DIR (default: build/).
# Extra arguments go to CMake's configure step. Ninja builds it where installed (install-deps.sh
# installs it): it starts the next compile the moment one ends and keeps its own timings
# (.ninja_log); a tree configured earlier keeps its generator. A new tree is a unity build (16
# sources a translation unit: the heavy headers - Catch2, Asio, spdlog - parsed once per batch
# instead of once per file), which halves a cold build; pass -DCMAKE_UNITY_BUILD=OFF for a tree
# you edit file by file (CONTRIBUTING.md).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${OCEAN_BUILD_DIR:-build}
fresh=()
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  fresh=(-DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16)
  if command -v ninja >/dev/null; then
    fresh+=(-G Ninja)
  fi
fi
cmake -S . -B "$build_dir" "${fresh[@]}" -DCMAKE_BUILD_TYPE=Release -DOCEAN_BUILD_TESTS=ON "$@" >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
