#!/usr/bin/env bash
# The main job: installs, builds, starts ocean-server on loopback and an ocean-viewer against it
# (a window when $DISPLAY is set, otherwise headless rendering to a PNG whose path it prints).
# The server also serves the browser viewer: the URL it prints opens the same sea in a browser;
# from a terminal the demo keeps the server up until Enter, so there is time to open it.
# OCEAN_DEMO_PROFILE (mobile), OCEAN_DEMO_HOST (127.0.0.1; 0.0.0.0 lets a phone on the LAN in),
# OCEAN_DEMO_PORT (17700; the next three ports serve metrics, WebSocket and the page) and
# OCEAN_DEMO_OUT (out/) adjust it.
set -euo pipefail
cd "$(dirname "$0")/.."
./deploy/install-deps.sh
./deploy/build.sh -DOCEAN_BUILD_WEB=ON
build_dir=${OCEAN_BUILD_DIR:-build}
profile=${OCEAN_DEMO_PROFILE:-mobile}
host=${OCEAN_DEMO_HOST:-127.0.0.1}
port=${OCEAN_DEMO_PORT:-17700}
out=${OCEAN_DEMO_OUT:-out}
mkdir -p "$out"

echo "== the simulation: one tick of the default scene =="
"$build_dir"/sim/ocean-simdump --summary

echo "== ocean-server on $host:$port =="
web=()
if [[ -f "$build_dir/web/ocean-web.wasm" ]]; then
  web=(--ws-listen "$host:$((port + 2))" --web-listen "$host:$((port + 3))")
fi
# Two vessels on circuits (deploy/demo-vessels.toml): their wakes are the server's, in every viewer.
"$build_dir"/server/ocean-server --listen "$host:$port" --metrics-listen "127.0.0.1:$((port + 1))" \
  --profiles mobile,desktop,lite --config deploy/demo-vessels.toml "${web[@]}" >"$out/server.log" 2>&1 &
server_pid=$!
trap 'kill -TERM "$server_pid" 2>/dev/null || true; wait "$server_pid" 2>/dev/null || true' EXIT
if ((${#web[@]})); then
  url_host=$host
  [[ "$host" == 0.0.0.0 ]] && url_host=$(hostname -I | cut -d' ' -f1)
  echo "browser viewer: http://$url_host:$((port + 3))/"
else
  echo "browser viewer: not built (emscripten missing); see README.md \"In a browser\""
fi

local_host=$host
[[ "$host" == 0.0.0.0 ]] && local_host=127.0.0.1
viewer=("$build_dir"/client/viewer/ocean-viewer --server "$local_host:$port" --profile "$profile")
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
if ((${#web[@]})) && [[ -t 0 ]]; then
  read -r -p "the server still serves the browser viewer at http://$url_host:$((port + 3))/ - press Enter to stop it "
fi
