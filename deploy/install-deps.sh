#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds, tests and demos with.
# Idempotent and quick when everything is present: apt runs only for what is missing.
set -euo pipefail

packages=(
  cmake g++ make ninja-build pkg-config git ca-certificates
  libfftw3-dev libasio-dev libwebsocketpp-dev libflatbuffers-dev flatbuffers-compiler
  libzstd-dev libsodium-dev libssl-dev libspdlog-dev libfmt-dev libcli11-dev libtomlplusplus-dev
  libstb-dev catch2
  libglfw3-dev libglm-dev libgles-dev libegl-dev libegl1-mesa-dev libgl1-mesa-dri
  xvfb xauth gnuplot-nox python3-numpy python3-yaml python3-jsonschema procps
  nlohmann-json3-dev etcd-server
)
# The browser viewer (-DOCEAN_BUILD_WEB=ON) and its test in headless Chromium over WebDriver.
# OCEAN_WEB=0 leaves them out (the server image's builder needs none of it).
if [[ "${OCEAN_WEB:-1}" != 0 ]]; then
  packages+=(emscripten chromium chromium-driver)
fi
if [[ "${OCEAN_SANITIZE:-}" == 1 || "${OCEAN_FUZZ:-}" == 1 ]]; then
  packages+=(clang libclang-rt-14-dev)
fi
# The container stage (deploy/container_test.sh): podman with runc, catatonit for kube play's
# pause image, debootstrap for the base images (no registry is reachable), curl for the probes.
if [[ "${OCEAN_CONTAINER:-}" == 1 ]]; then
  packages+=(podman runc catatonit debootstrap curl)
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [[ "$status" == installed ]] || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
if [[ $(id -u) -ne 0 ]]; then
  sudo=sudo
else
  sudo=
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
