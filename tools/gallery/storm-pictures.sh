#!/bin/bash
# The README's storm gallery (issue 36), rendered headless from a real ocean-server:
#   tools/gallery/storm-pictures.sh [BUILD] [OUT]     (defaults: build, docs)
# storm.png      a 20 m/s gale (JONSWAP, choppiness 1.2) from a bridge, 40 m up, 25 degrees down
# gale-deck.png  the same gale from a deck, 12 m up, 10 degrees down
# gale-air.png   the same gale from 200 m, 45 degrees down
# sea-15.png     a 15 m/s sea (choppiness 1.2) from the bridge
# low-sun.png    a 5 m/s sea (choppiness 0.8) from a deck 6 m up, looking into a sun 4 degrees high
#                (a sky ocean-skygen paints for it: --sky)
# Each viewer renders 150 frames (about 6 s of sea) so the foam's remnants have built up.
source "$(dirname "$0")/gallery.sh"  # BUILD, OUT and WORK from the arguments; gallery_server

# render NAME WIND "VIEWER CAMERA ARGS" [CHOPPINESS]
render() {
  local epoch=$(( $(date +%s%3N) - 100000 ))
  gallery_server "$WORK/server.log" --epoch "$epoch" --profiles desktop-choppy --spectrum jonswap --wind-speed "$2" \
    --choppiness "${4:-1.2}"
  "$BUILD/client/viewer/ocean-viewer" --server "127.0.0.1:$PORT" --headless --size 960x540 --frames 150 \
    --first-frame-timeout 60 --profile desktop-choppy --screenshot "$OUT/$1" $3 > /dev/null
  kill "$SERVER"; wait "$SERVER" 2>/dev/null || true
  echo "$OUT/$1"
}
render storm.png 20 "--eye-height 40 --pitch -25 --yaw 180"
render gale-deck.png 20 "--eye-height 12 --pitch -10 --yaw 180"
render gale-air.png 20 "--eye-height 200 --pitch -45 --yaw 180"
render sea-15.png 15 "--eye-height 40 --pitch -25 --yaw 180"
"$BUILD/assets/ocean-skygen" --out "$WORK/low-sky" --sun-elevation-deg 4 --sun-azimuth-deg 0
render low-sun.png 5 "--eye-height 6 --pitch -4 --yaw 0 --sky $WORK/low-sky" 0.8
