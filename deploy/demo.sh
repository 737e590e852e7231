#!/usr/bin/env bash
# The main job: installs, builds, starts ocean-server on loopback and an ocean-viewer against it
# (a window when $DISPLAY is set, otherwise headless rendering to a PNG whose path it prints).
# OCEAN_DEMO_PROFILE (mobile), OCEAN_DEMO_PORT (17700) and OCEAN_DEMO_OUT (out/) adjust it.
set -euo pipefail
cd "$(dirname "$0")/.."
./deploy/install-deps.sh
./deploy/build.sh
build_dir=${OCEAN_BUILD_DIR:-build}
profile=${OCEAN_DEMO_PROFILE:-mobile}
port=${OCEAN_DEMO_PORT:-17700}
out=${OCEAN_DEMO_OUT:-out}
mkdir -p "$out"

echo "== the simulation: one tick of the default scene =="
"$build_dir"/sim/ocean-simdump --summary

echo "== ocean-server on 127.0.0.1:$port =="
"$build_dir"/server/ocean-server --listen "127.0.0.1:$port" --metrics-listen "127.0.0.1:$((port + 1))" \
  --profiles mobile,desktop,lite >"$out/server.log" 2>&1 &
server_pid=$!
trap 'kill -TERM "$server_pid" 2>/dev/null || true; wait "$server_pid" 2>/dev/null || true' EXIT

viewer=("$build_dir"/client/viewer/ocean-viewer --server "127.0.0.1:$port" --profile "$profile")
if [[ -n "${DISPLAY:-}" ]]; then
  echo "== ocean-viewer in a window (Q or Esc quits; H toggles the HUD) =="
  "${viewer[@]}"
else
  png="$out/ocean-$profile.png"
  echo "== ocean-viewer, headless (no \$DISPLAY) =="
  "${viewer[@]}" --headless --frames 240 --size 1280x720 --hud --screenshot "$png" \
    --record "$out/ocean-$profile.npy" --json --first-frame-timeout 30
  echo "screenshot: $(realpath "$png")"
  echo "recorded heights: $(realpath "$out/ocean-$profile.npy")"
fi
echo "server log: $(realpath "$out/server.log")"
