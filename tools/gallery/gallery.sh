# Sourced by the gallery scripts (SCRIPT [BUILD] [OUT], defaults build and docs): sets BUILD, OUT
# and a WORK folder removed at exit with the servers left running; gallery_server LOG ARGS...
# starts ocean-server from $BUILD on a port the kernel picks (its log names it) and sets SERVER
# (its pid) and PORT.
set -euo pipefail
BUILD=${1:-build}
OUT=${2:-docs}
WORK=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$WORK"' EXIT
mkdir -p "$OUT"

gallery_server() {
  local log=$1
  shift
  "$BUILD/server/ocean-server" --listen 127.0.0.1:0 --metrics-listen off "$@" > "$log" 2>&1 &
  SERVER=$!
  PORT=""
  for _ in $(seq 100); do
    PORT=$(grep -o 'listening tcp=[^ ]*' "$log" | grep -o '[0-9]*$' || true)
    [ -n "$PORT" ] && return 0
    sleep 0.1
  done
  echo "ocean-server did not report its port:" >&2
  cat "$log" >&2
  return 1
}
