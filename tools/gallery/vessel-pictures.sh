#!/bin/bash
# The README's vessel pictures (issue 35), rendered headless from a real ocean-server:
#   tools/gallery/vessel-pictures.sh [BUILD] [OUT]     (defaults: build, docs)
# wake-desktop-choppy.png  a 30 m hull at 7 m/s and its wake, from 60 m up, on desktop-choppy
# wake-mobile.png          the same on mobile
# gale-stern.png           the same hull in a 20 m/s gale, from its stern camera (--follow)
# browser-follow.png       the browser viewer following a harbour ferry (needs Chromium; skipped without)
# The sea's clock is set (--epoch) so each picture catches the hull where the camera looks.
source "$(dirname "$0")/gallery.sh"  # BUILD, OUT and WORK from the arguments; gallery_server
cat > "$WORK/wake.toml" <<'TOML'
wake-size = 256
wake-origin-x = -128
wake-origin-z = -128

[[vessel]]
id = 7
length = 30
beam = 7
draft = 2.0
waypoints = [[0, -125, 0], [35.714286, 125, 0]]
TOML

# render NAME SEA_TIME_S "SERVER ARGS" "VIEWER ARGS"
render() {
  local epoch=$(( $(date +%s%3N) - $2 * 1000 ))
  gallery_server "$WORK/server.log" --config "$WORK/wake.toml" --epoch "$epoch" $3
  "$BUILD/client/viewer/ocean-viewer" --server "127.0.0.1:$PORT" --headless --size 960x540 --frames 30 \
    --first-frame-timeout 60 --screenshot "$OUT/$1" $4 > /dev/null
  kill "$SERVER"; wait "$SERVER" 2>/dev/null || true
  echo "$OUT/$1"
}
above="--eye-height 60 --pitch -30 --camera-z 100"
render wake-desktop-choppy.png 19 "--profiles desktop-choppy --wind-speed 5 --choppiness 1" "--profile desktop-choppy $above"
render wake-mobile.png 19 "--profiles mobile --wind-speed 5" "--profile mobile $above"
render gale-stern.png 19 "--profiles desktop-choppy --spectrum jonswap --wind-speed 20 --choppiness 1.2" \
  "--profile desktop-choppy --follow 7"
if command -v chromium > /dev/null && [ -x "$BUILD/tests/web/ocean-web-replay" ]; then
  /usr/bin/python3 tests/web/web_viewer_test.py --build "$BUILD" --fleet client/loadtest/fleets/harbour.toml --follow 1 \
    --size 1280x720 --screenshot "$OUT/browser-follow.png" > /dev/null && echo "$OUT/browser-follow.png"
fi
