#!/usr/bin/env python3
"""A storm that looks like a storm: ocean-server streams desktop-choppy for a 20 m/s JONSWAP storm
at choppiness 1.2, and for a 10 m/s sea at choppiness 0; ocean-viewer renders each headless at
1280x720. The storm's foam must cover a clearly larger share of the water than the calm sea's:
at least ten times the calm share, and at least 0.2 % of the water.

The camera is 40 m up, looking 25 degrees down and away from the sun (whose glitter is near white
too); the lower 75 % of the picture is water. Foam is counted as near-neutral pixels (channels
within 40/255 of each other) at least 80/255 brighter than the median of their row: water
darkens smoothly with nearness, so a row's median is its water, and a calm sea's sky reflections
stay within that of it. Prints one JSON object.
Exit status: 0 pass, 1 fail, 2 bad arguments."""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from png_decode import decode_png  # noqa: E402
from server_launch import start_server  # noqa: E402

SEAS = {
    "storm": ["--spectrum", "jonswap", "--wind-speed", "20", "--choppiness", "1.2"],
    "calm": ["--spectrum", "jonswap", "--wind-speed", "10", "--choppiness", "0"],
}


def foam_share(png_path):
    width, height, channels, rows = decode_png(open(png_path, "rb").read())
    foam = total = 0
    for line in rows[int(height * 0.25):]:
        pixels = [(line[x], line[x + 1], line[x + 2]) for x in range(0, width * channels, channels)]
        median = sorted(sum(p) // 3 for p in pixels)[len(pixels) // 2]
        for r, g, b in pixels:
            foam += sum((r, g, b)) // 3 >= median + 80 and max(r, g, b) - min(r, g, b) <= 40
            total += 1
    return foam / total


# The sea's time when the server starts: the picture is taken a few seconds later. Foam comes and
# goes with the wave groups, so at whatever time the clock happened to give, a storm's share
# ranged 0.13-1.9 % in 13 runs; every run now sees the same seconds of the same sea.
SEA_TIME_AT_START_S = 100


def render(build, sea, out_dir, size, frames):
    log_path = os.path.join(out_dir, f"{sea}-server.log")
    epoch_ms = int(time.time() * 1000) - SEA_TIME_AT_START_S * 1000
    server, port = start_server(build, ["--profiles", "desktop-choppy", "--size", "256", "--epoch", str(epoch_ms)]
                                + SEAS[sea], log_path)
    png = os.path.join(out_dir, f"{sea}.png")
    try:
        viewer = subprocess.run([os.path.join(build, "client", "viewer", "ocean-viewer"), "--server", f"127.0.0.1:{port}",
                                 "--headless", "--profile", "desktop-choppy", "--size", size, "--frames", str(frames),
                                 "--yaw", "180", "--eye-height", "40", "--pitch", "-25", "--screenshot", png, "--json", "--first-frame-timeout", "60"],
                                capture_output=True, text=True, timeout=240)
    finally:
        server.terminate()
        server.wait(timeout=30)
    if viewer.returncode != 0:
        sys.exit(f"FAIL: ocean-viewer exited {viewer.returncode} for the {sea} sea:\n{viewer.stderr[-2000:]}\n"
                 f"server log:\n{open(log_path).read()[-2000:]}")
    report = json.loads(viewer.stdout.strip().splitlines()[-1])
    return png, report


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", required=True, help="the CMake build folder")
    parser.add_argument("--out", help="folder for the screenshots and logs (default: a temporary one)")
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--frames", type=int, default=45)
    args = parser.parse_args()
    out_dir = args.out or tempfile.mkdtemp(prefix="ocean-storm-")
    os.makedirs(out_dir, exist_ok=True)
    result = {"size": args.size}
    for sea in ("storm", "calm"):
        png, report = render(args.build, sea, out_dir, args.size, args.frames)
        result[sea] = {"screenshot": png, "foam_share": round(foam_share(png), 5), "frames": report["frames"],
                       "fps": report["fps"], "kbps": report["kbps"]}
    storm, calm = result["storm"]["foam_share"], result["calm"]["foam_share"]
    result["pass"] = storm >= 10 * calm and storm >= 0.002
    print(json.dumps(result))
    return 0 if result["pass"] else 1


if __name__ == "__main__":
    sys.exit(main())
